// Binding of HertzPressure.hpp: eq. 7 and the contact quantities it needs, on scalars or broadcast arrays.
#include "../HertzPressure.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::object hertzPressureOf(const bp::object& Fn, const bp::object& R1, const bp::object& R2, const bp::object& uN)
	{
		return elementwise({{"Fn", Fn}, {"R1", R1}, {"R2", R2}, {"uN", uN}}, "Hertz pressure",
		                   [](const double* x) { return hertzPressure(x[0], x[1], x[2], x[3]); });
	}

	bp::object effectiveRadiusOf(const bp::object& R1, const bp::object& R2)
	{
		return elementwise({{"R1", R1}, {"R2", R2}}, "effective radius",
		                   [](const double* x) { return effectiveRadius(x[0], x[1]); });
	}

	bp::object contactModulusOf(const bp::object& E1, const bp::object& nu1, const bp::object& E2, const bp::object& nu2)
	{
		return elementwise({{"E1", E1}, {"nu1", nu1}, {"E2", E2}, {"nu2", nu2}}, "contact modulus",
		                   [](const double* x) { return contactModulus(x[0], x[1], x[2], x[3]); });
	}

	bp::object hertzPressureFromForceOf(const bp::object& Fn, const bp::object& R, const bp::object& Estar)
	{
		return elementwise({{"Fn", Fn}, {"R", R}, {"Estar", Estar}}, "Hertz pressure",
		                   [](const double* x) { return hertzPressureFromForce(x[0], x[1], x[2]); });
	}
}  // namespace

void registerHertzPressure()
{
	bp::def("hertzPressure", hertzPressureOf, (bp::arg("Fn"), "R1", "R2", "uN"),
	        "Maximum Hertz pressure, eq. 7 [Pa]: p0 = 3 Fn / (2 pi R uN), R = R1 R2 / (R1 + R2).\n"
	        "Fn [N], R1, R2 [m], uN overlap [m]; scalars or arrays (broadcast). A radius of 0 is a flat wall\n"
	        "(R2 = 0 gives R = R1). No compression (Fn <= 0 or uN <= 0) gives 0.");
	bp::def("effectiveRadius", effectiveRadiusOf, (bp::arg("R1"), "R2"), "R1 R2 / (R1 + R2) [m]; 0 is a wall.");
	bp::def("contactModulus", contactModulusOf, (bp::arg("E1"), "nu1", "E2", "nu2"),
	        "Hertz contact modulus E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa]; scalars or arrays.");
	bp::def("hertzPressureFromForce", hertzPressureFromForceOf, (bp::arg("Fn"), "R", "Estar"),
	        "Eq. 7 on a Hertzian contact from the force alone: (6 Fn E*^2 / (pi^3 R^2))^(1/3) [Pa]; Fn [N],\n"
	        "R effective radius [m], Estar contact modulus [Pa]; scalars or arrays. Fn <= 0 gives 0.");
}

}  // namespace binding
}  // namespace ballast
