#include "BallastCrushEngine.hpp"

#include <cmath>
#include <string>

#include "InputCheck.hpp"
#include "Strength.hpp"
#include "Types.hpp"
#include "VonMises.hpp"

namespace ballast {

void CrushParameters::validate() const
{
	requirePositive("ft0", ft0);
	requireNonNegative("m", m);
	requireNonNegative("rMin", rMin);
}

void evaluateCrushing(const CrushParameters& p, long n, const double* stresses, const double* radii, double* sigmaE,
                      double* strength, std::uint8_t* crush)
{
	p.validate();
	for (long g = 0; g < n; ++g) {
		requirePositive("radii", g, radii[g]);
		// Eigen maps are column-major by default; the stress is row-major, and von Mises of the
		// symmetric part does not care about the transposition.
		const Eigen::Map<const Mat3> s(stresses + 9 * g);
		sigmaE[g]   = vonMises(s);
		strength[g] = sizeStrength(p.ft0, radii[g], p.m);
		crush[g]    = radii[g] >= p.rMin && sigmaE[g] > strength[g];  // eq. 1
	}
}

}  // namespace ballast
