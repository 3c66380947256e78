// Fast paths sit beside the reference path (docs/pipeline.md, "Fast paths"): a stage may take a
// specialised, batched or SIMD route for the common states, and must then give the same bytes as
// its reference route. GLASS_FAST_PATHS=0 turns every fast path off, so that the reference path
// alone draws and tests can compare the two byte for byte. Every stage asks fastPathsEnabled(),
// so there is one switch.
#pragma once

#include <string>

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

// The SIMD kernels are compiled for several instruction sets (Highway targets) and run with the
// best one the processor has, unless GLASS_SIMD_TARGET names another: "scalar" (portable code on
// emulated 128-bit vectors, the baseline x86-64 binary's own), "ssse3", "sse4", "avx2" or "avx3"
// (AVX-512). A name the processor cannot run, or an unknown one, is ignored. Every target gives
// the same bytes (the test image_simd_targets compares them). GLASS_SIMD_TARGET is read once,
// at the first draw that uses a kernel (core/simd_dispatch.h).
//
// The target the SIMD kernels run with, by the names above, for GL_RENDERER and the benchmark.
const char* simdTargetName();

// The targets this processor can run, by the names above, separated by spaces, "scalar" first.
std::string availableSimdTargetNames();

}  // namespace glass::gl
