// Argument checks shared by the core: every error names the argument, the value and what is allowed.
// Below them, the allowed range of every parameter the engines pass to the core, declared once (issue 23):
// the core checks its parameters against it once, where they enter (the parameter structs' `checked`), and
// the binding exports it as ballast._ballast.parameterRanges(), from which ballast.params builds the Python
// checks and the words of docs/parameters.md.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

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
void requireNonNegative(const char* array, long index, double v);

// Refuses a computed result that is not finite (an overflow, or a division by an underflowed number):
// names lists the arguments it is computed from, what says what it is ("Hertz pressure").
void requireFiniteResult(const std::string& names, const std::string& what, double v);
// The same for element index of an array result.
void requireFiniteResult(const char* names, const char* what, long index, double v);

// ---------------------------------------------------------------- the parameters' ranges
struct ParameterRange {
	const char* name;                // the engine parameter, as ballast.params declares it ("fatigueExponent")
	double      lower, upper;        // the interval; upper may be infinite (then only finite values are in it)
	bool        lowerClosed, upperClosed;
	bool        integer;             // only whole numbers (the bounds are then whole numbers in [0, 2^64))
	bool        zeroAllowed;         // 0 ("switched off") is allowed besides the interval
	const char* words;               // the range in words, as every error and docs/parameters.md give it

	bool contains(double v) const;         // NaN is in no range
	bool contains(std::uint64_t v) const;  // exact, for integer ranges
};

namespace ranges {
	extern const ParameterRange ft0;                // eq. 4 [Pa m^m]
	extern const ParameterRange m;                  // eq. 4's size exponent [-]
	extern const ParameterRange rMin;               // smallest radius that crushes or abrades [m]
	extern const ParameterRange seed;               // fragment orientations and Weibull strengths [-]
	extern const ParameterRange weibullModulus;     // Weibull.hpp [-]
	extern const ParameterRange fatigueExponent;    // Basquin's b, Fatigue.hpp [-]
	extern const ParameterRange fatigueEndurance;   // [-]
	extern const ParameterRange fatigueHysteresis;  // [-]
	extern const ParameterRange strength;           // abrasion, eq. 6 [Pa]
	extern const ParameterRange jumpWindow;         // CycleJump.hpp [cycles]
	extern const ParameterRange jumpSteady;         // [-]
	extern const ParameterRange jumpMaxDamage;      // [-]
	extern const ParameterRange jumpMargin;         // [cycles]
	extern const ParameterRange jumpGrowth;         // [-]
	extern const ParameterRange jumpDriftNoise;     // [standard errors]
	extern const ParameterRange jumpDriftDamage;    // [-]
}  // namespace ranges

// Every range above, in the order of the list.
const std::vector<const ParameterRange*>& parameterRanges();

// v, or ArgumentError "argument: expected <words>, got <v>"; argument is the name the caller knows the
// value by (the binding's "exponent" is the engine's fatigueExponent).
double        requireInRange(const ParameterRange& range, const std::string& argument, double v);
std::uint64_t requireInRange(const ParameterRange& range, const std::string& argument, std::uint64_t v);

}  // namespace ballast
