// Tests of the fatigue law (Fatigue.hpp): Basquin-Miner damage counted on the peaks of the stress
// ratio s, crush when s > 1 - D. Expected cycles are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "Fatigue.hpp"
#include "ArgumentMessage.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

const double kPi = std::acos(-1.0);

// The load cycle in which a grain driven by s(t) = sPeak (1 - cos 2 pi t) / 2, sampled `perCycle`
// times per cycle (at t = k / perCycle), first crushes; 0 if not within maxCycles.
long crushCycle(const FatigueParameters& p, double sPeak, int perCycle, long maxCycles, GrainFatigue& g)
{
	const double r = 0.02;
	for (long c = 1; c <= maxCycles; ++c)
		for (int k = 0; k < perCycle; ++k) {
			const double  s = sPeak * (1 - std::cos(2 * kPi * k / perCycle)) / 2;
			unsigned char crush;
			evaluateFatigue(p, 1, &s, &r, &g, &crush);
			if (crush) return c;
		}
	return 0;
}

// Parameters with rMin = 0: every grain degrades.
FatigueParameters params(double exponent, double endurance, double hysteresis)
{
	return FatigueParameters::checked(exponent, endurance, hysteresis, 0.0);
}

// The message of FatigueParameters::checked, the one check of the parameters, or "" when they are accepted.
std::string messageOf(double exponent, double endurance, double hysteresis, double rMin = 0.0)
{
	return ballast_test::messageOf([&] { FatigueParameters::checked(exponent, endurance, hysteresis, rMin); });
}

}  // namespace

TEST(Fatigue, ConstantRatioCrushesInTheCycleWorkedOutByHand)
{
	// s_p = 0.6, b = 8: each peak adds (1 - 0.6) 0.6^8 = 0.4 x 0.01679616. The grain crushes once s > 1 - D,
	// i.e. once D > 0.4, i.e. after more than N_f = 0.6^-8 = 59.54 peaks (Basquin's life, as Miner's rule
	// says): k* = 60 peaks, counted as s falls in cycle 60 (1 - D = 0.5969 is then above the falling s);
	// in cycle 61 s rises past 0.5969 and the grain crushes (never in one cycle: 0.6 < 1).
	const FatigueParameters p = params(8.0, 0.5, 0.05);
	GrainFatigue            g;
	EXPECT_EQ(crushCycle(p, 0.6, 100, 1000, g), 61);
	EXPECT_EQ(g.peaks, 60);
	EXPECT_NEAR(g.damage, 60 * 0.4 * std::pow(0.6, 8), 1e-14);
}

TEST(Fatigue, CountsLoadCyclesNotChecks)
{
	// Any even number of samples per cycle hits the peak: 4, 8 or 1000 checks a cycle, the same cycle 61.
	const FatigueParameters p = params(8.0, 0.5, 0.05);
	for (int perCycle : {4, 8, 1000}) {
		GrainFatigue g;
		EXPECT_EQ(crushCycle(p, 0.6, perCycle, 1000, g), 61) << perCycle;
	}
	// 7 samples miss the peak: the largest sample is s_m = 0.6 (1 - cos(6 pi / 7)) / 2 = 0.57029; it is
	// what counts: crush in cycle floor(s_m^-8) + 2 (the sample s_m exceeds 1 - D first then).
	const double sm = 0.6 * (1 - std::cos(6 * kPi / 7)) / 2;
	GrainFatigue g;
	EXPECT_EQ(crushCycle(p, 0.6, 7, 1000, g), static_cast<long>(std::floor(std::pow(sm, -8))) + 2);
}

TEST(Fatigue, BelowTheEnduranceRatioNoDamage)
{
	const FatigueParameters p = params(8.0, 0.5, 0.05);
	GrainFatigue            g;
	EXPECT_EQ(crushCycle(p, 0.49, 50, 5000, g), 0);
	EXPECT_EQ(g.damage, 0.0);
	EXPECT_EQ(g.peaks, 0.0);
}

TEST(Fatigue, RipplesSmallerThanTheHysteresisAreNotCycles)
{
	// s ripples between 0.8 and 0.78 (a fall of 0.02 < 0.05) a thousand times, then falls to 0: one peak.
	const FatigueParameters p = params(4.0, 0.5, 0.05);
	GrainFatigue            g;
	for (int k = 0; k < 1000; ++k) {
		sampleFatigue(p, 0.8, g);
		sampleFatigue(p, 0.78, g);
	}
	EXPECT_EQ(g.peaks, 0.0);
	sampleFatigue(p, 0.0, g);
	EXPECT_EQ(g.peaks, 1.0);
	EXPECT_NEAR(g.damage, 0.2 * std::pow(0.8, 4), 1e-15);  // (1 - 0.8) 0.8^4 = 0.08192
	// a fall that ends a peak needs a rise of more than the hysteresis before the next peak
	sampleFatigue(p, 0.04, g);
	sampleFatigue(p, 0.8, g);  // rises by 0.8 from the valley 0: rising again
	sampleFatigue(p, 0.7, g);  // falls by 0.1: a second peak of 0.8
	EXPECT_EQ(g.peaks, 2.0);
	EXPECT_NEAR(g.damage, 2 * 0.2 * std::pow(0.8, 4), 1e-15);
}

TEST(Fatigue, CrushRule)
{
	EXPECT_TRUE(crushesWithDamage(1.01, 0.0));   // eq. 1 unchanged for an undamaged grain
	EXPECT_FALSE(crushesWithDamage(0.99, 0.0));
	EXPECT_FALSE(crushesWithDamage(0.5, 0.5));   // s = 1 - D: not above
	EXPECT_TRUE(crushesWithDamage(0.51, 0.5));
	// rMin: a damaged grain below rMin never crushes
	const FatigueParameters below = FatigueParameters::checked(8.0, 0.5, 0.05, 0.01), all = params(8.0, 0.5, 0.05);
	GrainFatigue            g;
	g.damage = 0.9;
	const double  s = 0.5, r = 0.005;
	unsigned char crush;
	evaluateFatigue(below, 1, &s, &r, &g, &crush);
	EXPECT_EQ(crush, 0);
	EXPECT_EQ(g.extreme, 0.0);  // below rMin the state is not even sampled: no damage grows there
	evaluateFatigue(all, 1, &s, &r, &g, &crush);
	EXPECT_EQ(crush, 1);
}

TEST(Fatigue, ParametersAreCheckedOnceAgainstTheirRanges)
{
	// b in [1, 100], endurance in [0, 1), hysteresis in [0.001, 0.5], rMin >= 0 (InputCheck.hpp, the ranges
	// ballast.params declares too); the message names the argument, the value and the range.
	EXPECT_EQ(messageOf(0.5, 0.5, 0.05), "exponent: expected a number in [1, 100], got 0.5");
	EXPECT_EQ(messageOf(101, 0.5, 0.05), "exponent: expected a number in [1, 100], got 101");
	EXPECT_EQ(messageOf(NAN, 0.5, 0.05), "exponent: expected a number in [1, 100], got nan");
	EXPECT_EQ(messageOf(8.0, 1.0, 0.05), "endurance: expected a number in [0, 1), got 1");
	EXPECT_EQ(messageOf(8.0, -0.1, 0.05), "endurance: expected a number in [0, 1), got -0.1");
	EXPECT_EQ(messageOf(8.0, 0.5, 1.5), "hysteresis: expected a number in [0.001, 0.5], got 1.5");
	EXPECT_EQ(messageOf(8.0, 0.5, 0.0009), "hysteresis: expected a number in [0.001, 0.5], got 0.0009");
	EXPECT_EQ(messageOf(8.0, 0.5, 0.05, -1.0), "rMin: expected a finite number >= 0, got -1");
	EXPECT_EQ(messageOf(0.0, 2.0, 0.0, -1.0).rfind("exponent", 0), 0u);  // the first bad one
	// the ends of the closed ranges are allowed
	for (double b : {1.0, 100.0})
		for (double h : {0.001, 0.5})
			EXPECT_EQ(messageOf(b, 0.0, h), "") << b << " " << h;
}

TEST(Fatigue, BadGrainValuesNameTheGrain)
{
	const FatigueParameters p = params(8.0, 0.5, 0.05);
	GrainFatigue            g;
	unsigned char           crush;
	const double            r = 0.02, bad = -0.1, s = 0.5, r0 = 0.0;
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateFatigue(p, 1, &bad, &r, &g, &crush); }),
	          "ratio[0]: expected a finite number >= 0, got -0.1");
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateFatigue(p, 1, &s, &r0, &g, &crush); }),
	          "radii[0]: expected a finite number > 0, got 0");
	g.damage = -1;
	EXPECT_EQ(ballast_test::messageOf([&] { evaluateFatigue(p, 1, &s, &r, &g, &crush); }),
	          "state[0]: expected damage >= 0, rising 0 or 1 and peaks >= 0, got (-1, 0, 1, 0)");
}
