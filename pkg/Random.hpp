// Reproducible random numbers keyed by integers (SplitMix64): the same (seed, key) gives the same
// stream on every machine and in every order of evaluation, so results do not depend on how many
// grains were drawn before. Used for fragment orientations (FragmentPattern) and strengths (Weibull).
#pragma once
#include <cstdint>

namespace ballast {

class KeyedRandom {
public:
	KeyedRandom(std::uint64_t seed, std::uint64_t key) : state_(seed ^ (key * 0xD1B54A32D192ED03ull)) { next(); }
	std::uint64_t next()
	{
		std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
		z               = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
		z               = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
		return z ^ (z >> 31);
	}
	// Uniform in [0, 1), 53 bits.
	double uniform01() { return (next() >> 11) * 0x1.0p-53; }

private:
	std::uint64_t state_;
};

}  // namespace ballast
