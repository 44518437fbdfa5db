// Tests of the bulk crushing decision, Dubina & Elias section 2: crush <=> r >= rMin and sigma_e > f_t (eq. 1),
// sigma_e by eq. 2 of the fabric stress of eq. 3, f_t = ft0 / r^m (eq. 4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "BallastCrushEngine.hpp"
#include "FabricStress.hpp"
#include "ArgumentMessage.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

const double kPi  = std::acos(-1.0);
const double kRel = 1e-12;

// Row-major fabric stress of a grain of radius r squeezed by two opposite forces F along x (eq. 3):
// sigma_xx = -3F/(2 pi r^2), so sigma_e = 3F/(2 pi r^2) (eq. 2, uniaxial).
void diametral(double r, double F, double* s9)
{
	for (int k = 0; k < 9; ++k)
		s9[k] = 0;
	s9[0] = -3.0 * F / (2.0 * kPi * r * r);
}

// Force that gives sigma_e = target on a grain of radius r in the diametral test.
double forceFor(double target, double r) { return target * 2.0 * kPi * r * r / 3.0; }

// The message of CrushParameters::checked, the one check of the parameters, or "" when they are accepted.
std::string messageOf(double ft0, double m, double rMin)
{
	return ballast_test::messageOf([&] { CrushParameters::checked(ft0, m, rMin); });
}

}  // namespace

TEST(BallastCrushEngine, ThresholdAboveAndBelow)
{
	// Grains at 1.01 f_t crush, at 0.99 f_t do not; f_t = ft0 / r (eq. 4 with m = 1).
	const CrushParameters p = CrushParameters::checked(2.5e5, 1.0, 0.0);
	const double          radii[4] = {0.012, 0.012, 0.022, 0.022};
	const double          factor[4] = {1.01, 0.99, 0.99, 1.01};
	double                s[36], se[4], ft[4];
	std::uint8_t          crush[4];
	for (int g = 0; g < 4; ++g)
		diametral(radii[g], forceFor(factor[g] * p.ft0 / radii[g], radii[g]), s + 9 * g);
	evaluateCrushing(p, 4, s, radii, nullptr, nullptr, se, ft, crush);
	for (int g = 0; g < 4; ++g) {
		const double fth = p.ft0 / radii[g];
		EXPECT_NEAR(ft[g], fth, kRel * fth) << g;
		EXPECT_NEAR(se[g], factor[g] * fth, kRel * fth) << g;
		EXPECT_EQ(crush[g], factor[g] > 1 ? 1 : 0) << g;
	}
}

TEST(BallastCrushEngine, ThroughFabricStress)
{
	// Chain eq. 3 -> eq. 2 -> eq. 1: contact forces F = 1.01 * (2 pi r^2 / 3) f_t crush, 0.99 does not.
	const CrushParameters p = CrushParameters::checked(1.8e5, 1.0, 0.0);
	const double          r = 0.016, ft = p.ft0 / r;
	for (double factor : {1.01, 0.99}) {
		const double F = forceFor(factor * ft, r);
		const Mat3   S = fabricStress(r, {Vec3(r, 0, 0), Vec3(-r, 0, 0)}, {Vec3(-F, 0, 0), Vec3(F, 0, 0)});
		double       s9[9];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				s9[3 * i + j] = S(i, j);
		double       se, st;
		std::uint8_t c;
		evaluateCrushing(p, 1, s9, &r, nullptr, nullptr, &se, &st, &c);
		EXPECT_NEAR(se, 3.0 * F / (2.0 * kPi * r * r), kRel * ft);
		EXPECT_NEAR(se, factor * ft, kRel * ft);
		EXPECT_EQ(c, factor > 1 ? 1 : 0);
	}
}

TEST(BallastCrushEngine, ExactlyAtThresholdDoesNotCrush)
{
	// Eq. 1 is strict: sigma_e == f_t is no crush. Uniaxial stress -f_t gives sigma_e = f_t exactly
	// (sqrt of the rounded square of x is x in IEEE arithmetic), and f_t = ft0 / r is one division.
	const CrushParameters p = CrushParameters::checked(3e5, 1.0, 0.0);
	const double          r = 0.019, ft = p.ft0 / r;
	double                s9[9] = {-ft, 0, 0, 0, 0, 0, 0, 0, 0};
	double                se, st;
	std::uint8_t          c;
	evaluateCrushing(p, 1, s9, &r, nullptr, nullptr, &se, &st, &c);
	EXPECT_NEAR(se, ft, kRel * ft);
	EXPECT_EQ(c, se > st ? 1 : 0);
	EXPECT_EQ(c, 0);
}

TEST(BallastCrushEngine, SizeExponent)
{
	// m = 2: f_t = ft0 / r^2; m = 0: f_t = ft0 whatever the size.
	const double r = 0.02;
	for (double m : {0.0, 2.0}) {
		const CrushParameters p = CrushParameters::checked(m == 0 ? 6e6 : 2.4e3, m, 0.0);
		const double          fth = p.ft0 / std::pow(r, m);
		for (double factor : {1.01, 0.99}) {
			double s9[9];
			diametral(r, forceFor(factor * fth, r), s9);
			double       se, st;
			std::uint8_t c;
			evaluateCrushing(p, 1, s9, &r, nullptr, nullptr, &se, &st, &c);
			EXPECT_NEAR(st, fth, kRel * fth) << "m = " << m;
			EXPECT_EQ(c, factor > 1 ? 1 : 0) << "m = " << m;
		}
	}
}

TEST(BallastCrushEngine, MinimumRadius)
{
	// r < rMin never crushes, even at 1e6 times its strength; r == rMin is eligible.
	const double          rMin = 0.01;
	const CrushParameters p = CrushParameters::checked(2e5, 1.0, rMin);
	const double          radii[3] = {0.5 * rMin, std::nextafter(rMin, 0.0), rMin};
	double                s[27], se[3], ft[3];
	std::uint8_t          crush[3];
	for (int g = 0; g < 3; ++g)
		diametral(radii[g], forceFor(1e6 * p.ft0 / radii[g], radii[g]), s + 9 * g);
	evaluateCrushing(p, 3, s, radii, nullptr, nullptr, se, ft, crush);
	EXPECT_EQ(crush[0], 0);
	EXPECT_EQ(crush[1], 0);
	EXPECT_EQ(crush[2], 1);
	// sigma_e and f_t are still reported for the small grains
	EXPECT_NEAR(se[0], 1e6 * p.ft0 / radii[0], kRel * 1e6 * p.ft0 / radii[0]);
	EXPECT_NEAR(ft[0], p.ft0 / radii[0], kRel * p.ft0 / radii[0]);
}

TEST(BallastCrushEngine, RowMajorShearAndSymmetricPart)
{
	// Stress with only s_xy = t (row-major index 1) has symmetric shear t/2: sigma_e = sqrt(3) t / 2.
	const CrushParameters p = CrushParameters::checked(1e5, 1.0, 0.0);
	const double          r = 0.02, ft = p.ft0 / r;
	for (double factor : {1.01, 0.99}) {
		const double t     = factor * ft * 2.0 / std::sqrt(3.0);
		double       s9[9] = {0, t, 0, 0, 0, 0, 0, 0, 0};
		double       se, st;
		std::uint8_t c;
		evaluateCrushing(p, 1, s9, &r, nullptr, nullptr, &se, &st, &c);
		EXPECT_NEAR(se, std::sqrt(3.0) * t / 2.0, kRel * ft);
		EXPECT_EQ(c, factor > 1 ? 1 : 0);
	}
}

TEST(BallastCrushEngine, ParametersAreCheckedOnceAgainstTheirRanges)
{
	// ft0 > 0, m in [0, 3] (the ranges of InputCheck.hpp, which ballast.params exports too), rMin >= 0;
	// the message names the parameter, the value and the range.
	const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
	EXPECT_EQ(messageOf(0.0, 1.0, 0.0), "ft0: expected a finite number > 0, got 0");
	EXPECT_EQ(messageOf(-1.0, 1.0, 0.0), "ft0: expected a finite number > 0, got -1");
	EXPECT_EQ(messageOf(nan, 1.0, 0.0), "ft0: expected a finite number > 0, got nan");
	EXPECT_EQ(messageOf(inf, 1.0, 0.0), "ft0: expected a finite number > 0, got inf");
	EXPECT_EQ(messageOf(1e5, -1.0, 0.0), "m: expected a number in [0, 3], got -1");
	EXPECT_EQ(messageOf(1e5, std::nextafter(3.0, 4.0), 0.0).rfind("m: expected a number in [0, 3], got 3.0000000000000004", 0), 0u);
	EXPECT_EQ(messageOf(1e5, nan, 0.0), "m: expected a number in [0, 3], got nan");
	EXPECT_EQ(messageOf(1e5, 1.0, -0.01), "rMin: expected a finite number >= 0, got -0.01");
	EXPECT_EQ(messageOf(1e5, 1.0, nan), "rMin: expected a finite number >= 0, got nan");
	EXPECT_EQ(messageOf(1e5, 1.0, inf), "rMin: expected a finite number >= 0, got inf");
	EXPECT_EQ(messageOf(-1.0, -1.0, -1.0).rfind("ft0", 0), 0u);  // the first bad one, in the order of the arguments
	EXPECT_EQ(messageOf(1e5, 0.0, 0.0), "");                     // the ends of the closed ranges are allowed
	EXPECT_EQ(messageOf(1e5, 3.0, 0.0), "");
	EXPECT_EQ(messageOf(5e-324, 1.0, 0.0), "");  // the smallest ft0 > 0
}

TEST(BallastCrushEngine, BadGrainValuesNameTheGrain)
{
	// evaluateCrushing checks what is per grain: a radius, a largest contact force, a strength factor.
	const double          nan = std::numeric_limits<double>::quiet_NaN();
	const CrushParameters p   = CrushParameters::checked(1e5, 1.0, 0.0);
	double                s[18] = {}, se[2], ft[2];
	std::uint8_t          c[2];
	const double          radii[2] = {0.01, -0.02};
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateCrushing(p, 2, s, radii, nullptr, nullptr, se, ft, c); }),
	          "radii[1]: expected a finite number > 0, got -0.02");
	const double nanR[1] = {nan};
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateCrushing(p, 1, s, nanR, nullptr, nullptr, se, ft, c); }),
	          "radii[0]: expected a finite number > 0, got nan");
	const double good[2] = {0.01, 0.02}, fMax[2] = {1.0, -1.0}, factor[2] = {1.0, 0.0};
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateCrushing(p, 2, s, good, fMax, nullptr, se, ft, c); }),
	          "fMax[1]: expected a finite number >= 0, got -1");
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateCrushing(p, 2, s, good, nullptr, factor, se, ft, c); }),
	          "factor[1]: expected a finite number > 0, got 0");
}

TEST(BallastCrushEngine, NoGrains)
{
	// n = 0 touches nothing.
	EXPECT_NO_THROW(evaluateCrushing(CrushParameters::checked(1e5, 1.0, 0.0), 0, nullptr, nullptr, nullptr, nullptr, nullptr,
	                                 nullptr, nullptr));
}

TEST(BallastCrushEngine, CriterionAndStrengthFactor)
{
	// A grain squeezed along a diameter at sigma_e = 0.9 f_t: intact; with a Weibull factor 0.8 its
	// strength is 0.8 f_t < 0.9 f_t: crushed. Under maxContactForce its stress is F / (4 r^2).
	const double r = 0.02, ft0 = 2e5, ft = ft0 / r, F = forceFor(0.9 * ft, r);
	double       s9[9], stress, st;
	std::uint8_t c;
	diametral(r, F, s9);
	const CrushParameters p    = CrushParameters::checked(ft0, 1.0, 0.0);
	const double          weak = 0.8, strong = 1.0;
	evaluateCrushing(p, 1, s9, &r, nullptr, &strong, &stress, &st, &c);
	EXPECT_EQ(c, 0);
	evaluateCrushing(p, 1, s9, &r, nullptr, &weak, &stress, &st, &c);
	EXPECT_EQ(c, 1);
	EXPECT_NEAR(st, 0.8 * ft, 1e-12 * ft);
	const CrushParameters q = CrushParameters::checked(ft0, 1.0, 0.0, Criterion::MaxContactForce);
	evaluateCrushing(q, 1, s9, &r, &F, nullptr, &stress, &st, &c);
	EXPECT_NEAR(stress, F / (4 * r * r), 1e-12 * ft);
	EXPECT_EQ(c, F / (4 * r * r) > ft ? 1 : 0);
	EXPECT_THROW(evaluateCrushing(q, 1, s9, &r, nullptr, nullptr, &stress, &st, &c), ArgumentError);  // no fMax
	const double zero = 0.0;
	EXPECT_THROW(evaluateCrushing(q, 1, s9, &r, &F, &zero, &stress, &st, &c), ArgumentError);  // factor must be > 0
}
