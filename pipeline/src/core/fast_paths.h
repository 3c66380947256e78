// Fast paths sit beside the reference path (docs/pipeline.md, "Fast paths"): a stage may take a
// specialised, batched or SIMD route for the common states, and must then give the same bytes as
// its reference route. GLASS_FAST_PATHS=0 turns every fast path off, so that the reference path
// alone draws and tests can compare the two byte for byte. Every stage asks fastPathsEnabled(),
// so there is one switch.
#pragma once

namespace glass::gl {

// False when the environment variable GLASS_FAST_PATHS is "0" at the first call; true otherwise.
bool fastPathsEnabled();

// The instruction set the SIMD kernels run with, for GL_RENDERER and the benchmark: "scalar"
// while no kernel uses SIMD, or when fast paths are off.
const char* simdTargetName();

}  // namespace glass::gl
