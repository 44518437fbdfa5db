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

const long kFar = 1000000;  // [cycles] a count whose growth bound never binds here

CycleJumpParameters params(long window = 4, double steady = 0.1, double maxDamage = 1.0 - 1e-9, long margin = 0,
                           double growth = 1000, double endurance = 0.5, double driftNoise = 0, double exponent = 10,
                           double driftDamage = 0)
{
	return CycleJumpParameters::checked(window, steady, maxDamage, margin, growth, endurance, driftNoise, exponent,
	                                    driftDamage);
}

// One grain's damage over a window of W cycles growing by `rate` a cycle from D0.
std::vector<double> linear(long W, double D0, double rate)
{
	std::vector<double> D;
	for (long k = 0; k <= W; ++k) D.push_back(D0 + k * rate);
	return D;
}

// W cycles of peaks, the same for every cycle: one value per grain.
std::vector<double> steadyPeaks(long W, const std::vector<double>& perGrain)
{
	std::vector<double> s;
	for (long k = 0; k < W; ++k) s.insert(s.end(), perGrain.begin(), perGrain.end());
	return s;
}

JumpPlan plan(const CycleJumpParameters& p, const std::vector<double>& damage, const std::vector<double>& peaks,
              long cycle, long remaining, std::vector<double>* rates = nullptr)
{
	const long          n = static_cast<long>(damage.size()) / (p.window + 1);
	std::vector<double> r(n);
	JumpPlan            out = planJump(p, n, damage.data(), peaks.data(), cycle, remaining, r.data());
	if (rates) *rates = r;
	return out;
}

}  // namespace

TEST(CycleJump, FailureBoundsTheJumpAtTheLastCycleTheGrainSurvives)
{
	// s_p = 0.6, b = 8: r = 0.4 0.6^8 = 0.00671846 a cycle. After a window of 4 cycles D = 4 r; the grain fails
	// in the first cycle after m more peaks with 4 r + m r > 0.4, m = floor(0.4 / r - 4) = floor(55.54) = 55
	const double r = 0.4 * std::pow(0.6, 8);
	JumpPlan     j = plan(params(), linear(4, 0, r), steadyPeaks(4, {0.6}), kFar, 100000);
	EXPECT_EQ(j.cycles, 55);
	EXPECT_EQ(j.limit, JumpLimit::failure);
	EXPECT_EQ(j.grain, 0);
	EXPECT_DOUBLE_EQ(j.maxRate, r);
	// a margin of 3 cycles leaves 3 more simulated before the failing one
	EXPECT_EQ(plan(params(4, 0.1, 1.0 - 1e-9, 3), linear(4, 0, r), steadyPeaks(4, {0.6}), kFar, 100000).cycles, 52);
	// the largest peak of the window counts: one cycle at 0.7 leaves floor((1 - 0.7 - 4 r) / r) = 40
	std::vector<double> s = steadyPeaks(4, {0.6});
	s[2]                  = 0.7;
	EXPECT_EQ(plan(params(), linear(4, 0, r), s, kFar, 100000).cycles, 40);
}

TEST(CycleJump, TheJumpedGrainCrushesInTheCycleItCrushesInWithoutTheJump)
{
	// The fatigue law itself (Fatigue.hpp), a grain peaking at 0.6 every cycle: without a jump it crushes in cycle
	// 61 (tests/cpp/test_Fatigue.cpp); with 4 cycles simulated, the jump, then cycles simulated again, in the same.
	const FatigueParameters f = FatigueParameters::checked(8, 0.5, 0.05, 0.0);
	const double            kPi = std::acos(-1.0), radius = 0.02;
	for (long margin : {0L, 1L, 5L}) {
		GrainFatigue        g;
		std::vector<double> window{0.0}, peaks;
		long                cycle = 0, crushed = 0;
		bool                jumped = false;
		while (!crushed && cycle < 200) {
			++cycle;
			double top = 0;
			for (int k = 0; k < 20 && !crushed; ++k) {
				const double  s = 0.6 * (1 - std::cos(2 * kPi * k / 20)) / 2;
				unsigned char c;
				top = std::max(top, s);
				evaluateFatigue(f, 1, &s, &radius, &g, &c);
				if (c) crushed = cycle;
			}
			window.push_back(g.damage);
			peaks.push_back(top);
			if (!jumped && window.size() == 5) {
				std::vector<double> rate;
				const JumpPlan      j = plan(params(4, 0.1, 1.0 - 1e-9, margin), window, peaks, cycle, 1000, &rate);
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
	JumpPlan j = plan(params(4, 0.1, 0.05), linear(4, 0, 0.001), steadyPeaks(4, {0.55}), kFar, 100000);
	EXPECT_EQ(j.cycles, 50);
	EXPECT_EQ(j.limit, JumpLimit::maxDamage);
	// the fastest grain bounds it: two grains, rates 0.001 and 0.004, interleaved per cycle
	std::vector<double> D;
	for (long k = 0; k <= 4; ++k) {
		D.push_back(0.001 * k);
		D.push_back(0.004 * k);
	}
	j = plan(params(4, 0.1, 0.05), D, steadyPeaks(4, {0.55, 0.55}), kFar, 100000);
	EXPECT_EQ(j.cycles, 12);  // floor(0.05 / 0.004)
	EXPECT_EQ(j.grain, 1);
}

TEST(CycleJump, AnUnsteadyRateShortensTheJump)
{
	// 0.001 a cycle in the first half, 0.002 in the second: r = 0.0015, |b - a| = 0.001; steady 0.1 of maxDamage
	// 0.05 allows 0.005 / 0.001 = 5 cycles (maxDamage alone would allow floor(0.05 / 0.0015) = 33)
	std::vector<double> D{0, 0.001, 0.002, 0.004, 0.006};
	std::vector<double> rate;
	JumpPlan            j = plan(params(4, 0.1, 0.05), D, steadyPeaks(4, {0.55}), kFar, 100000, &rate);
	EXPECT_EQ(j.cycles, 5);
	EXPECT_EQ(j.limit, JumpLimit::steady);
	EXPECT_DOUBLE_EQ(rate[0], 0.0015);
	// odd windows: halves of 2 and 3 cycles (W = 5, h = 2): 0.001 then 0.001: steady
	EXPECT_EQ(plan(params(5, 0.1, 0.05), linear(5, 0, 0.001), steadyPeaks(5, {0.55}), kFar, 100000).limit,
	          JumpLimit::maxDamage);
}

TEST(CycleJump, AGrainDriftingUpTowardsTheEnduranceRatioBoundsTheJump)
{
	// no damage; peaks 0.40, 0.40, 0.42, 0.42 (W = 4): the halves' means differ by 0.02 over 2 cycles, d = 0.01 a
	// cycle; from its largest peak 0.42 it reaches the endurance ratio 0.5 after floor(0.08 / 0.01) = 7 cycles
	// (a rounding below 8 of the doubles: 0.08 / 0.01 = 7.9999...)
	std::vector<double> s{0.40, 0.40, 0.42, 0.42};
	JumpPlan            j = plan(params(), std::vector<double>(5, 0.0), s, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_EQ(j.cycles, static_cast<long>(std::floor((0.5 - 0.42) / ((0.42 - 0.40) / 2.0))));
	EXPECT_GE(j.cycles, 7);
	EXPECT_LE(j.cycles, 8);
	// falling or flat peaks, or peaks above the endurance ratio, do not bound it
	EXPECT_EQ(plan(params(), std::vector<double>(5, 0.0), {0.42, 0.42, 0.40, 0.40}, kFar, 777).limit, JumpLimit::remaining);
}

TEST(CycleJump, PeaksThatOnlyScatterDoNotDrift)
{
	// peaks 0.38, 0.42 | 0.40, 0.44 (W = 4, h = 2): the means 0.40 and 0.42 differ by 0.02; about them the peaks
	// scatter by +-0.02, pooled variance 4 (0.02^2) / (W - 2) = 0.0008, the difference's standard error
	// sqrt(0.0008 (1/2 + 1/2)) = 0.028284. driftNoise 0: d = 0.01 a cycle, (0.5 - 0.44) / 0.01 = 6 cycles (5 or 6
	// by rounding); 0.5: d = (0.02 - 0.014142) / 2 = 0.0029289, floor(0.06 / 0.0029289) = floor(20.485) = 20;
	// 2: 0.02 lies within 2 standard errors, no drift, no bound
	const std::vector<double> noisy{0.38, 0.42, 0.40, 0.44}, none(5, 0.0);
	JumpPlan                  j = plan(params(4, 0.1, 0.05, 0, 1000, 0.5, 0), none, noisy, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_GE(j.cycles, 5);
	EXPECT_LE(j.cycles, 6);
	j = plan(params(4, 0.1, 0.05, 0, 1000, 0.5, 0.5), none, noisy, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_EQ(j.cycles, 20);
	j = plan(params(4, 0.1, 0.05, 0, 1000, 0.5, 2), none, noisy, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::remaining);
	EXPECT_EQ(j.cycles, 100000);
	// a drift well beyond the scatter still bounds it: 0.399, 0.401 | 0.419, 0.421, standard error sqrt(2e-6) =
	// 0.0014142, d = (0.02 - 2 0.0014142) / 2 = 0.0085858, floor((0.5 - 0.421) / 0.0085858) = floor(9.2012) = 9
	j = plan(params(4, 0.1, 0.05, 0, 1000, 0.5, 2), none, {0.399, 0.401, 0.419, 0.421}, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_EQ(j.cycles, 9);
	// a window of 2 has no scatter to measure: the drift counts whole
	EXPECT_EQ(plan(params(2, 0.1, 0.05, 0, 1000, 0.5, 2), std::vector<double>(3, 0.0), {0.40, 0.42}, kFar, 100000).cycles,
	          static_cast<long>(std::floor((0.5 - 0.42) / (0.02 / 1.0))));
}

// The damage a drifting grain would collect unseen, summed cycle by cycle with Fatigue.hpp's law.
double driftedDamage(double b, double e, double sMax, double d, long cycles)
{
	double D = 0;
	for (long k = 1; k <= cycles; ++k) {
		const double s = sMax + k * d;
		if (s >= e) D += (1 - s) * std::pow(s, b);
	}
	return D;
}

TEST(CycleJump, AGrainDriftingPastTheEnduranceRatioMayCollectUpToDriftDamage)
{
	// b = 1, e = 0.25, peaks 0.109375 | 0.125 (W = 2, binary fractions: exact): d = 1/64, s_k = 0.125 + k/64
	// reaches e at k = 8. The bound (1/d) [s^2/2 - s^3/3] from 0.25 to s_DN + 1/64 (top of (1 - s) s at 0.5, not
	// reached): DN = 8: 0.19132, 9: 0.38997, 10: 0.59546 (the sums 0.1875, 0.38257, 0.58472 lie below).
	const std::vector<double> none(3, 0.0), rising{0.109375, 0.125};
	auto                      p = [](double driftDamage, long margin = 0) {
                return params(2, 0.1, 0.99, margin, 1000, 0.25, 0, 1, driftDamage);
	};
	EXPECT_NEAR(driftDamageBound(p(0.5), 0.125, 1.0 / 64, 9), 0.38997395833, 1e-10);
	JumpPlan j = plan(p(0.5), none, rising, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_EQ(j.cycles, 9);
	EXPECT_EQ(j.peak, 0.125);  // the bounding grain's, as the log reports them
	EXPECT_EQ(j.drift, 1.0 / 64);
	EXPECT_LE(driftedDamage(1, 0.25, 0.125, 1.0 / 64, j.cycles), 0.5);
	// 0.1 and 0: the peak of cycle 8 is e itself and collects 0.1875: 7 cycles, all below e
	EXPECT_EQ(plan(p(0.1), none, rising, kFar, 100000).cycles, 7);
	EXPECT_EQ(plan(p(0.0), none, rising, kFar, 100000).cycles, 7);
	// a grain damaged to D = 0.75 fails where its peaks reach 1 - D = 0.25: floor(0.125 / (1/64)) - margin 1 = 7
	j = plan(p(0.5, 1), std::vector<double>(3, 0.75), rising, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::failure);
	EXPECT_EQ(j.cycles, 7);
}

TEST(CycleJump, AtALargeExponentADriftingGrainJumpsFarPastTheEnduranceRatio)
{
	// b = 30, e = 0.5, peaks 0.3671875 | 0.375 (W = 2): d = 1/128, e reached at k = 16. The bound of the damage
	// collected (1/d) [s^31/31 - s^32/32] from 0.5 to s_DN + 1/128: DN = 53 (s 0.789): 8.2591e-4; 54: 1.0805e-3.
	// driftDamage 1e-3 allows 53 cycles; 0 allows 15 (the 16th peak is e itself and collects 4.66e-10). The sum of the
	// law over the 53 is 7.1887e-4.
	const CycleJumpParameters p = params(2, 0.1, 0.99, 0, 1000, 0.5, 0, 30, 1e-3);
	EXPECT_NEAR(driftDamageBound(p, 0.375, 1.0 / 128, 53), 8.259066221e-4, 1e-12);
	EXPECT_NEAR(driftDamageBound(p, 0.375, 1.0 / 128, 54), 1.080489589e-3, 1e-12);
	const JumpPlan j = plan(p, std::vector<double>(3, 0.0), {0.3671875, 0.375}, kFar, 100000);
	EXPECT_EQ(j.limit, JumpLimit::endurance);
	EXPECT_EQ(j.cycles, 53);
	EXPECT_NEAR(driftedDamage(30, 0.5, 0.375, 1.0 / 128, 53), 7.188670144e-4, 1e-12);
	EXPECT_EQ(plan(params(2, 0.1, 0.99, 0, 1000, 0.5, 0, 30, 0), std::vector<double>(3, 0.0), {0.3671875, 0.375}, kFar,
	               100000)
	                  .cycles,
	          15);
}

TEST(CycleJump, TheCountGrowsByAtMostTheGrowthFactor)
{
	// no damage, cycle 30, growth 1: at most 30 more (the count at most doubles); growth 0.5: 15
	EXPECT_EQ(plan(params(4, 0.1, 0.05, 0, 1.0), std::vector<double>(5, 0.0), steadyPeaks(4, {0.1}), 30, 1000).cycles, 30);
	const JumpPlan j = plan(params(4, 0.1, 0.05, 0, 0.5), std::vector<double>(5, 0.0), steadyPeaks(4, {0.1}), 30, 1000);
	EXPECT_EQ(j.cycles, 15);
	EXPECT_EQ(j.limit, JumpLimit::growth);
	EXPECT_EQ(j.grain, -1);
}

TEST(CycleJump, NoDamageJumpsToTheEndOfTheRun)
{
	JumpPlan j = plan(params(), std::vector<double>(10, 0.0), steadyPeaks(4, {0.0, 0.3}), kFar, 777);
	EXPECT_EQ(j.cycles, 777);
	EXPECT_EQ(j.limit, JumpLimit::remaining);
	EXPECT_EQ(j.grain, -1);
	EXPECT_EQ(j.maxRate, 0.0);
	// and a tiny rate does not overflow the count
	EXPECT_EQ(plan(params(), linear(4, 0, 1e-300), steadyPeaks(4, {0.6}), 1000000000000L, 123456789).cycles, 123456789);
}

TEST(CycleJump, AGrainAlreadyPastItsFailureAllowsNoJump)
{
	// D = 0.45 > 1 - 0.6: it crushes at its next peak of 0.6
	JumpPlan j = plan(params(), linear(4, 0.41, 0.01), steadyPeaks(4, {0.6}), kFar, 1000);
	EXPECT_EQ(j.cycles, 0);
	EXPECT_EQ(j.limit, JumpLimit::failure);
}

TEST(CycleJump, BadInputIsRefusedNamingIt)
{
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(1, 0.1, 0.05, 0, 1, 0.5, 2, 10, 0.001); }),
	          "window: expected an integer in [2, 10000], got 1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4.5, 0.1, 0.05, 0, 1, 0.5, 2, 10, 0.001); }),
	          "window: expected an integer in [2, 10000], got 4.5");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0, 0.05, 0, 1, 0.5, 2, 10, 0.001); }), "steady: expected a number in (0, 1], got 0");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 1, 0, 1, 0.5, 2, 10, 0.001); }),
	          "maxDamage: expected a number in (0, 1), got 1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, -1, 1, 0.5, 2, 10, 0.001); }),
	          "margin: expected an integer in [0, 10000], got -1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, 0, 0, 0.5, 2, 10, 0.001); }),
	          "growth: expected a number in (0, 1000], got 0");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, 0, 1, 1, 2, 10, 0.001); }),
	          "endurance: expected a number in [0, 1), got 1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, 0, 1, 0.5, -1, 10, 0.001); }),
	          "driftNoise: expected a number in [0, 100], got -1");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, 0, 1, 0.5, 2, 0.5, 0.001); }),
	          "exponent: expected a number in [1, 100], got 0.5");
	EXPECT_EQ(messageOf([] { CycleJumpParameters::checked(4, 0.1, 0.05, 0, 1, 0.5, 2, 10, 1); }),
	          "driftDamage: expected a number in [0, 1), got 1");
	const std::vector<double> falling{0, 0.01, 0.02, 0.005, 0.03};
	EXPECT_EQ(messageOf([&] { plan(params(), falling, steadyPeaks(4, {0.6}), kFar, 10); })
	                  .rfind("damage: grain 0's damage falls from 0.02 to 0.005", 0),
	          0u);
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), steadyPeaks(4, {0.0}), kFar, 10); }),
	          "peaks: grain 0's damage grew in the window, but its peaks are 0");
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), steadyPeaks(4, {NAN}), kFar, 10); }).rfind("peaks[0]: ", 0),
	          0u);
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), steadyPeaks(4, {0.6}), kFar, -1); }),
	          "remaining: expected >= 0 cycles, got -1");
	EXPECT_EQ(messageOf([&] { plan(params(), linear(4, 0, 0.01), steadyPeaks(4, {0.6}), 0, 5); }), "cycle: expected >= 1, got 0");
}
