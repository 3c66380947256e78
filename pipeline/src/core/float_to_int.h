// Conversions from floating point to int that are defined for every input. C++ leaves converting
// a value outside int's range (an infinity, NaN, 1e30) undefined, and GL programs can send such
// values: a raster position moved by a huge glBitmap step, NaN texture coordinates. The
// specification leaves the pictures of such values undefined; glass must still not crash, so
// pixel positions computed from user data go through these.
#pragma once

#include <cmath>

namespace glass::gl {

// Pixel positions are clamped to +-2^30: far outside any framebuffer (whose sides are at most
// 2^14), so such a position draws nothing, and adding an image size to it cannot overflow.
inline constexpr double kFarPixel = 1073741824.0;  // 2^30

// floor(v) as an int, clamped to +-2^30; NaN gives -2^30 (off the framebuffer).
inline int floorToPixel(double v) {
  if (!(v >= -kFarPixel)) return -static_cast<int>(kFarPixel);  // NaN or far below
  if (v >= kFarPixel) return static_cast<int>(kFarPixel);
  return static_cast<int>(std::floor(v));
}

}  // namespace glass::gl

namespace glass::gl {

// An enum passed as a float parameter (glFogf(GL_FOG_MODE, GL_LINEAR), glTexParameterf): its value
// when the float holds a whole number an enum can have, else 0, which no caller accepts.
inline unsigned enumFromFloat(double v) {
  if (!(v >= 0.0 && v <= 4294967295.0) || v != std::floor(v)) return 0;
  return static_cast<unsigned>(v);
}

}  // namespace glass::gl
