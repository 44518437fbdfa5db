// Binding of Weibull.hpp: the grains' Weibull strength factors, one per key.
#include <cstdint>
#include <string>
#include <vector>

#include "../InputCheck.hpp"
#include "../Weibull.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	np::ndarray weibullFactorsOf(const bp::object& seed, const bp::object& keys, const bp::object& modulus)
	{
		const std::uint64_t        sd = asSeed(seed);
		np::ndarray                k  = asIndices(keys, "keys");
		const long                 n  = requireShape(k, "keys", {-1}, "a 1-d array");
		std::vector<std::uint64_t> u(n);
		for (long i = 0; i < n; ++i) {
			if (lptr(k)[i] < 0)
				throw ArgumentError("keys: expected integers >= 0, got " + std::to_string(lptr(k)[i]) + " at index " + std::to_string(i));
			u[i] = (std::uint64_t)lptr(k)[i];
		}
		const double modulusValue = requireInRange(ranges::weibullModulus, "modulus", asScalar(modulus, "modulus"));
		np::ndarray  out          = emptyDoubles({n});
		weibullFactors(sd, n, u.data(), modulusValue, wptr(out));
		return finiteResult(out, "modulus", "Weibull factor");
	}
}  // namespace

void registerWeibull()
{
	bp::def("weibullFactors", weibullFactorsOf, (bp::arg("seed"), "keys", "modulus"),
	        "Weibull strength factors (docs/strength.md): w = (-ln U)^(1/modulus), U uniform from (seed, key), one per\n"
	        "key (N,) integers >= 0; modulus 0 gives 1. Reproducible and independent of the order of the keys.");
}

}  // namespace binding
}  // namespace ballast
