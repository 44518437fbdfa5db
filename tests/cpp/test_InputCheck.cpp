// Tests of InputCheck: Python-like shortest round-trip formatting and error messages naming the argument.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "ArgumentMessage.hpp"
#include "InputCheck.hpp"

using namespace ballast;

namespace {

using ballast_test::messageOf;

}  // namespace

TEST(InputCheck, FormatValueShortest)
{
	// 0.1 is not exactly representable: the shortest string that reads back is "0.1", as Python prints it.
	EXPECT_EQ(formatValue(0.1), "0.1");
	EXPECT_EQ(formatValue(1e-300), "1e-300");
	EXPECT_EQ(formatValue(-2.5), "-2.5");
	EXPECT_EQ(formatValue(0.0), "0");
	EXPECT_EQ(formatValue(1e16), "1e+16");
	EXPECT_EQ(formatValue(std::numeric_limits<double>::infinity()), "inf");
	EXPECT_EQ(formatValue(-std::numeric_limits<double>::infinity()), "-inf");
	EXPECT_EQ(formatValue(std::numeric_limits<double>::quiet_NaN()), "nan");
	EXPECT_EQ(formatValue(-std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(InputCheck, FormatValueRoundTrips)
{
	// Exact round trip (the value read back is the same double) for awkward values and random ones.
	const double fixed[] = {0.1, 1.0 / 3.0, 1e-300, 5e-324, 1.7976931348623157e308, 2.0 / 3.0 * 1e-7, -123456.789};
	for (double v : fixed)
		EXPECT_EQ(std::strtod(formatValue(v).c_str(), nullptr), v) << formatValue(v);
	std::mt19937_64                        gen(12345);
	std::uniform_real_distribution<double> mant(-1.0, 1.0);
	std::uniform_int_distribution<int>     ex(-300, 300);
	for (int i = 0; i < 2000; ++i) {
		const double v = std::ldexp(mant(gen), ex(gen));
		const std::string s = formatValue(v);
		EXPECT_EQ(std::strtod(s.c_str(), nullptr), v) << s;
		// at most 17 significant digits: sign, digits, point and a 3-digit exponent fit in 24 characters
		EXPECT_LE(s.size(), 24u) << s;
	}
	EXPECT_EQ(formatValue(0.25), "0.25");
}

TEST(InputCheck, MessagesNameArgumentAndValue)
{
	const std::string m1 = messageOf([] { requirePositive("ft0", -2.5); });
	EXPECT_NE(m1.find("ft0"), std::string::npos) << m1;
	EXPECT_NE(m1.find("-2.5"), std::string::npos) << m1;
	EXPECT_NE(m1.find("> 0"), std::string::npos) << m1;

	const std::string m2 = messageOf([] { requireNonNegative("rMin", -0.1); });
	EXPECT_NE(m2.find("rMin"), std::string::npos) << m2;
	EXPECT_NE(m2.find("-0.1"), std::string::npos) << m2;
	EXPECT_NE(m2.find(">= 0"), std::string::npos) << m2;

	const std::string m3 = messageOf([] { requireFinite("Fn", std::numeric_limits<double>::quiet_NaN()); });
	EXPECT_NE(m3.find("Fn"), std::string::npos) << m3;
	EXPECT_NE(m3.find("nan"), std::string::npos) << m3;

	const std::string m4 = messageOf([] { requirePositive("radius", std::numeric_limits<double>::infinity()); });
	EXPECT_NE(m4.find("radius"), std::string::npos) << m4;
	EXPECT_NE(m4.find("inf"), std::string::npos) << m4;
}

TEST(InputCheck, NonFiniteResultNamesTheArgumentsAndTheResult)
{
	EXPECT_NO_THROW(requireFiniteResult("Fn, uN", "Hertz pressure", 1.7e308));
	EXPECT_NO_THROW(requireFiniteResult("Fn, uN", "Hertz pressure", 2, -1.7e308));
	const double inf = std::numeric_limits<double>::infinity();
	EXPECT_EQ(messageOf([&] { requireFiniteResult("Fn, uN", "Hertz pressure", inf); }),
	          "Fn, uN: expected values whose Hertz pressure is finite, the result would be inf");
	EXPECT_EQ(messageOf([] { requireFiniteResult("sigma", "von Mises stress", 7, std::nan("")); }),
	          "sigma: expected values whose von Mises stress is finite, the result would be nan at index 7");
	EXPECT_EQ(messageOf([&] { requireFiniteResult("ft0, radius", "strength", 0, -inf); }).rfind("ft0, radius: ", 0), 0u);
}

TEST(InputCheck, AcceptsAndRejectsBoundaries)
{
	// > 0 rejects 0, >= 0 accepts it; finite accepts any finite value including negatives.
	EXPECT_THROW(requirePositive("x", 0.0), ArgumentError);
	EXPECT_NO_THROW(requirePositive("x", 5e-324));
	EXPECT_NO_THROW(requireNonNegative("x", 0.0));
	EXPECT_THROW(requireNonNegative("x", -5e-324), ArgumentError);
	EXPECT_NO_THROW(requireFinite("x", -1e308));
	EXPECT_THROW(requireFinite("x", -std::numeric_limits<double>::infinity()), ArgumentError);
	EXPECT_THROW(requireNonNegative("x", std::numeric_limits<double>::quiet_NaN()), ArgumentError);
	// ArgumentError is an invalid_argument, so generic handlers catch it
	EXPECT_THROW(requirePositive("x", -1.0), std::invalid_argument);
}

// ---------------------------------------------------------------- the parameters' ranges
namespace {

std::string plain(double v)  // 100 as "100" (formatValue gives the shortest form, "1e+02")
{
	std::ostringstream s;
	s << v;
	return s.str();
}

// The words of a range as contains() reads its bounds: "a number in [lo, hi]" with the brackets of its
// ends, "a finite number > lo" (>= for a closed end) for an unbounded one, "0 or ..." when 0 is allowed.
std::string wordsFromBounds(const ParameterRange& r)
{
	const std::string zero = r.zeroAllowed ? "0 or " : "";
	if (std::isinf(r.upper)) return zero + "a finite number " + (r.lowerClosed ? ">= " : "> ") + plain(r.lower);
	return zero + (r.integer ? "an integer in " : "a number in ") + (r.lowerClosed ? "[" : "(") + plain(r.lower) + ", "
	       + plain(r.upper) + (r.upperClosed ? "]" : ")");
}

}  // namespace

TEST(InputCheck, EveryRangeIsListedOnceByItsName)
{
	const char* expected[] = {"ft0", "m", "rMin", "seed", "weibullModulus", "fatigueExponent", "fatigueEndurance",
	                          "fatigueHysteresis", "strength", "jumpWindow", "jumpSteady", "jumpMaxDamage", "jumpMargin",
	                          "jumpGrowth", "jumpDriftNoise", "jumpDriftDamage"};
	ASSERT_EQ(parameterRanges().size(), sizeof expected / sizeof *expected);
	for (size_t i = 0; i < parameterRanges().size(); ++i)
		EXPECT_EQ(std::string(parameterRanges()[i]->name), expected[i]);
	EXPECT_EQ(parameterRanges()[1], &ranges::m);
}

TEST(InputCheck, RangeWordsSayTheBounds)
{
	// The words are typed once, for Python's users (docs/parameters.md); they must say the bounds. The seed
	// reads [0, 2^63 - 1] for its open end at 2^63 (9.2233720368547758e+18).
	for (const ParameterRange* r : parameterRanges()) {
		if (r == &ranges::seed) continue;
		EXPECT_EQ(r->words, wordsFromBounds(*r)) << r->name;
	}
	EXPECT_EQ(std::string(ranges::seed.words), "an integer in [0, 2^63 - 1]");
	EXPECT_EQ(ranges::seed.upper, std::ldexp(1.0, 63));
	EXPECT_FALSE(ranges::seed.upperClosed);
}

TEST(InputCheck, RangesContainTheirEndsAsDeclared)
{
	const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
	for (const ParameterRange* r : parameterRanges()) {
		if (std::isfinite(r->lower)) {
			EXPECT_EQ(r->contains(r->lower), r->lowerClosed || (r->zeroAllowed && r->lower == 0)) << r->name;
			EXPECT_FALSE(r->contains(std::nextafter(r->lower, -inf)) && !(r->zeroAllowed && r->lower == 0)) << r->name;
		}
		if (std::isfinite(r->upper)) {
			EXPECT_EQ(r->contains(r->upper), r->upperClosed) << r->name;
			EXPECT_FALSE(r->contains(r->integer ? r->upper + 2048 : std::nextafter(r->upper, inf))) << r->name;
		}
		EXPECT_FALSE(r->contains(nan)) << r->name;
		EXPECT_FALSE(r->contains(inf)) << r->name;
		EXPECT_FALSE(r->contains(-inf)) << r->name;
	}
	// 0 switches the Weibull scatter off; between 0 and 1 the modulus is refused
	EXPECT_TRUE(ranges::weibullModulus.contains(0.0));
	EXPECT_FALSE(ranges::weibullModulus.contains(0.5));
	EXPECT_TRUE(ranges::weibullModulus.contains(1.0));
	EXPECT_FALSE(ranges::ft0.contains(0.0));
	EXPECT_TRUE(ranges::ft0.contains(5e-324));
	EXPECT_TRUE(ranges::rMin.contains(0.0));
	EXPECT_TRUE(ranges::fatigueEndurance.contains(std::nextafter(1.0, 0.0)));
	EXPECT_FALSE(ranges::seed.contains(0.5));  // integers only
}

TEST(InputCheck, IntegerRangesAreExact)
{
	// 2^63 - 1 is no double (it rounds to 2^63): the integer check compares integers.
	const std::uint64_t top = (std::uint64_t(1) << 63) - 1;
	EXPECT_TRUE(ranges::seed.contains(std::uint64_t(0)));
	EXPECT_TRUE(ranges::seed.contains(top));
	EXPECT_FALSE(ranges::seed.contains(top + 1));
	EXPECT_FALSE(ranges::seed.contains(std::numeric_limits<std::uint64_t>::max()));
	EXPECT_EQ(requireInRange(ranges::seed, "seed", top), top);
	EXPECT_EQ(messageOf([&] { requireInRange(ranges::seed, "seed", top + 1); }),
	          "seed: expected an integer in [0, 2^63 - 1], got 9223372036854775808");
}

TEST(InputCheck, RangeErrorsNameTheArgumentTheValueAndTheRange)
{
	// The argument is the caller's name for the value (the binding's "exponent" is fatigueExponent).
	EXPECT_EQ(requireInRange(ranges::m, "m", 3.0), 3.0);
	EXPECT_EQ(messageOf([] { requireInRange(ranges::m, "m", 3.5); }), "m: expected a number in [0, 3], got 3.5");
	EXPECT_EQ(messageOf([] { requireInRange(ranges::fatigueExponent, "exponent", 0.5); }),
	          "exponent: expected a number in [1, 100], got 0.5");
	EXPECT_EQ(messageOf([] { requireInRange(ranges::weibullModulus, "modulus", -2.0); }),
	          "modulus: expected 0 or a number in [1, 50], got -2");
	EXPECT_EQ(messageOf([] { requireInRange(ranges::fatigueHysteresis, "hysteresis", std::nan("")); }),
	          "hysteresis: expected a number in [0.001, 0.5], got nan");
	EXPECT_EQ(messageOf([] { requireInRange(ranges::ft0, "ft0", -std::numeric_limits<double>::infinity()); }),
	          "ft0: expected a finite number > 0, got -inf");
}
