// Tests of InputCheck: Python-like shortest round-trip formatting and error messages naming the argument.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
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
