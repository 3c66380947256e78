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

// words[i] = packColorBytes(floatToColorByte(red[i]), ..., floatToColorByte(alpha[i])) for i <
// count, for colours held as one array per component (component[0] red to component[3] alpha),
// such as a batch of line runs' (fragment/line_kernels.cpp). Four colours at a time are the
// lanes of vectors (GCC and Clang vector extensions), each lane doing exactly floatToColorByte's
// operations, so the bytes are the same on any target; the last count % 4 one by one.
inline void packColorColumns(const float* const component[4], int count, uint32_t* words) {
  using FloatLanes = float __attribute__((vector_size(16)));
  using IntLanes = int32_t __attribute__((vector_size(16)));
  constexpr int kLanes = 4;
  int i = 0;
  for (; i + kLanes <= count; i += kLanes) {
    IntLanes packed = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c) {
      FloatLanes value;
      std::memcpy(&value, component[c] + i, sizeof value);
      const FloatLanes sum = value * (255.0f / 256.0f) + 32768.0f;
      IntLanes inRange;
      std::memcpy(&inRange, &sum, sizeof inRange);
      inRange &= 0xFF;
      const IntLanes belowOne = value >= 1.0f ? IntLanes{255, 255, 255, 255} : inRange;
      const IntLanes bytes = value > 0.0f ? belowOne : IntLanes{0, 0, 0, 0};  // 0 also for NaN
      // The colour buffer's order, r, g, b, a in memory, as packColorBytes's word holds it.
      const int shift = std::endian::native == std::endian::little ? 8 * c : 24 - 8 * c;
      packed |= bytes << shift;
    }
    std::memcpy(words + i, &packed, sizeof packed);
  }
  for (; i < count; ++i)
    words[i] = packColorBytes(floatToColorByte(component[0][i]), floatToColorByte(component[1][i]),
                              floatToColorByte(component[2][i]), floatToColorByte(component[3][i]));
}

}  // namespace glass::gl
