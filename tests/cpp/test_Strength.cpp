// Tests of the size-dependent strength, Dubina & Elias eq. 4: f_t = f_t0 / r^m (paper: m = 1).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "InputCheck.hpp"
#include "Strength.hpp"

using namespace ballast;

namespace {

const double kRel = 1e-14;  // one division or one pow: a couple of ulps

std::string messageOf(double ft0, double r, double m)
{
	try {
		sizeStrength(ft0, r, m);
	} catch (const ArgumentError& e) {
		return e.what();
	}
	return "";
}

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

TEST(Strength, BadInputsNameTheArgument)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	struct Case {
		double      ft0, r, m;
		const char* name;
	} cases[] = {
	        {0.0, 0.01, 1.0, "ft0"}, {-1.0, 0.01, 1.0, "ft0"}, {nan, 0.01, 1.0, "ft0"},   {inf, 0.01, 1.0, "ft0"},
	        {1e5, 0.0, 1.0, "radius"}, {1e5, -0.01, 1.0, "radius"}, {1e5, nan, 1.0, "radius"}, {1e5, 0.01, -0.5, "m"},
	        {1e5, 0.01, nan, "m"},
	};
	for (const Case& c : cases) {
		EXPECT_THROW(sizeStrength(c.ft0, c.r, c.m), ArgumentError) << c.name;
		const std::string msg = messageOf(c.ft0, c.r, c.m);
		EXPECT_EQ(msg.rfind(c.name, 0), 0u) << "message should start with the name: " << msg;
	}
}
