// Binding of InputCheck.hpp: the parameters' ranges, the one declaration ballast.params builds its checks from.
#include <limits>

#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::dict parameterRangesOf()
	{
		bp::dict out;
		for (const ParameterRange* r : parameterRanges())
			out[r->name] = bp::make_tuple(r->lower, r->upper, r->lowerClosed, r->upperClosed, r->integer, r->zeroAllowed,
			                              r->words);
		return out;
	}
}  // namespace

void registerInputCheck()
{
	bp::def("parameterRanges", parameterRangesOf,
	        "The allowed range of every engine parameter the C++ core checks, the one declaration of them:\n"
	        "{name: (lower, upper, lowerClosed, upperClosed, integer, zeroAllowed, words)}: lower <= v (< if not lowerClosed)\n"
	        "and v <= upper (< if not upperClosed), a whole number if integer, or v == 0 if zeroAllowed; words says it\n"
	        "('a number in [0, 3]'), as the errors do. ballast.params builds its checks and docs/parameters.md from it.");
}

}  // namespace binding
}  // namespace ballast
