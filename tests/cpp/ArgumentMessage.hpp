// Test helper shared by the core's tests: the message of the ArgumentError a call throws.
#pragma once
#include <string>

#include "InputCheck.hpp"

namespace ballast_test {

// The message of the ballast::ArgumentError thrown by f(), or "" when nothing is thrown.
template <class F> std::string messageOf(F f)
{
	try {
		f();
	} catch (const ballast::ArgumentError& e) {
		return e.what();
	}
	return "";
}

}  // namespace ballast_test
