// A small seeded random number generator whose sequence is fixed by this file alone (SplitMix64,
// Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014), so that the
// chaos game and the random lines of the course's tools give the same output on every machine.
// <random>'s engines are portable but its distributions are not: libstdc++ and libc++ map the
// same engine output to different doubles.
#pragma once

#include <cstdint>

namespace glass::geometry {

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}

  constexpr std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1): the top 53 bits as a double's mantissa.
  constexpr double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Uniform integer in [0, bound), bound > 0, by rejection so that no value is favoured.
  constexpr std::uint64_t below(std::uint64_t bound) {
    const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % bound);
    std::uint64_t x;
    do {
      x = next();
    } while (x >= limit);
    return x % bound;
  }

 private:
  std::uint64_t state_;
};

}  // namespace glass::geometry
