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

inline bool isRasterizableCoordinate(float v) {
  return std::isfinite(v) && std::fabs(v) <= kMaxWindowCoordinate;
}

// Rounds to the nearest 1/256 pixel, ties to even (the default IEEE rounding, so the result is the
// same on every machine). 256 * v is exact in double.
inline int64_t snapToSubpixel(float v) {
  return static_cast<int64_t>(std::nearbyint(static_cast<double>(v) * double(kSubpixelOne)));
}

}  // namespace glass::raster
