// The random numbers of the unit tests that draw many inputs: a 64-bit linear congruential
// generator (Knuth's MMIX constants), the same sequence on every machine, so a failing input is
// found again from its seed.
#pragma once

#include <cstdint>

struct LcgRandom {
  uint64_t state;
  // 53 bits from the top of the state.
  uint64_t next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 11;
  }
};
