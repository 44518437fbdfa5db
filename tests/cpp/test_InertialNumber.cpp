// Tests of the inertial number I = |rate| d sqrt(rho / p) (GDR MiDi 2004).
#include <gtest/gtest.h>

#include <cmath>

#include "InertialNumber.hpp"
#include "InputCheck.hpp"

using namespace ballast;

TEST(InertialNumber, ByHand)
{
	// the oedometer before crushing: plate at 1 mm/s on a 0.15 m sample (rate 6.67e-3 1/s), d = 32.5 mm,
	// rho = 2600 kg/m^3, 1 MN on a 0.3 m cylinder (p = 1.415e7 Pa): I = 6.67e-3 * 0.0325 * 1.3556e-2 = 2.94e-6
	const double rate = 1e-3 / 0.15, p = 1e6 / (M_PI * 0.15 * 0.15);
	const double I = rate * 0.0325 * std::sqrt(2600.0 / p);
	EXPECT_NEAR(inertialNumber(rate, 0.0325, 2600.0, p), I, 1e-15 * I);
	EXPECT_NEAR(I, 2.937e-6, 1e-9);
	EXPECT_EQ(inertialNumber(-rate, 0.0325, 2600.0, p), inertialNumber(rate, 0.0325, 2600.0, p));  // |rate|
}

TEST(InertialNumber, ScalesWithTheRootOfTheDensity)
{
	// density scaling by 25 makes I 5 times larger at the same rate and pressure
	EXPECT_NEAR(inertialNumber(0.1, 0.03, 25 * 2600.0, 1e6), 5 * inertialNumber(0.1, 0.03, 2600.0, 1e6), 1e-15);
}

TEST(InertialNumber, BadInput)
{
	EXPECT_THROW(inertialNumber(0.1, 0.03, 2600.0, 0.0), ArgumentError);
	EXPECT_THROW(inertialNumber(NAN, 0.03, 2600.0, 1e6), ArgumentError);
	EXPECT_THROW(inertialNumber(0.1, -0.03, 2600.0, 1e6), ArgumentError);
}
