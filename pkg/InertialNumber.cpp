#include "InertialNumber.hpp"

#include <cmath>

#include "InputCheck.hpp"

namespace ballast {

double inertialNumber(double rate, double d, double density, double pressure)
{
	requireFinite("rate", rate);
	requirePositive("d", d);
	requirePositive("density", density);
	requirePositive("pressure", pressure);
	const double I = std::abs(rate) * d * std::sqrt(density / pressure);
	requireFiniteResult("rate, d, density, pressure", "inertial number", I);
	return I;
}

}  // namespace ballast
