// The accumulation buffer (OpenGL 1.5 specification, section 4.2.4; tables 6.21 and 6.34): one
// signed 16-bit value per channel and pixel holding colours in [-1, 1] as c * 32767, the layout
// Mesa uses (RGBA_SNORM16), so that glAccum rounds as Mesa does. Allocated on first use: programs
// that never touch it pay nothing.
#pragma once

#include <cstdint>
#include <vector>

namespace glass::gl {

// GL_ACCUM_RED_BITS .. GL_ACCUM_ALPHA_BITS.
inline constexpr int kAccumulationBits = 16;

struct AccumulationState {
  float clearValue[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // glClearAccum, clamped to [-1, 1]
  // width * height * 4 values, row 0 (the bottom row) first; empty until first used.
  std::vector<int16_t> buffer;
};

}  // namespace glass::gl
