// Fast paths of the fragment stage for line segments (docs/pipeline.md, "Fast paths").
//
// The line walk hands a sink runs of fragments that share their depth and varyings
// (glass/raster/line_run.h). The reference path expands each run into fragments and runs the
// whole of chapter 4.1 on every one (FragmentProcessor::processFragments), converting the same
// colour again for each. For the states lines are mostly drawn with, FragmentProcessor::prepare
// picks a kernel once per draw that converts a run's colour once and then makes the depth test
// and the writes fragment by fragment, with the reference path's own functions, so that it
// writes the same bytes.
#pragma once

#include <cstdint>

#include "core/simd_dispatch.h"
#include "fragment/stencil_depth_tests.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/line_run.h"

namespace glass::gl {

// The state a line kernel is compiled for. Kernels exist only for draws whose fragment colour is
// the interpolated primary colour as it is (no per-fragment lighting, texturing, colour sum or
// fog), with no alpha test, stencil test, blending or logic op, writing all four colour channels
// or none; FragmentProcessor::prepare checks that. The depth function and mask are read at run
// time (tests.depthFunc, tests.depthMask), as the reference path reads them.
struct LineKernelKey {
  bool depthTest = false;
  bool writeColor = false;
};

// Tests and writes the fragments of a batch of runs, each colour ORed with storedAlpha
// (storedAlphaWord, core/ancillary_buffers.h). tests.stencilTest must be off.
using LineKernel = void (*)(raster::Framebuffer& framebuffer, const StencilDepthSettings& tests,
                            uint32_t storedAlpha, const raster::LineRunBatch& batch);

// The kernel compiled for the key, in the copy of the chosen SIMD target.
LineKernel lineKernelFor(const LineKernelKey& key);

// The kernels' conversion of colours held as one array per component (component[0] red to
// component[3] alpha): words[i] = packColorBytes(floatToColorByte(red[i]), ...,
// floatToColorByte(alpha[i])) for i < count, in the copy compiled for `target` (tests; the
// target must run here).
void packColorColumnsWith(SimdTarget target, const float* const component[4], int count, uint32_t* words);

}  // namespace glass::gl
