#include "InputCheck.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

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

}  // namespace ballast
