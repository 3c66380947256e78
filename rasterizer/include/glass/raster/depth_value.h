// Conversion of window depth in [0, 1] to the 24-bit depth buffer value: the one rounding that
// fragments, glClear(GL_DEPTH_BUFFER_BIT) and glDrawPixels(GL_DEPTH_COMPONENT) share, so that a
// fragment at the clear depth compares equal with the cleared buffer.
#pragma once

#include <cstdint>
#include <cstring>

#include "glass/raster/fragment.h"

namespace glass::raster {

// z is clamped to [0, 1] (spec 2.11.1 keeps window z in the depth range; polygon offset can push
// it out) and scaled to [0, 2^24 - 1]. Rounding is to the nearest integer, halves upward:
// floor(z * (2^24 - 1) + 0.5). So z = 0 gives 0 and z = 1 gives kDepthMax exactly, and a value
// written with glClearDepth(z) compares equal with a fragment at the same z.
//
// Written without branches (the clamped ends give 0.5 -> 0 and 2^24 - 0.5 -> kDepthMax), so that
// a row of depths becomes vector code; NaN compares false and clamps to 0.
inline uint32_t depthValue(double z) {
  double clamped = z > 0.0 ? z : 0.0;
  clamped = clamped < 1.0 ? clamped : 1.0;
  return static_cast<uint32_t>(static_cast<int32_t>(clamped * double(kDepthMax) + 0.5));
}

// depthValue(z[0]) and depthValue(z[1]) as one vector operation each (GCC and Clang vector
// extensions): the same clamps, multiply, add and truncation per lane, so the same values (the
// unit test depth_value_pairs_match compares them).
inline void depthValuePair(const double z[2], uint32_t out[2]) {
  using DoubleLanes = double __attribute__((vector_size(16)));
  using IntLanes = int32_t __attribute__((vector_size(8)));
  const DoubleLanes zero = {0.0, 0.0}, one = {1.0, 1.0};
  DoubleLanes clamped = {z[0], z[1]};
  clamped = clamped > zero ? clamped : zero;  // NaN compares false and clamps to 0
  clamped = clamped < one ? clamped : one;
  const IntLanes values = __builtin_convertvector(clamped * double(kDepthMax) + 0.5, IntLanes);
  std::memcpy(out, &values, sizeof values);
}

}  // namespace glass::raster
