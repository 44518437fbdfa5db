// Tests of the equivalent stress, Dubina & Elias eq. 2, and the principal stresses it is defined by.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "VonMises.hpp"

using namespace ballast;

namespace {

const double kRel = 1e-12;  // relative tolerance for closed forms (a handful of roundings)
const double kEig = 1e-10;  // relative tolerance against an iterative eigen-solver

// Eq. 2 written out from principal stresses.
double eq2(const Vec3& p)
{
	return std::sqrt(((p[0] - p[1]) * (p[0] - p[1]) + (p[1] - p[2]) * (p[1] - p[2]) + (p[0] - p[2]) * (p[0] - p[2])) / 2.0);
}

}  // namespace

TEST(VonMises, Uniaxial)
{
	// sI = sigma, sII = sIII = 0: eq. 2 = sqrt((s^2 + 0 + s^2)/2) = |s|, in tension and compression, on any axis.
	for (double sig : {-3.7e7, 2.1e6}) {
		for (int ax = 0; ax < 3; ++ax) {
			Mat3 s     = Mat3::Zero();
			s(ax, ax) = sig;
			EXPECT_NEAR(vonMises(s), std::abs(sig), kRel * std::abs(sig));
		}
	}
}

TEST(VonMises, IsotropicIsZero)
{
	// Hydrostatic p: all principal stresses equal, no deviator.
	const double p = -5.3e6;
	EXPECT_NEAR(vonMises(p * Mat3::Identity()), 0.0, kRel * std::abs(p));
	// and adding hydrostatic pressure does not change it
	Mat3 s     = Mat3::Zero();
	s(2, 2)    = 4e6;
	EXPECT_NEAR(vonMises(s + p * Mat3::Identity()), 4e6, kRel * 4e6);
}

TEST(VonMises, PureShear)
{
	// Shear tau: principal (tau, 0, -tau) -> sqrt((tau^2 + tau^2 + 4 tau^2)/2) = sqrt(3) tau.
	const double tau = 1.3e6;
	for (int i = 0; i < 3; ++i) {
		const int j = (i + 1) % 3;
		Mat3      s = Mat3::Zero();
		s(i, j) = s(j, i) = tau;
		EXPECT_NEAR(vonMises(s), std::sqrt(3.0) * tau, kRel * tau);
		const Vec3 p = principalStresses(s);
		EXPECT_NEAR(p[0], tau, kEig * tau);
		EXPECT_NEAR(p[1], 0.0, kEig * tau);
		EXPECT_NEAR(p[2], -tau, kEig * tau);
	}
}

TEST(VonMises, NonSymmetricUsesSymmetricPart)
{
	// s_xy = tau + w, s_yx = tau - w: symmetric part is pure shear tau, the skew part w carries no stress.
	const double tau = 2e5, w = 7e5;
	Mat3         s = Mat3::Zero();
	s(0, 1)        = tau + w;
	s(1, 0)        = tau - w;
	EXPECT_NEAR(vonMises(s), std::sqrt(3.0) * tau, kRel * tau);
	const Vec3 p = principalStresses(s);
	EXPECT_NEAR(p[0], tau, kEig * tau);
	EXPECT_NEAR(p[2], -tau, kEig * tau);
	// one-sided entry: s_xy = t, s_yx = 0 -> shear t/2 -> sqrt(3) t/2; transposing changes nothing
	Mat3 one   = Mat3::Zero();
	one(1, 2)  = 4e5;
	EXPECT_NEAR(vonMises(one), std::sqrt(3.0) * 2e5, kRel * 2e5);
	EXPECT_NEAR(vonMises(one.transpose()), std::sqrt(3.0) * 2e5, kRel * 2e5);
}

TEST(VonMises, PrincipalStressesOfRotatedDiagonal)
{
	// R D R^T with D = diag(3, -1, 2) MPa has eigenvalues {3, 2, -1} MPa, returned in descending order.
	const double     M = 1e6;
	const Mat3       D = Vec3(3 * M, -1 * M, 2 * M).asDiagonal();
	const Mat3       R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
	const Mat3       s = R * D * R.transpose();
	const Vec3       p = principalStresses(s);
	EXPECT_NEAR(p[0], 3 * M, kEig * M);
	EXPECT_NEAR(p[1], 2 * M, kEig * M);
	EXPECT_NEAR(p[2], -1 * M, kEig * M);
	// eq. 2 by hand: ((3-2)^2 + (2+1)^2 + (3+1)^2)/2 = 13 -> sqrt(13) MPa, invariant under rotation
	EXPECT_NEAR(vonMises(s), std::sqrt(13.0) * M, kEig * M);
}

TEST(VonMises, RandomTensorsMatchEq2)
{
	// The sqrt(3 J2) evaluation equals eq. 2 from the principal stresses of the symmetric part.
	std::mt19937                           gen(99);
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	for (int k = 0; k < 200; ++k) {
		Mat3 s;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				s(i, j) = 1e7 * u(gen);
		const Vec3 p = principalStresses(s);
		EXPECT_GE(p[0], p[1]);
		EXPECT_GE(p[1], p[2]);
		// principal stresses of the symmetric part: their sum is the trace, their squares sum to ||sym||_F^2
		const Mat3 sym = 0.5 * (s + s.transpose());
		EXPECT_NEAR(p.sum(), s.trace(), kEig * 1e7);
		EXPECT_NEAR(p.squaredNorm(), sym.squaredNorm(), kEig * 1e14);
		EXPECT_NEAR(vonMises(s), eq2(p), kEig * 1e7);
	}
}

TEST(VonMises, ZeroTensor)
{
	EXPECT_EQ(vonMises(Mat3::Zero()), 0.0);
	const Vec3 p = principalStresses(Mat3::Zero());
	EXPECT_EQ(p.norm(), 0.0);
}
