// The stencil and depth tests of a block row (fragment/stencil_depth_rows-inl.h) as a function
// of the library, for every SIMD target: the block kernels include the per-target header and
// call it inline; tests call it here, target by target, to compare it with testStencilAndDepth.
#pragma once

#include <cstdint>

#include "fragment/stencil_depth_tests.h"
#include "glass/raster/simd_target.h"

namespace glass::gl {

inline constexpr int kStencilDepthRowPixels = 8;

// testStencilAndDepth(settings, &stencil[i], &depth[i], fragmentDepth[i]) for each bit i of mask
// (pixels 0 to kStencilDepthRowPixels - 1; stencil is used only with the stencil test on, depth
// only with the depth test on), computed by the copy compiled for `target` (which must run
// here: simdTargetRuns). Returns the pixels of mask that passed both tests.
unsigned testStencilAndDepthRowWith(raster::SimdTarget target, const StencilDepthSettings& settings,
                                    uint8_t* stencil, uint32_t* depth, const uint32_t* fragmentDepth,
                                    unsigned mask);

}  // namespace glass::gl
