#include "BallastCrushEngine.hpp"

#include "InputCheck.hpp"
#include "Strength.hpp"
#include "Types.hpp"

namespace ballast {

CrushParameters CrushParameters::checked(double ft0, double m, double rMin, Criterion criterion)
{
	// braces: checked in the order written
	return CrushParameters{requireInRange(ranges::ft0, "ft0", ft0), requireInRange(ranges::m, "m", m),
	                       requireInRange(ranges::rMin, "rMin", rMin), criterion};
}

void evaluateCrushing(const CrushParameters& p, long n, const double* stresses, const double* radii, const double* fMax,
                      const double* factor, double* stress, double* strength, std::uint8_t* crush)
{
	if (p.criterion == Criterion::MaxContactForce && !fMax)
		throw ArgumentError("fMax: the maxContactForce criterion needs the largest contact force of every grain");
	for (long g = 0; g < n; ++g) {
		requirePositive("radii", g, radii[g]);
		if (fMax) requireNonNegative("fMax", g, fMax[g]);
		if (factor) requirePositive("factor", g, factor[g]);
		// Eigen maps are column-major by default; the stress is row-major, and the criteria use its
		// symmetric part, which does not care about the transposition.
		const Eigen::Map<const Mat3> s(stresses + 9 * g);
		stress[g]   = criterionStress(p.criterion, s, fMax ? fMax[g] : 0.0, radii[g]);
		strength[g] = sizeStrength(p.ft0, radii[g], p.m) * (factor ? factor[g] : 1.0);  // eq. 4, times w
		crush[g]    = radii[g] >= p.rMin && stress[g] > strength[g];                      // eq. 1
	}
}

}  // namespace ballast
