// Binding of FabricStress.hpp: the fabric (Love-Weber) stress of eq. 3, of one grain and of many.
#include <string>
#include <vector>

#include "../FabricStress.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	np::ndarray fabricStressOfOne(const bp::object& radius, const bp::object& branches, const bp::object& forces)
	{
		const double r = asScalar(radius, "radius");
		sphereVolume(r);  // r > 0 and a volume that neither under- nor overflows; errors name radius, not radii[0]
		np::ndarray l  = asDoubles(branches, "branches");
		np::ndarray f  = asDoubles(forces, "forces");
		const long  nl = requireShape(l, "branches", {-1, 3}, "an (n,3) array");
		const long  nf = requireShape(f, "forces", {-1, 3}, "an (n,3) array");
		if (nl != nf)
			throw TypeError("forces: expected as many rows as branches (" + std::to_string(nl) + "), got " + std::to_string(nf));
		std::vector<long> zero(nl, 0);
		np::ndarray       out = emptyDoubles({3, 3});
		fabricStressMany(1, &r, nl, zero.data(), dptr(l), dptr(f), wptr(out));
		return finiteResult(out, "radius, branches, forces", "fabric stress", false);
	}

	np::ndarray grainStresses(const bp::object& radii, const bp::object& grainIndex, const bp::object& branches,
	                          const bp::object& forces)
	{
		np::ndarray r  = asDoubles(radii, "radii");
		const long  n  = requireShape(r, "radii", {-1}, "a 1-d array");
		np::ndarray gi = asIndices(grainIndex, "grainIndex");
		const long  m  = requireShape(gi, "grainIndex", {-1}, "a 1-d array");
		np::ndarray l  = asDoubles(branches, "branches");
		np::ndarray f  = asDoubles(forces, "forces");
		requireShape(l, "branches", {m, 3}, "an (" + std::to_string(m) + ",3) array, one row per grainIndex");
		requireShape(f, "forces", {m, 3}, "an (" + std::to_string(m) + ",3) array, one row per grainIndex");
		np::ndarray out = emptyDoubles({n, 3, 3});
		fabricStressMany(n, dptr(r), m, lptr(gi), dptr(l), dptr(f), wptr(out));
		return finiteResult(out, "radii, branches, forces", "fabric stress");
	}
}  // namespace

void registerFabricStress()
{
	bp::def("fabricStress", fabricStressOfOne, (bp::arg("radius"), "branches", "forces"),
	        "Fabric (Love-Weber) stress of one grain, eq. 3 [Pa]: (1/V) sum_c l^c (x) F^c, V = 4/3 pi r^3.\n"
	        "radius [m] > 0; branches (n,3) [m] from the grain centre to each contact point; forces (n,3) [N] acting on the grain.\n"
	        "Returns a (3,3) array, compression negative.");
	bp::def("grainStresses", grainStresses, (bp::arg("radii"), "grainIndex", "branches", "forces"),
	        "Eq. 3 for many grains from flat contact arrays: radii (N,) [m]; grainIndex (M,) integers in [0,N);\n"
	        "branches (M,3) [m]; forces (M,3) [N]. Returns (N,3,3) [Pa].");
}

}  // namespace binding
}  // namespace ballast
