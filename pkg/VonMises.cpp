#include "VonMises.hpp"

#include <algorithm>
#include <cmath>

namespace ballast {

Vec3 principalStresses(const Mat3& s)
{
	const Mat3                                  sym = 0.5 * (s + s.transpose());
	Eigen::SelfAdjointEigenSolver<Mat3> eig(sym, Eigen::EigenvaluesOnly);
	Vec3                                        p = eig.eigenvalues();  // ascending
	return Vec3(p[2], p[1], p[0]);
}

double vonMises(const Mat3& s)
{
	const double sxx = s(0, 0), syy = s(1, 1), szz = s(2, 2);
	const double txy = 0.5 * (s(0, 1) + s(1, 0));
	const double tyz = 0.5 * (s(1, 2) + s(2, 1));
	const double tzx = 0.5 * (s(2, 0) + s(0, 2));
	const double j2x3 = 0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx))
	        + 3.0 * (txy * txy + tyz * tyz + tzx * tzx);
	return std::sqrt(std::max(0.0, j2x3));
}

}  // namespace ballast
