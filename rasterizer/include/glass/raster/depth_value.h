// Conversion of window depth in [0, 1] to the 24-bit depth buffer value: the one rounding that
// fragments, glClear(GL_DEPTH_BUFFER_BIT) and glDrawPixels(GL_DEPTH_COMPONENT) share, so that a
// fragment at the clear depth compares equal with the cleared buffer.
#pragma once

#include <cstdint>

#include "glass/raster/fragment.h"

namespace glass::raster {

// z is clamped to [0, 1] (spec 2.11.1 keeps window z in the depth range; polygon offset can push
// it out) and scaled to [0, 2^24 - 1]. Rounding is to the nearest integer, halves upward:
// floor(z * (2^24 - 1) + 0.5). So z = 0 gives 0 and z = 1 gives kDepthMax exactly, and a value
// written with glClearDepth(z) compares equal with a fragment at the same z.
//
// Written without branches (the clamped ends give 0.5 -> 0 and 2^24 - 0.5 -> kDepthMax), as the
// triangle walk computes a row of depths in vector lanes (rasterizer/src/block_rows.cpp); NaN
// compares false and clamps to 0.
inline uint32_t depthValue(double z) {
  double clamped = z > 0.0 ? z : 0.0;
  clamped = clamped < 1.0 ? clamped : 1.0;
  return static_cast<uint32_t>(static_cast<int32_t>(clamped * double(kDepthMax) + 0.5));
}

}  // namespace glass::raster
