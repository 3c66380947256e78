// The row sampler of texture/row_sampler_2d-inl.h as a function of the library, for every SIMD
// target: the fragment kernels include the per-target header and call it inline; tests call it
// here, target by target, to compare it with Sampler2D.
#pragma once

#include "core/simd_dispatch.h"
#include "texture/sampler_2d.h"

namespace glass::gl {

constexpr int kSampledRowPixels = 8;

// texel[c][i] = component c of sampler.sampleChosen(quadChoice[i / 2], s[i], t[i], ...) for each
// bit i of mask (pixels 2k and 2k + 1 share quad k's levels), computed by the copy of the row
// sampler compiled for `target` (which must run here: simdTargetRuns).
void sampleTextureRowWith(SimdTarget target, const Sampler2D& sampler, const float* s, const float* t,
                          const Sampler2D::LevelChoice* quadChoice, unsigned mask,
                          float texel[4][kSampledRowPixels]);

}  // namespace glass::gl
