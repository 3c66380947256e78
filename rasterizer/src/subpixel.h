// Window coordinates in 24.8 fixed point: 8 sub-pixel bits, as the triangle and line rasterizers
// (and Mesa's llvmpipe, the reference glass is compared with) snap them.
#pragma once

#include <cmath>
#include <cstdint>

namespace glass::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixelOne = int64_t{1} << kSubpixelBits;  // one pixel
inline constexpr int64_t kSubpixelHalf = kSubpixelOne / 2;            // offset of a pixel centre

// Window coordinates beyond +-2^19 pixels are refused, which keeps every edge-function product
// (2^27 * 2^28) well inside 64 bits. Clipped primitives lie inside the viewport, far below this.
inline constexpr double kMaxWindowCoordinate = double(1 << 19);

// One comparison, false for NaN and the infinities too.
inline bool isRasterizableCoordinate(float v) { return std::fabs(v) <= kMaxWindowCoordinate; }

// Rounds to the nearest 1/256 pixel, ties to even (the default IEEE rounding, so the result is the
// same on every machine). 256 * v is exact in double. For |v| <= kMaxWindowCoordinate the scaled
// value is below 2^28, and adding 1.5 * 2^52 leaves no bits of it below the units: the addition
// rounds it to an integer, ties to even, exactly as std::nearbyint does, and the subtraction is
// exact (the compiler may not fold the two: glass builds without -ffast-math). It is done here
// rather than by nearbyint, which is a call into the C library on the baseline x86-64 target, six
// of them for each triangle. A unit test compares the two on the ties, the signs and the ends of
// the range. A coordinate beyond the range (which the rasterizers refuse before snapping) gives
// a value of no use, but defined.
inline int64_t snapToSubpixel(float v) {
  constexpr double kShift = 0x1.8p52;
  const double scaled = static_cast<double>(v) * double(kSubpixelOne);
  if (!(std::fabs(scaled) < 0x1p51)) return 0;
  return static_cast<int64_t>((scaled + kShift) - kShift);
}

}  // namespace glass::raster
