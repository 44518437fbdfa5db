#include "CycleJump.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

CycleJumpParameters CycleJumpParameters::checked(double window, double steady, double maxDamage, double margin,
                                                 double growth, double endurance, double driftNoise, double exponent,
                                                 double driftDamage)
{
	// braces: checked in the order written
	return CycleJumpParameters{static_cast<long>(requireInRange(ranges::jumpWindow, "window", window)),
	                           requireInRange(ranges::jumpSteady, "steady", steady),
	                           requireInRange(ranges::jumpMaxDamage, "maxDamage", maxDamage),
	                           static_cast<long>(requireInRange(ranges::jumpMargin, "margin", margin)),
	                           requireInRange(ranges::jumpGrowth, "growth", growth),
	                           requireInRange(ranges::fatigueEndurance, "endurance", endurance),
	                           requireInRange(ranges::jumpDriftNoise, "driftNoise", driftNoise),
	                           requireInRange(ranges::fatigueExponent, "exponent", exponent),
	                           requireInRange(ranges::jumpDriftDamage, "driftDamage", driftDamage)};
}

const char* jumpLimitName(JumpLimit limit)
{
	switch (limit) {
		case JumpLimit::remaining: return "remaining";
		case JumpLimit::growth: return "growth";
		case JumpLimit::maxDamage: return "maxDamage";
		case JumpLimit::steady: return "steady";
		case JumpLimit::endurance: return "endurance";
		case JumpLimit::failure: return "failure";
	}
	return "?";
}

double driftDamageBound(const CycleJumpParameters& p, double sMax, double d, double cycles)
{
	const double b = p.exponent, top = b / (b + 1);
	// an antiderivative of (1 - s) s^b, continued past its top by the top's value: the law made nondecreasing
	auto law   = [b](double s) { return (1 - s) * std::pow(s, b); };
	auto integ = [&](double s) {
		const double u = std::min(s, top);
		return std::pow(u, b + 1) / (b + 1) - std::pow(u, b + 2) / (b + 2) + (s > top ? law(top) * (s - top) : 0.0);
	};
	const double last = sMax + cycles * d;
	if (last < p.endurance) return 0.0;
	// for a nondecreasing g, g(s_k) <= (1/d) times its integral over [s_k, s_k + d]
	return (integ(last + d) - integ(std::max(p.endurance, sMax + d))) / d;
}

JumpPlan planJump(const CycleJumpParameters& p, long n, const double* damage, const double* peaks, long cycle,
                  long remaining, double* rate)
{
	if (n < 0) throw ArgumentError("n: expected >= 0 grains, got " + std::to_string(n));
	if (cycle < 1) throw ArgumentError("cycle: expected >= 1, got " + std::to_string(cycle));
	if (remaining < 0) throw ArgumentError("remaining: expected >= 0 cycles, got " + std::to_string(remaining));
	const long W = p.window, h = W / 2;
	for (long g = 0; g < n; ++g) {
		for (long k = 0; k < W; ++k) requireNonNegative("peaks", k * n + g, peaks[k * n + g]);
		for (long k = 0; k <= W; ++k) {
			requireNonNegative("damage", k * n + g, damage[k * n + g]);
			if (k > 0 && damage[k * n + g] < damage[(k - 1) * n + g])
				throw ArgumentError("damage: grain " + std::to_string(g) + "'s damage falls from "
				                    + formatValue(damage[(k - 1) * n + g]) + " to " + formatValue(damage[k * n + g])
				                    + " in the window (a grain's damage never falls: restart the window)");
		}
	}
	JumpPlan plan;
	double   best = static_cast<double>(remaining);  // bounds compared as doubles: a tiny rate gives a huge bound
	double   sMax = 0, drift = 0;                    // of the grain being bounded
	auto     bound = [&](double cycles, JumpLimit limit, long g) {
                if (cycles < best) {
                        best       = std::max(cycles, 0.0);
                        plan.limit = limit;
                        plan.grain = g;
                        plan.peak  = g < 0 ? 0.0 : sMax;
                        plan.drift = g < 0 ? 0.0 : drift;
                }
	};
	bound(std::floor(p.growth * static_cast<double>(cycle)), JumpLimit::growth, -1);
	for (long g = 0; g < n; ++g) {
		const double D0 = damage[g], Dh = damage[h * n + g], DW = damage[W * n + g];
		const double r = (DW - D0) / W, a = (Dh - D0) / h, b = (DW - Dh) / (W - h);
		double       first = 0, second = 0;
		sMax = 0;
		for (long k = 0; k < W; ++k) {
			sMax = std::max(sMax, peaks[k * n + g]);
			(k < h ? first : second) += peaks[k * n + g];
		}
		first /= h;
		second /= (W - h);
		// the scatter about the halves' means, pooled (W - 2 degrees of freedom; none in a window of 2)
		double squares = 0;
		for (long k = 0; k < W; ++k) {
			const double e = peaks[k * n + g] - (k < h ? first : second);
			squares += e * e;
		}
		const double spread = W > 2 ? std::sqrt(squares / (W - 2) * (1.0 / h + 1.0 / (W - h))) : 0.0;
		// the halves' centres lie W / 2 cycles apart
		drift              = (second - first - p.driftNoise * spread) / (0.5 * W);
		rate[g]            = r;
		plan.maxRate       = std::max(plan.maxRate, r);
		if (sMax < p.endurance && drift > 0) {
			// no damage before the peaks reach e; beyond, the largest DN whose bound is within driftDamage
			double lo = std::floor((p.endurance - sMax) / drift), hi = best;
			if (lo < hi && driftDamageBound(p, sMax, drift, hi) > p.driftDamage) {
				if (driftDamageBound(p, sMax, drift, lo) > p.driftDamage) lo -= 1;  // its last peak is e exactly
				while (hi - lo > 1) {
					const double mid = std::floor(0.5 * (lo + hi));
					(driftDamageBound(p, sMax, drift, mid) <= p.driftDamage ? lo : hi) = mid;
				}
				bound(lo, JumpLimit::endurance, g);
			}
			bound(std::floor((1.0 - DW - sMax) / drift) - p.margin, JumpLimit::failure, g);
		}
		if (r <= 0) continue;  // no damage in the window: nothing to extrapolate for this grain
		if (sMax <= 0)
			throw ArgumentError("peaks: grain " + std::to_string(g) + "'s damage grew in the window, but its peaks are 0");
		bound(std::floor(p.maxDamage / r), JumpLimit::maxDamage, g);
		if (a != b) bound(std::floor(p.steady * p.maxDamage / std::fabs(b - a)), JumpLimit::steady, g);
		// fails in the first cycle after m more peaks with DW + m r > 1 - s_p (Fatigue.hpp's crush rule)
		bound(std::floor((1.0 - sMax - DW) / r) - p.margin, JumpLimit::failure, g);
	}
	plan.cycles = static_cast<long>(best);
	return plan;
}

}  // namespace ballast
