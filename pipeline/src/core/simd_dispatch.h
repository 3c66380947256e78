// The pipeline's SIMD kernels pick their copy with the rasterizer's choice of target
// (glass/raster/simd_target.h: the names, GLASS_SIMD_TARGET, and how a copy is chosen).
#pragma once

#include "glass/raster/simd_target.h"

namespace glass::gl {

using raster::chosenSimdFunction;
using raster::chosenSimdTarget;
using raster::SimdFunctions;
using raster::SimdTarget;
using raster::simdTargetRuns;

}  // namespace glass::gl
