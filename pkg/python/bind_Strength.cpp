// Binding of Strength.hpp: the size-dependent strength of eq. 4 on scalars or broadcast arrays.
#include "../InputCheck.hpp"
#include "../Strength.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	// Each element is an entry: ft0 and m are checked against the engines' ranges (the same as crushCheck's).
	double checkedSizeStrength(const double* x)
	{
		const double ft0 = requireInRange(ranges::ft0, "ft0", x[0]);
		requirePositive("radius", x[1]);
		return sizeStrength(ft0, x[1], requireInRange(ranges::m, "m", x[2]));
	}

	bp::object sizeStrengthOf(const bp::object& ft0, const bp::object& r, const bp::object& m)
	{
		return elementwise({{"ft0", ft0}, {"radius", r}, {"m", m}}, "strength ft0 / r^m", checkedSizeStrength);
	}
}  // namespace

void registerStrength()
{
	bp::def("sizeStrength", sizeStrengthOf, (bp::arg("ft0"), "radius", bp::arg("m") = 1.0),
	        "Size-dependent strength, eq. 4 [Pa]: ft0 / r^m; ft0 [Pa m^m], radius [m], m [-] (paper: 1).");
}

}  // namespace binding
}  // namespace ballast
