#pragma once
// The GA's only source of randomness: std::mt19937_64 seeded from the parameters, with the
// distributions written out here. std::uniform_real_distribution, std::normal_distribution and
// std::uniform_int_distribution are implementation-defined algorithms, so the same seed could
// give different runs with libstdc++ and libc++; these give the same draws everywhere.

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace glossa::control {

constexpr double kTwoPi = 6.283185307179586476925287;

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  // Uniform on [0, 1): the top 53 bits of one draw, exactly representable.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Uniform on {0, ..., n - 1} (n >= 1), unbiased: draws in the incomplete last block of n
  // values are rejected.
  std::uint64_t index(std::uint64_t n) {
    constexpr std::uint64_t top = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t excess = (top % n + 1) % n;  // (2^64) mod n
    std::uint64_t r = engine_();
    while (r > top - excess) r = engine_();
    return r % n;
  }

  bool bernoulli(double p) { return uniform() < p; }

  // Standard normal by Box-Muller (one value per pair of draws; 1 - uniform() is in (0, 1], so
  // the logarithm is finite).
  double normal() {
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace glossa::control
