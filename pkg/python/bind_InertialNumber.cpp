// Binding of InertialNumber.hpp: I = rate d sqrt(rho / p), on scalars or broadcast arrays.
#include "../InertialNumber.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::object inertialNumberOf(const bp::object& rate, const bp::object& d, const bp::object& density,
	                            const bp::object& pressure)
	{
		return elementwise({{"rate", rate}, {"d", d}, {"density", density}, {"pressure", pressure}}, "inertial number",
		                   [](const double* x) { return inertialNumber(x[0], x[1], x[2], x[3]); });
	}
}  // namespace

void registerInertialNumber()
{
	bp::def("inertialNumber", inertialNumberOf, (bp::arg("rate"), "d", "density", "pressure"),
	        "Inertial number I = |rate| d sqrt(density / pressure) [-] (GDR MiDi 2004): rate [1/s], grain\n"
	        "diameter d [m], density [kg/m^3] and pressure [Pa] > 0; scalars or arrays. Below 1e-3: quasi-static.");
}

}  // namespace binding
}  // namespace ballast
