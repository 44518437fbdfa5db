#include "InputCheck.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace ballast {

std::string formatValue(double v)
{
	if (std::isnan(v)) return "nan";  // printf may write -nan, Python never does
	char buf[40];
	std::snprintf(buf, sizeof buf, "%.17g", v);
	// shortest representation that reads back to the same double
	for (int prec = 1; prec <= 17; ++prec) {
		char b[40];
		std::snprintf(b, sizeof b, "%.*g", prec, v);
		if (std::strtod(b, nullptr) == v) return b;
	}
	return buf;
}

void requireFinite(const std::string& name, double v)
{
	if (!std::isfinite(v)) throw ArgumentError(name + ": expected a finite number, got " + formatValue(v));
}

void requirePositive(const std::string& name, double v)
{
	if (!std::isfinite(v) || v <= 0) throw ArgumentError(name + ": expected a finite number > 0, got " + formatValue(v));
}

void requireNonNegative(const std::string& name, double v)
{
	if (!std::isfinite(v) || v < 0) throw ArgumentError(name + ": expected a finite number >= 0, got " + formatValue(v));
}

static std::string element(const char* array, long index)
{
	return std::string(array) + "[" + std::to_string(index) + "]";
}

void requireFinite(const char* array, long index, double v)
{
	if (!std::isfinite(v)) requireFinite(element(array, index), v);
}

void requirePositive(const char* array, long index, double v)
{
	if (!std::isfinite(v) || v <= 0) requirePositive(element(array, index), v);
}

void requireNonNegative(const char* array, long index, double v)
{
	if (!std::isfinite(v) || v < 0) requireNonNegative(element(array, index), v);
}

void requireFiniteResult(const std::string& names, const std::string& what, double v)
{
	if (!std::isfinite(v))
		throw ArgumentError(names + ": expected values whose " + what + " is finite, the result would be " + formatValue(v));
}

void requireFiniteResult(const char* names, const char* what, long index, double v)
{
	if (!std::isfinite(v))
		throw ArgumentError(std::string(names) + ": expected values whose " + what + " is finite, the result would be "
		                    + formatValue(v) + " at index " + std::to_string(index));
}

// ---------------------------------------------------------------- the parameters' ranges
namespace {
	const double kInf = std::numeric_limits<double>::infinity();
}

namespace ranges {
	// Where C++ and Python disagreed before issue 23, the Python range (what users were told) was kept.
	const ParameterRange ft0{"ft0", 0, kInf, false, false, false, false, "a finite number > 0"};
	// eq. 4 with m is the size effect of a Weibull modulus 3 / m (Strength.hpp): m = 3 is modulus 1, the
	// widest scatter weibullModulus allows
	const ParameterRange m{"m", 0, 3, true, true, false, false, "a number in [0, 3]"};
	const ParameterRange rMin{"rMin", 0, kInf, true, false, false, false, "a finite number >= 0"};
	// the int64 range ballast.params declared; the generator itself (Random.hpp) would take any 64-bit seed
	const ParameterRange seed{"seed", 0, 0x1p63, true, false, true, false, "an integer in [0, 2^63 - 1]"};
	// below 1 the scatter spans orders of magnitude (w = (-ln U)^(1/k)); 0 switches it off
	const ParameterRange weibullModulus{"weibullModulus", 1, 50, true, true, false, true, "0 or a number in [1, 50]"};
	const ParameterRange fatigueExponent{"fatigueExponent", 1, 100, true, true, false, false, "a number in [1, 100]"};
	const ParameterRange fatigueEndurance{"fatigueEndurance", 0, 1, true, false, false, false, "a number in [0, 1)"};
	// smaller falls count noise as load cycles, larger ones miss the peaks of s <= 1
	const ParameterRange fatigueHysteresis{"fatigueHysteresis", 0.001, 0.5, true, true, false, false,
	                                       "a number in [0.001, 0.5]"};
	const ParameterRange strength{"strength", 0, kInf, false, false, false, false, "a finite number > 0"};
	// cycle jumping (CycleJump.hpp): two halves of at least one cycle each; a jump may move damage by less than 1
	const ParameterRange jumpWindow{"jumpWindow", 2, 10000, true, true, true, false, "an integer in [2, 10000]"};
	const ParameterRange jumpSteady{"jumpSteady", 0, 1, false, true, false, false, "a number in (0, 1]"};
	const ParameterRange jumpMaxDamage{"jumpMaxDamage", 0, 1, false, false, false, false, "a number in (0, 1)"};
	const ParameterRange jumpMargin{"jumpMargin", 0, 10000, true, true, true, false, "an integer in [0, 10000]"};
	const ParameterRange jumpGrowth{"jumpGrowth", 0, 1000, false, true, false, false, "a number in (0, 1000]"};
	const ParameterRange jumpDriftNoise{"jumpDriftNoise", 0, 100, true, true, false, false, "a number in [0, 100]"};
	const ParameterRange jumpDriftDamage{"jumpDriftDamage", 0, 1, true, false, false, false, "a number in [0, 1)"};
}  // namespace ranges

const std::vector<const ParameterRange*>& parameterRanges()
{
	static const std::vector<const ParameterRange*> all = {
	        &ranges::ft0,  &ranges::m, &ranges::rMin, &ranges::seed, &ranges::weibullModulus, &ranges::fatigueExponent,
	        &ranges::fatigueEndurance, &ranges::fatigueHysteresis, &ranges::strength, &ranges::jumpWindow, &ranges::jumpSteady,
	        &ranges::jumpMaxDamage, &ranges::jumpMargin, &ranges::jumpGrowth, &ranges::jumpDriftNoise,
	        &ranges::jumpDriftDamage};
	return all;
}

bool ParameterRange::contains(double v) const
{
	if (zeroAllowed && v == 0) return true;
	const bool aboveLower = lowerClosed ? v >= lower : v > lower;
	const bool belowUpper = upperClosed ? v <= upper : v < upper;
	return aboveLower && belowUpper && std::isfinite(v) && (!integer || v == std::floor(v));
}

bool ParameterRange::contains(std::uint64_t v) const
{
	assert(integer && lower >= 0 && upper < 0x1p64 && lower == std::floor(lower) && upper == std::floor(upper));
	if (zeroAllowed && v == 0) return true;
	// the bounds are whole numbers below 2^64: compared as integers, exactly (2^63 - 1 is no double)
	const std::uint64_t lo = static_cast<std::uint64_t>(lower), hi = static_cast<std::uint64_t>(upper);
	return (lowerClosed ? v >= lo : v > lo) && (upperClosed ? v <= hi : v < hi);
}

double requireInRange(const ParameterRange& range, const std::string& argument, double v)
{
	if (!range.contains(v)) throw ArgumentError(argument + ": expected " + range.words + ", got " + formatValue(v));
	return v;
}

std::uint64_t requireInRange(const ParameterRange& range, const std::string& argument, std::uint64_t v)
{
	if (!range.contains(v)) throw ArgumentError(argument + ": expected " + range.words + ", got " + std::to_string(v));
	return v;
}

}  // namespace ballast
