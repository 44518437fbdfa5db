// Binding of BallastCrushEngine.hpp: the bulk crushing decision for all grains of a snapshot (eq. 1).
#include <cstdint>
#include <string>
#include <vector>

#include "../BallastCrushEngine.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::tuple crushCheck(const bp::object& stresses, const bp::object& radii, const bp::object& ft0, const bp::object& m,
	                     const bp::object& rMin, const std::string& criterion, const bp::object& fMax, const bp::object& factor)
	{
		const double ft0Value = asScalar(ft0, "ft0"), mValue = asScalar(m, "m"), rMinValue = asScalar(rMin, "rMin");
		const CrushParameters   p      = CrushParameters::checked(ft0Value, mValue, rMinValue, parseCriterion(criterion));
		const GrainStressArrays grains = asGrainStresses(stresses, radii);
		const long              n      = grains.n;
		// optional per-grain arrays: None, or one value per radius
		auto perGrain = [&](const bp::object& o, const char* name) -> std::vector<double> {
			if (o.is_none()) return {};
			np::ndarray a = asDoubles(o, name);
			requireShape(a, name, {n}, "None or an (" + std::to_string(n) + ",) array, one value per radius");
			return std::vector<double>(dptr(a), dptr(a) + n);
		};
		const std::vector<double> fm = perGrain(fMax, "fMax"), w = perGrain(factor, "factor");
		np::ndarray               stress = emptyDoubles({n}), ft = emptyDoubles({n});
		std::vector<std::uint8_t> crush(n);
		evaluateCrushing(p, n, dptr(grains.stresses), dptr(grains.radii), fMax.is_none() ? nullptr : fm.data(),
		                 factor.is_none() ? nullptr : w.data(), wptr(stress), wptr(ft), crush.data());
		finiteResult(stress, "stresses, fMax, radii", "criterion's stress");
		finiteResult(ft, "ft0, radii, m, factor", "strength factor x ft0 / r^m");
		return bp::make_tuple(stress, ft, boolArray(crush));
	}
}  // namespace

void registerBallastCrushEngine()
{
	bp::def("crushCheck", crushCheck,
	        (bp::arg("stresses"), "radii", "ft0", "m", "rMin", bp::arg("criterion") = "vonMises", bp::arg("fMax") = bp::object(),
	         bp::arg("factor") = bp::object()),
	        "Crushing decision for all grains (eq. 1): stresses (N,3,3) [Pa], radii (N,) [m]; criterion 'vonMises' (eq. 2),\n"
	        "'maxContactForce' (fMax / d^2, fMax (N,) [N] the largest normal contact force of each grain) or\n"
	        "'majorPrincipal'; factor (N,) [-] each grain's strength factor (None: 1).\n"
	        "Returns (stress (N,) [Pa], strength factor x ft0 / r^m (N,) [Pa], crush (N,) bool); r < rMin never crush.");
}

}  // namespace binding
}  // namespace ballast
