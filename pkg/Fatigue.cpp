#include "Fatigue.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

void FatigueParameters::validate() const
{
	requirePositive("exponent", exponent);
	requireNonNegative("endurance", endurance);
	if (!(endurance < 1.0)) throw ArgumentError("endurance: expected a ratio in [0, 1), got " + formatValue(endurance));
	requirePositive("hysteresis", hysteresis);
	if (!(hysteresis < 1.0)) throw ArgumentError("hysteresis: expected a ratio in (0, 1), got " + formatValue(hysteresis));
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

void evaluateFatigue(const FatigueParameters& p, double rMin, long n, const double* ratio, const double* radii,
                     GrainFatigue* state, unsigned char* crush)
{
	p.validate();
	requireNonNegative("rMin", rMin);
	for (long g = 0; g < n; ++g) {
		requireFinite("ratio", g, ratio[g]);
		if (ratio[g] < 0) requireNonNegative("ratio[" + std::to_string(g) + "]", ratio[g]);
		requirePositive("radii", g, radii[g]);
		const GrainFatigue& s = state[g];
		if (!std::isfinite(s.damage) || s.damage < 0 || (s.rising != 0 && s.rising != 1) || !(s.peaks >= 0))
			throw ArgumentError("state[" + std::to_string(g) + "]: expected damage >= 0, rising 0 or 1 and peaks >= 0, got ("
			                    + formatValue(s.damage) + ", " + formatValue(s.extreme) + ", " + formatValue(s.rising) + ", "
			                    + formatValue(s.peaks) + ")");
	}
	for (long g = 0; g < n; ++g) {
		crush[g] = 0;
		if (radii[g] < rMin) continue;  // never degrades: no damage either (it would grow without bound)
		sampleFatigue(p, ratio[g], state[g]);
		crush[g] = crushesWithDamage(ratio[g], state[g].damage);
	}
}

}  // namespace ballast
