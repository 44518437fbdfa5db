#include "Strength.hpp"

#include <cassert>
#include <cmath>

namespace ballast {

double sizeStrength(double ft0, double r, double m)
{
	assert(ft0 > 0 && r > 0 && m >= 0);
	return m == 1.0 ? ft0 / r : ft0 / std::pow(r, m);  // eq. 4
}

}  // namespace ballast
