// Fast paths sit beside the reference path (docs/pipeline.md, "Fast paths"): a stage may take a
// specialised, batched or SIMD route for the common states, and must then give the same bytes as
// its reference route. GLASS_FAST_PATHS=0 turns every fast path off, so that the reference path
// alone draws and tests can compare the two byte for byte. Every stage asks fastPathsEnabled(),
// so there is one switch.
#pragma once

#include "glass/raster/simd_target.h"

namespace glass::gl {

// False when the environment variable GLASS_FAST_PATHS is "0" at the first call; true otherwise.
bool fastPathsEnabled();

// For tests that compare the two paths within one process: while an object of this class lives,
// fastPathsEnabled() returns `enabled` whatever the environment says. Draws choose their path
// when they start, so the caller switches only between finished draws (glFinish).
class ScopedFastPaths {
 public:
  explicit ScopedFastPaths(bool enabled);
  ~ScopedFastPaths();
  ScopedFastPaths(const ScopedFastPaths&) = delete;
  ScopedFastPaths& operator=(const ScopedFastPaths&) = delete;

 private:
  int previous_;
};

// The SIMD target the kernels run with and the ones this processor can run, by the names
// GLASS_SIMD_TARGET takes (glass/raster/simd_target.h).
using raster::availableSimdTargetNames;
using raster::simdTargetName;

}  // namespace glass::gl
