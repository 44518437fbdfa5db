// Tests of the size-dependent strength, Dubina & Elias eq. 4: f_t = f_t0 / r^m (paper: m = 1). sizeStrength
// checks nothing; its parameters are checked once by CrushParameters::checked (test_BallastCrushEngine.cpp)
// and by the binding (tests/python/test__ballast_Strength.py).
#include <gtest/gtest.h>

#include <cmath>

#include "Strength.hpp"

using namespace ballast;

namespace {

const double kRel = 1e-14;  // one division or one pow: a couple of ulps

}  // namespace

TEST(Strength, PaperExponent)
{
	// Eq. 4: f_t = f_t0 / r, halving the radius doubles the strength.
	const double ft0 = 2.5e5, r = 0.0175;
	EXPECT_NEAR(sizeStrength(ft0, r, 1.0), ft0 / r, kRel * ft0 / r);
	EXPECT_NEAR(sizeStrength(ft0, r), ft0 / r, kRel * ft0 / r);  // default m = 1
	EXPECT_NEAR(sizeStrength(ft0, r / 2) / sizeStrength(ft0, r), 2.0, kRel * 2.0);
}

TEST(Strength, OtherExponents)
{
	const double ft0 = 3e3, r = 0.02;
	EXPECT_NEAR(sizeStrength(ft0, r, 2.0), ft0 / (r * r), kRel * ft0 / (r * r));
	EXPECT_NEAR(sizeStrength(ft0, r, 0.0), ft0, kRel * ft0);  // no size effect
	// m = 1.5: ft0 / (r sqrt r)
	EXPECT_NEAR(sizeStrength(ft0, r, 1.5), ft0 / (r * std::sqrt(r)), 1e-13 * ft0 / (r * std::sqrt(r)));
}

TEST(Strength, PaperExponentIsOneDivision)
{
	// m = 1 is computed as ft0 / r, not through pow: bit for bit the paper's eq. 4.
	for (double r : {0.0103, 0.0175, 0.02225})
		EXPECT_EQ(sizeStrength(3.1e6, r, 1.0), 3.1e6 / r) << r;
}

TEST(Strength, EndsOfTheRangeOfM)
{
	// m = 3, the largest allowed: f_t = ft0 / r^3 (the size effect of Weibull modulus 1).
	const double ft0 = 2.0, r = 0.5;
	EXPECT_NEAR(sizeStrength(ft0, r, 3.0), 16.0, kRel * 16.0);
	EXPECT_EQ(sizeStrength(ft0, r, 0.0), ft0);  // r^0 = 1 exactly
}
