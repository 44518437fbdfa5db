// Argument checks shared by the core: every error names the argument, the value and what is allowed.
#pragma once
#include <stdexcept>
#include <string>

namespace ballast {

// Thrown for a bad argument; the Python binding turns it into ValueError.
class ArgumentError : public std::invalid_argument {
public:
	explicit ArgumentError(const std::string& what) : std::invalid_argument(what) {}
};

// Formats a double in the shortest %g form that reads back to the same value (1e+02 for 100).
std::string formatValue(double v);

void requireFinite(const std::string& name, double v);
void requirePositive(const std::string& name, double v);     // finite and > 0
void requireNonNegative(const std::string& name, double v);  // finite and >= 0

// The same for element index of an array named array ("radii[3]"); the name is built only on failure,
// so a check of every grain costs no string.
void requireFinite(const char* array, long index, double v);
void requirePositive(const char* array, long index, double v);

// Refuses a computed result that is not finite (an overflow, or a division by an underflowed number):
// names lists the arguments it is computed from, what says what it is ("Hertz pressure").
void requireFiniteResult(const std::string& names, const std::string& what, double v);
// The same for element index of an array result.
void requireFiniteResult(const char* names, const char* what, long index, double v);

}  // namespace ballast
