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
inline uint32_t depthValue(double z) {
  if (!(z > 0.0)) return 0;  // also NaN
  if (z >= 1.0) return kDepthMax;
  return static_cast<uint32_t>(z * double(kDepthMax) + 0.5);
}

}  // namespace glass::raster
