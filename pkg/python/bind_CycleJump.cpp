// Binding of CycleJump.hpp: the cycles a fatigue damage rate may be advanced over at once.
#include <cmath>
#include <string>

#include "../CycleJump.hpp"
#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	const double kMaxRemaining = 1e15;  // [cycles] far beyond any run, exact as a double and as a long

	bp::tuple cycleJumpPlan(const bp::object& damage, const bp::object& peak, const bp::object& remaining,
	                        const bp::object& window, const bp::object& steady, const bp::object& maxDamage,
	                        const bp::object& margin)
	{
		const CycleJumpParameters p = CycleJumpParameters::checked(asScalar(window, "window"), asScalar(steady, "steady"),
		                                                           asScalar(maxDamage, "maxDamage"), asScalar(margin, "margin"));
		const double left = asScalar(remaining, "remaining");
		if (!(left >= 0 && left <= kMaxRemaining) || left != std::floor(left))  // a long holds it exactly
			throw ArgumentError("remaining: expected an integer in [0, 1e15], got " + formatValue(left));
		np::ndarray pk = asDoubles(peak, "peak");
		const long  n  = requireShape(pk, "peak", {-1}, "a 1-d array");
		np::ndarray D  = asDoubles(damage, "damage");
		requireShape(D, "damage", {p.window + 1, n},
		             "a (" + std::to_string(p.window + 1) + "," + std::to_string(n) + ") array: the damage of each grain "
		             "at the end of each of the window's cycles and before them");
		np::ndarray    rate = emptyDoubles({n});
		const JumpPlan plan = planJump(p, n, dptr(D), dptr(pk), static_cast<long>(left), wptr(rate));
		return bp::make_tuple(plan.cycles, jumpLimitName(plan.limit), plan.grain, plan.maxRate, rate);
	}
}  // namespace

void registerCycleJump()
{
	bp::def("cycleJumpPlan", cycleJumpPlan,
	        (bp::arg("damage"), "peak", "remaining", "window", "steady", "maxDamage", "margin"),
	        "Cycle jumping (docs/cycles.md): damage (window+1, N) [-], each grain's fatigue damage at the start and the\n"
	        "end of each of the last `window` simulated cycles, oldest first; peak (N,) [-] each grain's largest damaging\n"
	        "peak of sigma_e / f_t in them; remaining [cycles]. Returns (DN [cycles], what bounds it: 'remaining',\n"
	        "'maxDamage', 'steady' or 'failure', the bounding grain's index (-1 for remaining), the largest rate [1/cycle],\n"
	        "the rate of each grain (N,) [1/cycle]).");
}

}  // namespace binding
}  // namespace ballast
