// Tests of cycle jumping (CycleJump.hpp): each bound of a jump against values worked out by hand in the comments,
// the jump checked against the fatigue law itself (the grain crushes in the cycle it crushes in without the jump),
// and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ArgumentMessage.hpp"
#include "CycleJump.hpp"
#include "Fatigue.hpp"

using namespace ballast;
using ballast_test::messageOf;

namespace {

CycleJumpParameters params(long window = 4, double steady = 0.1, double maxDamage = 1.0 - 1e-9, long margin = 0)
{
	return CycleJumpParameters::checked(window, steady, maxDamage, margin);
}

// One grain's damage over a window of W cycles growing by `rate` a cycle from D0.
std::vector<double> linear(long W, double D0, double rate)
{
	std::vector<double> D;
	for (long k = 0; k <= W; ++k) D.push_back(D0 + k * rate);
	return D;
}

JumpPlan plan(const CycleJumpParameters& p, const std::vector<double>& damage, const std::vector<double>& peak,
              long remaining, std::vector<double>* rates = nullptr)
{
	std::vector<double> r(peak.size());
	JumpPlan            out = planJump(p, static_cast<long>(peak.size()), damage.data(), peak.data(), remaining, r.data());
	if (rates) *rates = r;
	return out;
}

}  // namespace

TEST(CycleJump, FailureBoundsTheJumpAtTheLastCycleTheGrainSurvives)
{
	// s_p = 0.6, b = 8: r = 0.4 0.6^8 = 0.00671846 a cycle. After a window of 4 cycles D = 4 r; the grain fails
	// in the first cycle after m more peaks with 4 r + m r > 0.4, m = floor(0.4 / r - 4) = floor(55.54) = 55
	const double r = 0.4 * std::pow(0.6, 8);
	JumpPlan     j = plan(params(), linear(4, 0, r), {0.6}, 100000);
	EXPECT_EQ(j.cycles, 55);
	EXPECT_EQ(j.limit, JumpLimit::failure);
	EXPECT_EQ(j.grain, 0);
	EXPECT_DOUBLE_EQ(j.maxRate, r);
	// a margin of 3 cycles leaves 3 more simulated before the failing one
	EXPECT_EQ(plan(params(4, 0.1, 1.0 - 1e-9, 3), linear(4, 0, r), {0.6}, 100000).cycles, 52);
}

TEST(CycleJump, TheJumpedGrainCrushesInTheCycleItCrushesInWithoutTheJump)
{
	// The fatigue law itself (Fatigue.hpp), a grain peaking at 0.6 every cycle: without a jump it crushes in cycle
	// 61 (tests/cpp/test_Fatigue.cpp); with 4 cycles simulated, the jump, then cycles simulated again, in the same.
	const FatigueParameters f = FatigueParameters::checked(8, 0.5, 0.05, 0.0);
	const double            kPi = std::acos(-1.0), radius = 0.02;
	for (long margin : {0L, 1L, 5L}) {
		GrainFatigue        g;
		std::vector<double> window{0.0};
		long                cycle = 0, crushed = 0;
		bool                jumped = false;
		while (!crushed && cycle < 200) {
			++cycle;
			for (int k = 0; k < 20 && !crushed; ++k) {
				const double  s = 0.6 * (1 - std::cos(2 * kPi * k / 20)) / 2;
				unsigned char c;
				evaluateFatigue(f, 1, &s, &radius, &g, &c);
				if (c) crushed = cycle;
			}
			window.push_back(g.damage);
			if (!jumped && window.size() == 5) {
				std::vector<double> rate;
				const JumpPlan      j = plan(params(4, 0.1, 1.0 - 1e-9, margin), window, {0.6}, 1000, &rate);
				g.damage += j.cycles * rate[0];
				cycle += j.cycles;
				jumped = true;
				EXPECT_GT(j.cycles, 40);
			}
		}
		EXPECT_EQ(crushed, 61) << "margin " << margin;
	}
}

TEST(CycleJump, NoGrainsDamageMovesByMoreThanMaxDamage)
{
	// r = 0.001 a cycle far from failure (s_p 0.55): maxDamage 0.05 allows 50 cycles
	JumpPlan j = plan(params(4, 0.1, 0.05), linear(4, 0, 0.001), {0.55}, 100000);
	EXPECT_EQ(j.cycles, 50);
	EXPECT_EQ(j.limit, JumpLimit::maxDamage);
	// the fastest grain bounds it: two grains, rates 0.001 and 0.004, interleaved per cycle
	std::vector<double> D;
	for (long k = 0; k <= 4; ++k) {
		D.push_back(0.001 * k);
		D.push_back(0.004 * k);
	}
	j = plan(params(4, 0.1, 0.05), D, {0.55, 0.55}, 100000);
	EXPECT_EQ(j.cycles, 12);  // floor(0.05 / 0.004)
	EXPECT_EQ(j.grain, 1);
}

TEST(CycleJump, AnUnsteadyRateShortensTheJump)
{
	// 0.001 a cycle in the first half, 0.002 in the second: r = 0.0015, |b - a| = 0.001; steady 0.1 of maxDamage
	// 0.05 allows 0.005 / 0.001 = 5 cycles (maxDamage alone would allow floor(0.05 / 0.0015) = 33)
	std::vector<double> D{0, 0.001, 0.002, 0.004, 0.006};
	std::vector<double> rate;
	JumpPlan            j = plan(params(4, 0.1, 0.05), D, {0.55}, 100000, &rate);
	EXPECT_EQ(j.cycles, 5);
	EXPECT_EQ(j.limit, JumpLimit::steady);
	EXPECT_DOUBLE_EQ(rate[0], 0.0015);
	// odd windows: halves of 2 and 3 cycles (W = 5, h = 2): 0.001 then 0.001: steady
	EXPECT_EQ(plan(params(5, 0.1, 0.05), linear(5, 0, 0.001), {0.55}, 100000).limit, JumpLimit::maxDamage);
}

TEST(CycleJump, NoDamageJumpsToTheEndOfTheRun)
{
	JumpPlan j = plan(params(), std::vector<double>(10, 0.0), {0.0, 0.3}, 777);
	EXPECT_EQ(j.cycles, 777);
	EXPECT_EQ(j.limit, JumpLimit::remaining);
	EXPECT_EQ(j.grain, -1);
	EXPECT_EQ(j.maxRate, 0.0);
	// and a tiny rate does not overflow the count
	EXPECT_EQ(plan(params(), linear(4, 0, 1e-300), {0.6}, 123456789).cycles, 123456789);
}

TEST(CycleJump, AGrainAlreadyPastItsFailureAllowsNoJump)
{
	// D = 0.45 > 1 - 0.6: it crushes at its next peak of 0.6
	JumpPlan j = plan(params(), linear(4, 0.41, 0.01), {0.6}, 1000);
	EXPECT_EQ(j.cycles, 0);
	EXPECT_EQ(j.limit, JumpLimit::failure);
}

TEST(CycleJump, BadInputIsRefusedNamingIt)
{
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(1, 0.1, 0.05, 0); }), "window: expected an integer in [2, 10000], got 1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4.5, 0.1, 0.05, 0); }),
	          "window: expected an integer in [2, 10000], got 4.5");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0, 0.05, 0); }), "steady: expected a number in (0, 1], got 0");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 1, 0); }), "maxDamage: expected a number in (0, 1), got 1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, -1); }),
	          "margin: expected an integer in [0, 10000], got -1");
	const std::vector<double> falling{0, 0.01, 0.02, 0.005, 0.03};
	EXPECT_EQ(messageOf([&] { plan(params(), falling, {0.6}, 10); }).rfind("damage: grain 0's damage falls from 0.02 to 0.005", 0),
	          0u);
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), {0.0}, 10); }),
	          "peak[0]: a grain whose damage grew has a damaging peak > 0, got 0");
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), {NAN}, 10); }).rfind("peak[0]: ", 0), 0u);
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), {0.6}, -1); }), "remaining: expected >= 0 cycles, got -1");
}
