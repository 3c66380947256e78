// Conversion between the colour buffer's 8-bit components and floating-point colour (spec 2.14.9
// and table 2.9): c -> c / 255 on the way in; on the way out, clamp to [0, 1] and round c * 255 to
// the nearest integer.
//
// The rounding is Mesa's (its float-to-ubyte conversion, used by llvmpipe and softpipe alike):
// c * 255/256 is rounded to float, then to the nearest multiple of 1/256, ties to even. It agrees
// with floor(c * 255 + 0.5) except near ties, where Mesa's float product decides: 0.3f gives 76,
// not 77. Following it keeps glass's pictures equal to Mesa's for colours such as 0.3 and 0.9.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>

namespace glass::gl {

inline uint8_t floatToColorByte(float c) {
  // Adding 2^15 leaves 8 fraction bits in the float's mantissa: the sum is scaled rounded to the
  // nearest multiple of 1/256 (ties to even), and its low mantissa bits hold scaled * 256.
  // For 0 < c < 1, scaled < 255/256, so the result is at most 255. The ends are chosen after
  // the sum rather than before it (selects, no branches), so that a row of pixels converts as
  // vector code (packRowColors in fragment/block_kernels.cpp).
  const float sum = c * (255.0f / 256.0f) + 32768.0f;
  const uint32_t inRange = std::bit_cast<uint32_t>(sum) & 0xFFu;
  const uint32_t belowOne = c >= 1.0f ? 255u : inRange;
  return static_cast<uint8_t>(c > 0.0f ? belowOne : 0u);  // 0 also for NaN
}

// The 32-bit word whose bytes in memory are r, g, b, a (the colour buffer's order), so that a
// pixel is written with one store. (Four byte stores read back as a word would stall until the
// processor had merged them.)
inline uint32_t packColorBytes(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  if constexpr (std::endian::native == std::endian::little) {
    return uint32_t{r} | uint32_t{g} << 8 | uint32_t{b} << 16 | uint32_t{a} << 24;
  } else {
    return uint32_t{r} << 24 | uint32_t{g} << 16 | uint32_t{b} << 8 | uint32_t{a};
  }
}

}  // namespace glass::gl
