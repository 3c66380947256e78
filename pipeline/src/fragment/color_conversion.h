// Conversion between the colour buffer's 8-bit components and floating-point colour (spec 2.14.9
// and table 2.9): c -> c / 255 on the way in; on the way out, clamp to [0, 1] and round to the
// nearest of the 256 levels (floor(c * 255 + 0.5), as Mesa does).
#pragma once

#include <cstdint>

namespace glass::gl {

inline uint8_t floatToColorByte(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<uint8_t>(c * 255.0f + 0.5f);
}

inline float colorByteToFloat(uint8_t c) { return static_cast<float>(c) * (1.0f / 255.0f); }

}  // namespace glass::gl
