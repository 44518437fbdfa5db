// Binding of ClumpStress.hpp: the Love-Weber stress of clumps from their members' stresses.
#include <string>

#include "../ClumpStress.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	np::ndarray clumpStresses(const bp::object& memberStresses, const bp::object& memberVolumes,
	                          const bp::object& memberForces, const bp::object& memberPositions,
	                          const bp::object& clumpIndex, const bp::object& clumpCentres, const bp::object& clumpVolumes)
	{
		np::ndarray s  = asDoubles(memberStresses, "memberStresses");
		const long  m  = requireShape(s, "memberStresses", {-1, 3, 3}, "an (m,3,3) array");
		const std::string rows = "an (" + std::to_string(m) + ",3) array, one row per member";
		np::ndarray v  = asDoubles(memberVolumes, "memberVolumes");
		requireShape(v, "memberVolumes", {m}, "a 1-d array of " + std::to_string(m) + ", one per member");
		np::ndarray f  = asDoubles(memberForces, "memberForces");
		requireShape(f, "memberForces", {m, 3}, rows);
		np::ndarray x  = asDoubles(memberPositions, "memberPositions");
		requireShape(x, "memberPositions", {m, 3}, rows);
		np::ndarray ci = asIndices(clumpIndex, "clumpIndex");
		requireShape(ci, "clumpIndex", {m}, "a 1-d array of " + std::to_string(m) + ", one per member");
		np::ndarray X  = asDoubles(clumpCentres, "clumpCentres");
		const long  k  = requireShape(X, "clumpCentres", {-1, 3}, "an (k,3) array");
		np::ndarray V  = asDoubles(clumpVolumes, "clumpVolumes");
		requireShape(V, "clumpVolumes", {k}, "a 1-d array of " + std::to_string(k) + ", one per clump");
		np::ndarray out = emptyDoubles({k, 3, 3});
		clumpStress(m, dptr(s), dptr(v), dptr(f), dptr(x), lptr(ci), k, dptr(X), dptr(V), wptr(out));
		return finiteResult(out, "memberStresses, memberForces, memberPositions, clumpCentres", "clump stress");
	}
}  // namespace

void registerClumpStress()
{
	bp::def("clumpStresses", clumpStresses,
	        (bp::arg("memberStresses"), "memberVolumes", "memberForces", "memberPositions", "clumpIndex", "clumpCentres",
	         "clumpVolumes"),
	        "Love-Weber stress of clumps [Pa], (k,3,3): sigma_k = (1/V_k) sum_{m of k} [sigma_m V_m + F_m (x) (x_m - X_k)].\n"
	        "memberStresses (m,3,3) [Pa] as utils.bodyStressTensors gives them (f_i l_j); memberVolumes (m,) [m^3] > 0 as\n"
	        "YADE divided by (4/3 pi r^3); memberForces (m,3) [N] the sum of contact forces on each member; memberPositions\n"
	        "(m,3) [m]; clumpIndex (m,) the row of each member's clump; clumpCentres (k,3) [m] centres of mass;\n"
	        "clumpVolumes (k,) [m^3] > 0.");
}

}  // namespace binding
}  // namespace ballast
