// Binding of CycleJump.hpp: the cycles a fatigue damage rate may be advanced over at once.
#include <cmath>
#include <string>

#include "../CycleJump.hpp"
#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	const double kMaxCycles = 1e15;  // [cycles] far beyond any run, exact as a double and as a long

	long asCycles(const bp::object& obj, const std::string& name, double lowest)
	{
		const double v = asScalar(obj, name);
		if (!(v >= lowest && v <= kMaxCycles) || v != std::floor(v))  // a long holds it exactly
			throw ArgumentError(name + ": expected an integer in [" + formatValue(lowest) + ", 1e15], got " + formatValue(v));
		return static_cast<long>(v);
	}

	bp::tuple cycleJumpPlan(const bp::object& damage, const bp::object& peaks, const bp::object& cycle,
	                        const bp::object& remaining, const bp::object& window, const bp::object& steady,
	                        const bp::object& maxDamage, const bp::object& margin, const bp::object& growth,
	                        const bp::object& endurance, const bp::object& driftNoise, const bp::object& exponent,
	                        const bp::object& driftDamage)
	{
		const CycleJumpParameters p = CycleJumpParameters::checked(
		        asScalar(window, "window"), asScalar(steady, "steady"), asScalar(maxDamage, "maxDamage"),
		        asScalar(margin, "margin"), asScalar(growth, "growth"), asScalar(endurance, "endurance"),
		        asScalar(driftNoise, "driftNoise"), asScalar(exponent, "exponent"), asScalar(driftDamage, "driftDamage"));
		const long  N = asCycles(cycle, "cycle", 1), left = asCycles(remaining, "remaining", 0);
		np::ndarray D = asDoubles(damage, "damage");
		requireShape(D, "damage", {p.window + 1, -1},
		                                "a (" + std::to_string(p.window + 1) + ",N) array: the damage of each grain at the "
		                                "start of the window and at the end of each of its cycles");
		const long n = static_cast<long>(D.shape(1));
		np::ndarray s = asDoubles(peaks, "peaks");
		requireShape(s, "peaks", {p.window, n},
		             "a (" + std::to_string(p.window) + "," + std::to_string(n) + ") array: each grain's largest stress "
		             "ratio in each of the window's cycles");
		np::ndarray    rate = emptyDoubles({n});
		const JumpPlan plan = planJump(p, n, dptr(D), dptr(s), N, left, wptr(rate));
		return bp::make_tuple(plan.cycles, jumpLimitName(plan.limit), plan.grain, plan.maxRate, rate, plan.peak,
		                      plan.drift);
	}
}  // namespace

void registerCycleJump()
{
	bp::def("cycleJumpPlan", cycleJumpPlan,
	        (bp::arg("damage"), "peaks", "cycle", "remaining", "window", "steady", "maxDamage", "margin", "growth",
	         "endurance", "driftNoise", "exponent", "driftDamage"),
	        "Cycle jumping (docs/cycles.md): damage (window+1, N) [-], each grain's fatigue damage at the start of the last\n"
	        "`window` simulated cycles and at the end of each; peaks (window, N) [-], each grain's largest sigma_e / f_t in\n"
	        "each of them; cycle [cycles], the count at the window's end; remaining [cycles]; window .. endurance, driftNoise,\n"
	        "exponent, driftDamage: the jump parameters (docs/cycles.md; driftNoise [standard errors]; exponent: the fatigue\n"
	        "law's b). Returns (DN [cycles], what\n"
	        "bounds it: 'remaining', 'growth', 'maxDamage', 'steady', 'endurance' or 'failure', the bounding grain's index\n"
	        "(-1 for remaining and growth), the largest rate [1/cycle], the rate of each grain (N,) [1/cycle], the bounding\n"
	        "grain's largest ratio in the window [-] and the drift of its peaks [1/cycle] (0, 0 for remaining and growth)).");
}

}  // namespace binding
}  // namespace ballast
