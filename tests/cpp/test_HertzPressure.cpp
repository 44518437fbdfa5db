// Tests of the maximum Hertz pressure, Dubina & Elias eq. 7: p0 = 3 Fn / (2 pi a^2), a^2 = R uN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "HertzPressure.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

const double kPi  = std::acos(-1.0);
const double kRel = 1e-13;  // a few roundings

std::string messageOf(double Fn, double R1, double R2, double uN)
{
	try {
		hertzPressure(Fn, R1, R2, uN);
	} catch (const ArgumentError& e) {
		return e.what();
	}
	return "";
}

}  // namespace

TEST(HertzPressure, SphereOnWall)
{
	// R2 = 0 is a wall: R = R1 (limit R2 -> inf), p0 = 3F/(2 pi R1 uN).
	const double F = 2e4, R1 = 0.02, uN = 1e-5;
	const double p0 = 3.0 * F / (2.0 * kPi * R1 * uN);
	EXPECT_NEAR(effectiveRadius(R1, 0.0), R1, kRel * R1);
	EXPECT_NEAR(hertzPressure(F, R1, 0.0, uN), p0, kRel * p0);
	// wall on side 1
	EXPECT_NEAR(effectiveRadius(0.0, R1), R1, kRel * R1);
	EXPECT_NEAR(hertzPressure(F, 0.0, R1, uN), p0, kRel * p0);
}

TEST(HertzPressure, TwoEqualSpheres)
{
	// R = R1 R1 / 2 R1 = R1/2: twice the pressure of the same sphere on a wall.
	const double F = 5e3, R1 = 0.015, uN = 2e-5;
	EXPECT_NEAR(effectiveRadius(R1, R1), R1 / 2, kRel * R1);
	const double p0 = 3.0 * F / (2.0 * kPi * (R1 / 2) * uN);
	EXPECT_NEAR(hertzPressure(F, R1, R1, uN), p0, kRel * p0);
	EXPECT_NEAR(hertzPressure(F, R1, R1, uN), 2.0 * hertzPressure(F, R1, 0.0, uN), kRel * p0);
}

TEST(HertzPressure, TwoUnequalSpheresSymmetric)
{
	// R1 = 0.01, R2 = 0.03: R = 3e-4 / 0.04 = 7.5e-3.
	const double F = 800.0, R1 = 0.01, R2 = 0.03, uN = 3e-6;
	EXPECT_NEAR(effectiveRadius(R1, R2), 7.5e-3, kRel * 7.5e-3);
	const double p0 = 3.0 * F / (2.0 * kPi * 7.5e-3 * uN);
	EXPECT_NEAR(hertzPressure(F, R1, R2, uN), p0, kRel * p0);
	EXPECT_NEAR(hertzPressure(F, R2, R1, uN), p0, kRel * p0);
	// 1/R = 1/R1 + 1/R2
	EXPECT_NEAR(1.0 / effectiveRadius(R1, R2), 1.0 / R1 + 1.0 / R2, kRel * (1.0 / R1 + 1.0 / R2));
}

TEST(HertzPressure, ConsistentWithHertzTheory)
{
	// Hertz: Fn = 4/3 E* sqrt(R) uN^1.5, a^2 = R uN, so eq. 7 gives p0 = 3 Fn / (2 pi R uN)
	//   = 3 (4/3) E* sqrt(R) uN^1.5 / (2 pi R uN) = (2/pi) E* sqrt(uN / R),
	// the classical peak pressure p0 = 2 a E* / (pi R).
	const double E = 3e11, nu = 0.3;
	const double Estar = E / (2.0 * (1.0 - nu * nu));  // two equal materials
	const double R1 = 0.02, R2 = 0.012, R = R1 * R2 / (R1 + R2);
	for (double uN : {1e-7, 1e-6, 4e-5}) {
		const double Fn = 4.0 / 3.0 * Estar * std::sqrt(R) * std::pow(uN, 1.5);
		const double p0 = 2.0 / kPi * Estar * std::sqrt(uN / R);
		EXPECT_NEAR(hertzPressure(Fn, R1, R2, uN), p0, kRel * p0) << "uN = " << uN;
		const double a = std::sqrt(R * uN);
		EXPECT_NEAR(hertzPressure(Fn, R1, R2, uN), 2.0 * a * Estar / (kPi * R), kRel * p0);
	}
}

TEST(HertzPressure, NoCompressionGivesZero)
{
	const double R1 = 0.02, R2 = 0.01;
	EXPECT_EQ(hertzPressure(0.0, R1, R2, 1e-5), 0.0);
	EXPECT_EQ(hertzPressure(-10.0, R1, R2, 1e-5), 0.0);
	EXPECT_EQ(hertzPressure(10.0, R1, R2, 0.0), 0.0);
	EXPECT_EQ(hertzPressure(10.0, R1, R2, -1e-6), 0.0);
	EXPECT_EQ(hertzPressure(-10.0, R1, 0.0, -1e-6), 0.0);
}

TEST(HertzPressure, EffectiveRadiusOfExtremeRadiiIsFinite)
{
	// R1 R2 / (R1 + R2) taken literally overflows (1e200 * 1e200) or underflows (1e-200 * 1e-200) to inf or 0
	EXPECT_NEAR(effectiveRadius(1e200, 1e200), 5e199, kRel * 5e199);
	EXPECT_NEAR(effectiveRadius(1e-200, 1e-200), 5e-201, kRel * 5e-201);
	EXPECT_NEAR(effectiveRadius(1.7e308, 1.7e308), 8.5e307, kRel * 8.5e307);
	EXPECT_NEAR(effectiveRadius(1e-200, 1e200), 1e-200, kRel * 1e-200);
	EXPECT_NEAR(effectiveRadius(3e-200, 1.5e-200), 1e-200, kRel * 1e-200);
}

TEST(HertzPressure, BadInputsThrow)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	EXPECT_THROW(effectiveRadius(0.0, 0.0), ArgumentError);
	EXPECT_THROW(hertzPressure(1.0, 0.0, 0.0, 1e-6), ArgumentError);  // two walls: no radius at all
	EXPECT_NE(messageOf(1.0, 0.0, 0.0, 1e-6).find("R1, R2"), std::string::npos);
	EXPECT_NE(messageOf(nan, 0.01, 0.01, 1e-6).find("Fn"), std::string::npos);
	EXPECT_NE(messageOf(1.0, 0.01, 0.01, nan).find("uN"), std::string::npos);
	EXPECT_NE(messageOf(1.0, nan, 0.01, 1e-6).find("R1"), std::string::npos);
	EXPECT_NE(messageOf(1.0, 0.01, nan, 1e-6).find("R2"), std::string::npos);
	EXPECT_NE(messageOf(1.0, -0.01, 0.01, 1e-6).find("R1"), std::string::npos);
	EXPECT_NE(messageOf(1.0, 0.01, -0.01, 1e-6).find("R2"), std::string::npos);
	// radii are checked even when the contact carries no force
	EXPECT_THROW(hertzPressure(0.0, -0.01, 0.01, 0.0), ArgumentError);
	EXPECT_THROW(hertzPressure(std::numeric_limits<double>::infinity(), 0.01, 0.01, 1e-6), ArgumentError);
}

TEST(HertzPressure, ContactModulusClosedForm)
{
	// Ballast on ballast (E = 3e11, nu = 0.3): E* = E / (2 (1 - nu^2)); ballast on steel (10 E, 0.25).
	const double E = 3e11;
	EXPECT_NEAR(contactModulus(E, 0.3, E, 0.3), E / (2 * (1 - 0.09)), kRel * E);
	const double mixed = 1.0 / ((1 - 0.09) / E + (1 - 0.0625) / (10 * E));
	EXPECT_NEAR(contactModulus(E, 0.3, 10 * E, 0.25), mixed, kRel * mixed);
	EXPECT_NEAR(contactModulus(10 * E, 0.25, E, 0.3), mixed, kRel * mixed);
	EXPECT_THROW(contactModulus(0.0, 0.3, E, 0.3), ArgumentError);
	EXPECT_THROW(contactModulus(E, 0.5, E, 0.3), ArgumentError);
}

TEST(HertzPressure, FromForceEqualsEq7OnAHertzContact)
{
	// Hertz law F = 4/3 E* sqrt(R) uN^(3/2): the overlap of a force, then eq. 7 from (F, uN) must
	// equal the force-only form (6 F E*^2 / (pi^3 R^2))^(1/3).
	const double Es = 1.65e11;
	for (double R : {4e-3, 1.1e-2, 2.2e-2})
		for (double F : {1.0, 3e3, 2e5}) {
			const double uN = std::pow(3 * F / (4 * Es * std::sqrt(R)), 2.0 / 3.0);
			const double p0 = hertzPressure(F, R, 0.0, uN);
			EXPECT_NEAR(hertzPressureFromForce(F, R, Es), p0, 1e-12 * p0) << "R=" << R << " F=" << F;
		}
	// p0 grows as F^(1/3): eight times the force, twice the pressure
	EXPECT_NEAR(hertzPressureFromForce(8e3, 0.01, Es), 2 * hertzPressureFromForce(1e3, 0.01, Es), 1e-12 * 1e10);
	EXPECT_EQ(hertzPressureFromForce(0.0, 0.01, Es), 0.0);
	EXPECT_EQ(hertzPressureFromForce(-5.0, 0.01, Es), 0.0);
	EXPECT_THROW(hertzPressureFromForce(1.0, 0.0, Es), ArgumentError);
	EXPECT_THROW(hertzPressureFromForce(1.0, 0.01, -1.0), ArgumentError);
	EXPECT_THROW(hertzPressureFromForce(std::numeric_limits<double>::quiet_NaN(), 0.01, Es), ArgumentError);
}
