#include "CycleJump.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

CycleJumpParameters CycleJumpParameters::checked(double window, double steady, double maxDamage, double margin)
{
	// braces: checked in the order written
	return CycleJumpParameters{static_cast<long>(requireInRange(ranges::jumpWindow, "window", window)),
	                           requireInRange(ranges::jumpSteady, "steady", steady),
	                           requireInRange(ranges::jumpMaxDamage, "maxDamage", maxDamage),
	                           static_cast<long>(requireInRange(ranges::jumpMargin, "margin", margin))};
}

const char* jumpLimitName(JumpLimit limit)
{
	switch (limit) {
		case JumpLimit::remaining: return "remaining";
		case JumpLimit::maxDamage: return "maxDamage";
		case JumpLimit::steady: return "steady";
		case JumpLimit::failure: return "failure";
	}
	return "?";
}

JumpPlan planJump(const CycleJumpParameters& p, long n, const double* damage, const double* peak, long remaining,
                  double* rate)
{
	if (n < 0) throw ArgumentError("n: expected >= 0 grains, got " + std::to_string(n));
	if (remaining < 0) throw ArgumentError("remaining: expected >= 0 cycles, got " + std::to_string(remaining));
	const long W = p.window, h = W / 2;
	for (long g = 0; g < n; ++g) {
		requireNonNegative("peak", g, peak[g]);
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
	auto     bound = [&](double cycles, JumpLimit limit, long g) {
                if (cycles < best) {
                        best       = std::max(cycles, 0.0);
                        plan.limit = limit;
                        plan.grain = g;
                }
	};
	for (long g = 0; g < n; ++g) {
		const double D0 = damage[g], Dh = damage[h * n + g], DW = damage[W * n + g];
		const double r = (DW - D0) / W, a = (Dh - D0) / h, b = (DW - Dh) / (W - h);
		rate[g]        = r;
		plan.maxRate   = std::max(plan.maxRate, r);
		if (r <= 0) continue;  // no damage in the window: nothing to extrapolate for this grain
		if (peak[g] <= 0)
			throw ArgumentError("peak[" + std::to_string(g) + "]: a grain whose damage grew has a damaging peak > 0, got "
			                    + formatValue(peak[g]));
		bound(std::floor(p.maxDamage / r), JumpLimit::maxDamage, g);
		if (a != b) bound(std::floor(p.steady * p.maxDamage / std::fabs(b - a)), JumpLimit::steady, g);
		// fails in the first cycle after m more peaks with DW + m r > 1 - s_p (Fatigue.hpp's crush rule)
		bound(std::floor((1.0 - peak[g] - DW) / r) - p.margin, JumpLimit::failure, g);
	}
	plan.cycles = static_cast<long>(best);
	return plan;
}

}  // namespace ballast
