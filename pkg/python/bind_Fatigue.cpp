// Binding of Fatigue.hpp: one fatigue sample of all grains (Basquin-Miner damage on the peaks of s).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "../Fatigue.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::tuple fatigueCheck(const bp::object& ratio, const bp::object& radii, const bp::object& state, const bp::object& exponent,
	                       const bp::object& endurance, const bp::object& hysteresis, const bp::object& rMin)
	{
		const double b = asScalar(exponent, "exponent"), e = asScalar(endurance, "endurance"),
		             h = asScalar(hysteresis, "hysteresis"), rMinValue = asScalar(rMin, "rMin");
		const FatigueParameters p = FatigueParameters::checked(b, e, h, rMinValue);
		np::ndarray             s = asDoubles(ratio, "ratio");
		const long              n = requireShape(s, "ratio", {-1}, "a 1-d array");
		np::ndarray             r = asDoubles(radii, "radii");
		requireShape(r, "radii", {n}, "an (" + std::to_string(n) + ",) array, one radius per ratio");
		np::ndarray before = asDoubles(state, "state");
		requireShape(before, "state", {n, 4}, "an (" + std::to_string(n) + ",4) array (damage, extreme, rising, peaks) per ratio");
		np::ndarray after = emptyDoubles({n, 4});  // the input state is not changed in place
		std::copy(dptr(before), dptr(before) + 4 * n, wptr(after));
		std::vector<std::uint8_t> crush(n);
		evaluateFatigue(p, n, dptr(s), dptr(r), reinterpret_cast<GrainFatigue*>(wptr(after)), crush.data());
		finiteResult(after, "ratio, state, exponent", "fatigue damage");
		return bp::make_tuple(after, boolArray(crush));
	}
}  // namespace

void registerFatigue()
{
	bp::def("fatigueCheck", fatigueCheck, (bp::arg("ratio"), "radii", "state", "exponent", "endurance", "hysteresis", "rMin"),
	        "Fatigue (docs/fatigue.md): one sample of the stress ratio sigma_e / f_t (N,) [-] of grains of radii (N,) [m],\n"
	        "their state (N,4) (damage D, running extreme, rising 0/1, damaging peaks; a new grain is 0, 0, 1, 0);\n"
	        "a peak >= endurance [-] ends when the ratio falls hysteresis [-] below it and adds peak^exponent to D.\n"
	        "Returns (the new state (N,4), crush (N,) bool: r >= rMin and ratio > 1 - D).");
}

}  // namespace binding
}  // namespace ballast
