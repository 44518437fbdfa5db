#include "Weibull.hpp"

#include <cassert>
#include <cmath>

#include "Random.hpp"

namespace ballast {

double weibullFactor(std::uint64_t seed, std::uint64_t key, double modulus)
{
	assert(modulus >= 0 && std::isfinite(modulus));
	if (modulus == 0) return 1.0;
	KeyedRandom  rng(seed, key);
	const double u = 1.0 - rng.uniform01();  // in (0, 1]: -ln u is finite
	return std::pow(-std::log(u), 1.0 / modulus);
}

void weibullFactors(std::uint64_t seed, long n, const std::uint64_t* keys, double modulus, double* out)
{
	for (long i = 0; i < n; ++i)
		out[i] = weibullFactor(seed, keys[i], modulus);
}

}  // namespace ballast
