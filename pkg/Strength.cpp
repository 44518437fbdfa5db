#include "Strength.hpp"

#include <cmath>

#include "InputCheck.hpp"

namespace ballast {

double sizeStrength(double ft0, double r, double m)
{
	requirePositive("ft0", ft0);
	requirePositive("radius", r);
	requireNonNegative("m", m);
	return m == 1.0 ? ft0 / r : ft0 / std::pow(r, m);
}

}  // namespace ballast
