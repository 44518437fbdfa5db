#include "Fatigue.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

FatigueParameters FatigueParameters::checked(double exponent, double endurance, double hysteresis, double rMin)
{
	// braces: checked in the order written
	return FatigueParameters{requireInRange(ranges::fatigueExponent, "exponent", exponent),
	                         requireInRange(ranges::fatigueEndurance, "endurance", endurance),
	                         requireInRange(ranges::fatigueHysteresis, "hysteresis", hysteresis),
	                         requireInRange(ranges::rMin, "rMin", rMin)};
}

void sampleFatigue(const FatigueParameters& p, double s, GrainFatigue& g)
{
	if (g.rising != 0) {
		if (s > g.extreme) {
			g.extreme = s;
		} else if (s < g.extreme - p.hysteresis) {  // the peak is over: Basquin-Miner
			if (g.extreme >= p.endurance) {
				g.damage += std::max(0.0, 1.0 - g.extreme) * std::pow(g.extreme, p.exponent);
				g.peaks += 1;
			}
			g.rising  = 0;
			g.extreme = s;
		}
	} else {
		if (s < g.extreme) {
			g.extreme = s;
		} else if (s > g.extreme + p.hysteresis) {  // the valley is over
			g.rising  = 1;
			g.extreme = s;
		}
	}
}

void evaluateFatigue(const FatigueParameters& p, long n, const double* ratio, const double* radii, GrainFatigue* state,
                     unsigned char* crush)
{
	for (long g = 0; g < n; ++g) {
		requireNonNegative("ratio", g, ratio[g]);
		requirePositive("radii", g, radii[g]);
		const GrainFatigue& s = state[g];
		if (!std::isfinite(s.damage) || s.damage < 0 || (s.rising != 0 && s.rising != 1) || !(s.peaks >= 0))
			throw ArgumentError("state[" + std::to_string(g) + "]: expected damage >= 0, rising 0 or 1 and peaks >= 0, got ("
			                    + formatValue(s.damage) + ", " + formatValue(s.extreme) + ", " + formatValue(s.rising) + ", "
			                    + formatValue(s.peaks) + ")");
	}
	for (long g = 0; g < n; ++g) {
		crush[g] = 0;
		if (radii[g] < p.rMin) continue;  // never degrades: no damage either (it would grow without bound)
		sampleFatigue(p, ratio[g], state[g]);
		crush[g] = crushesWithDamage(ratio[g], state[g].damage);
	}
}

}  // namespace ballast
