#include "DensityScaling.hpp"

#include <cmath>

#include "InputCheck.hpp"

namespace ballast {

double pWaveStep(double r, double density, double young)
{
	requirePositive("r", r);
	requirePositive("density", density);
	requirePositive("young", young);
	const double step = r * std::sqrt(density / young);
	requireFiniteResult("r, density, young", "P-wave step", step);
	return step;
}

double densityScaling(double ownStep, double targetStep)
{
	requirePositive("ownStep", ownStep);
	requireNonNegative("targetStep", targetStep);
	if (targetStep == 0 || ownStep >= targetStep) return 1.0;
	const double q = ownStep / targetStep, s = q * q;
	if (s == 0)  // a body that could never move
		throw ArgumentError("ownStep, targetStep: (ownStep / targetStep)^2 underflows to 0 for ownStep = " + formatValue(ownStep) +
		                    " s, targetStep = " + formatValue(targetStep) + " s");
	return s;
}

}  // namespace ballast
