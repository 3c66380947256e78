// The lanes level of detail of texture/level_of_detail-inl.h as a function of the library, for
// every SIMD target: the fragment kernels include the per-target header and call it inline; tests
// call it here, target by target, to compare it with levelOfDetailFromSquaredScale.
#pragma once

#include "core/simd_dispatch.h"

namespace glass::gl {

constexpr int kLevelOfDetailQuads = 4;

// lambda[i] = levelOfDetailFromSquaredScale(rhoSquared[i], minLod, maxLod, bias) for the
// kLevelOfDetailQuads entries, computed by the copy compiled for `target` (which must run here:
// simdTargetRuns). rhoSquared must be aligned to 32 bytes.
void levelsOfDetailWith(SimdTarget target, const double* rhoSquared, float minLod, float maxLod, float bias,
                        float* lambda);

}  // namespace glass::gl
