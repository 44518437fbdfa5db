// Scattered grain strength, beyond the paper (issue 13; docs/strength.md). Weibull's weakest-link
// statistics (Weibull 1951; for crushable grains McDowell & Bolton 1998): a grain of radius r survives
// a stress sigma with probability
//   P_s = exp(-(sigma / sigma_0(r))^k),   sigma_0(r) = ft0 / r^m  (eq. 4: the characteristic strength),
// k the Weibull modulus. Its strength is sigma_0(r) * w with w = (-ln U)^(1/k), U uniform in (0, 1]
// drawn from (seed, key): reproducible, and independent of the order in which grains are drawn.
// k = 3 with m = 1 is the size effect of eq. 4 (sigma_0 ~ V^(-1/k)). k = 0: no scatter, w = 1.
#pragma once
#include <cstdint>

namespace ballast {

// The strength factor w [-] of the grain `key`; modulus k [-] 0 (none) or > 0, the caller checked it
// (InputCheck.hpp: weibullModulus).
double weibullFactor(std::uint64_t seed, std::uint64_t key, double modulus);

// n factors for keys[0..n), of a modulus checked as above.
void weibullFactors(std::uint64_t seed, long n, const std::uint64_t* keys, double modulus, double* out);

}  // namespace ballast
