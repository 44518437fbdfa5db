// Binding of DensityScaling.hpp: a body's own P-wave step and YADE's densityScaling factor, on scalars
// or broadcast arrays.
#include "../DensityScaling.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::object pWaveStepOf(const bp::object& r, const bp::object& density, const bp::object& young)
	{
		return elementwise({{"r", r}, {"density", density}, {"young", young}}, "P-wave step",
		                   [](const double* x) { return pWaveStep(x[0], x[1], x[2]); });
	}

	bp::object densityScalingOf(const bp::object& ownStep, const bp::object& targetStep)
	{
		return elementwise({{"ownStep", ownStep}, {"targetStep", targetStep}}, "density scaling",
		                   [](const double* x) { return densityScaling(x[0], x[1]); });
	}
}  // namespace

void registerDensityScaling()
{
	bp::def("pWaveStep", pWaveStepOf, (bp::arg("r"), "density", "young"),
	        "Eq. 5 for one sphere: r sqrt(density / young) [s]; r [m], density [kg/m^3], young [Pa] > 0;\n"
	        "scalars or arrays (broadcast).");
	bp::def("densityScaling", densityScalingOf, (bp::arg("ownStep"), "targetStep"),
	        "YADE's State.densityScaling for a body whose own step is ownStep [s] to reach targetStep [s]:\n"
	        "(ownStep / targetStep)^2, at most 1 (a body is never made lighter); targetStep 0 gives 1.");
}

}  // namespace binding
}  // namespace ballast
