// Tests of the Weibull strength factors (Weibull.hpp): the distribution (Kolmogorov-Smirnov against
// P_f = 1 - exp(-w^k)), reproducibility and independence of the draw order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "Weibull.hpp"

using namespace ballast;

namespace {

// Kolmogorov-Smirnov statistic of the sample against F(w) = 1 - exp(-w^k).
double ksStatistic(std::vector<double> w, double k)
{
	std::sort(w.begin(), w.end());
	const double n = w.size();
	double       d = 0;
	for (size_t i = 0; i < w.size(); ++i) {
		const double F = 1 - std::exp(-std::pow(w[i], k));
		d              = std::max({d, (i + 1) / n - F, F - i / n});
	}
	return d;
}

}  // namespace

TEST(Weibull, FactorsFollowTheWeibullLaw)
{
	// 20 000 keys: at the 1 % level the KS statistic stays below 1.628 / sqrt(n) = 0.0115.
	for (double k : {3.0, 10.0}) {
		std::vector<double> w;
		for (std::uint64_t key = 0; key < 20000; ++key)
			w.push_back(weibullFactor(7, key, k));
		EXPECT_LT(ksStatistic(w, k), 1.628 / std::sqrt(20000.0)) << k;
		// the characteristic value: a fraction 1 - 1/e = 0.632 of the factors is below 1
		const double below = std::count_if(w.begin(), w.end(), [](double v) { return v < 1; }) / 20000.0;
		EXPECT_NEAR(below, 1 - std::exp(-1.0), 0.01) << k;
		// and a wrong modulus is rejected by the same test
		EXPECT_GT(ksStatistic(w, 1.5 * k), 1.628 / std::sqrt(20000.0)) << k;
	}
}

TEST(Weibull, ReproducibleAndIndependentOfOrder)
{
	const std::uint64_t keys[3] = {5, 17, 3};
	double              a[3], b[3];
	weibullFactors(11, 3, keys, 3.0, a);
	for (int i = 2; i >= 0; --i)
		b[i] = weibullFactor(11, keys[i], 3.0);
	for (int i = 0; i < 3; ++i)
		EXPECT_EQ(a[i], b[i]);
	EXPECT_NE(weibullFactor(11, 5, 3.0), weibullFactor(12, 5, 3.0));  // another seed, another strength
	EXPECT_EQ(weibullFactor(11, 5, 0.0), 1.0);                        // k = 0: no scatter
}

TEST(Weibull, ModulusAtTheEndsOfItsRange)
{
	// k = 1: w = -ln U is exponential, its median ln 2; k = 50: w = (-ln U)^(1/50) stays within a few
	// per cent of 1 for all but the extreme draws (U in [1e-6, 1 - 1e-6] gives w in [0.76, 1.05]).
	// The modulus itself is checked once, by the binding (InputCheck.hpp: weibullModulus).
	std::vector<double> w1, w50;
	for (std::uint64_t key = 0; key < 20001; ++key) {
		w1.push_back(weibullFactor(3, key, 1.0));
		w50.push_back(weibullFactor(3, key, 50.0));
	}
	std::nth_element(w1.begin(), w1.begin() + 10000, w1.end());
	EXPECT_NEAR(w1[10000], std::log(2.0), 0.02);
	for (double v : w50) {
		EXPECT_GT(v, 0.7);
		EXPECT_LT(v, 1.06);
	}
}
