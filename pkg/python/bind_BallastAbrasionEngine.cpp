// Binding of BallastAbrasionEngine.hpp: the abrasion decision for all grains (eqs. 6-7) and the bounds on p0
// the prefilter reads fewer contacts with.
#include <cstdint>
#include <string>
#include <vector>

#include "../BallastAbrasionEngine.hpp"
#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::tuple abrasionCheck(const bp::object& radii, const bp::object& grain1, const bp::object& grain2, const bp::object& Fn,
	                        const bp::object& R1, const bp::object& R2, const bp::object& uN, const bp::object& strength,
	                        const bp::object& rMin)
	{
		const double             strengthValue = asScalar(strength, "strength"), rMinValue = asScalar(rMin, "rMin");
		const AbrasionParameters p             = AbrasionParameters::checked(strengthValue, rMinValue);
		np::ndarray              r             = asDoubles(radii, "radii");
		const long               n             = requireShape(r, "radii", {-1}, "a 1-d array");
		np::ndarray              g1            = asIndices(grain1, "grain1");
		const long               m             = requireShape(g1, "grain1", {-1}, "a 1-d array");
		std::vector<np::ndarray> c;  // grain2, Fn, R1, R2, uN: one per contact, like grain1
		const char*              names[] = {"grain2", "Fn", "R1", "R2", "uN"};
		const bp::object*        objs[]  = {&grain2, &Fn, &R1, &R2, &uN};
		for (int i = 0; i < 5; ++i) {
			c.push_back(i == 0 ? asIndices(*objs[i], names[i]) : asDoubles(*objs[i], names[i]));
			requireShape(c.back(), names[i], {m}, "a 1-d array of length " + std::to_string(m) + ", like grain1");
		}
		np::ndarray               p0 = emptyDoubles({n});
		std::vector<std::uint8_t> abrade(n);
		evaluateAbrasion(p, n, dptr(r), m, lptr(g1), lptr(c[0]), dptr(c[1]), dptr(c[2]), dptr(c[3]), dptr(c[4]), wptr(p0),
		                 abrade.data());
		finiteResult(p0, "Fn, R1, R2, uN", "Hertz pressure");
		return bp::make_tuple(p0, boolArray(abrade));
	}

	np::ndarray abrasionBound(const bp::object& stresses, const bp::object& radii, const bp::object& rPartner,
	                          const bp::object& EstarMax)
	{
		const GrainStressArrays grains = asGrainStresses(stresses, radii);
		const long              n      = grains.n;
		const double*           s      = dptr(grains.stresses);
		std::vector<double>     traces(n);
		for (long g = 0; g < n; ++g) {
			traces[g] = s[9 * g] + s[9 * g + 4] + s[9 * g + 8];
			requireFiniteResult("stresses", "trace", g, traces[g]);
		}
		np::ndarray bound = emptyDoubles({n});
		abrasionPressureBound(n, traces.data(), dptr(grains.radii), asScalar(rPartner, "rPartner"), asScalar(EstarMax, "EstarMax"),
		                      wptr(bound));
		return finiteResult(bound, "stresses, radii, rPartner, EstarMax", "abrasion pressure bound");
	}

	double sphereContactBoundOf(const bp::object& maxOverlapRatio, const bp::object& EstarMax)
	{
		const double b = sphereContactBound(asScalar(maxOverlapRatio, "maxOverlapRatio"), asScalar(EstarMax, "EstarMax"));
		requireFiniteResult("maxOverlapRatio, EstarMax", "pressure bound", b);
		return b;
	}
}  // namespace

void registerBallastAbrasionEngine()
{
	bp::def("abrasionCheck", abrasionCheck, (bp::arg("radii"), "grain1", "grain2", "Fn", "R1", "R2", "uN", "strength", "rMin"),
	        "Abrasion decision for all grains (eq. 6 with eq. 7): radii (N,) [m]; per contact (M,): grain1, grain2 the grain\n"
	        "index of each side or -1, Fn [N], R1, R2 [m] (0 = wall), uN [m]; strength [Pa]; rMin [m].\n"
	        "Returns (p0max (N,) [Pa], abrade (N,) bool).");
	bp::def("abrasionBound", abrasionBound, (bp::arg("stresses"), "radii", "rPartner", "EstarMax"),
	        "Upper bound of p0 (eq. 7) over the Hertzian contacts of each grain with bodies of radius >= rPartner [m]\n"
	        "(0: walls and facets), from its fabric stress alone: stresses (N,3,3) [Pa] (eq. 3), radii (N,) [m],\n"
	        "EstarMax the largest contact modulus [Pa]. Returns (N,) [Pa].");
	bp::def("sphereContactBound", sphereContactBoundOf, (bp::arg("maxOverlapRatio"), "EstarMax"),
	        "Upper bound of p0 (eq. 7) over all Hertzian sphere-sphere contacts, (2 E*/pi) sqrt(2 rho) [Pa], from\n"
	        "rho = max u_N / (2 R) (utils.maxOverlapRatio()) and the largest contact modulus EstarMax [Pa].");
}

}  // namespace binding
}  // namespace ballast
