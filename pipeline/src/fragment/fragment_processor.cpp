#include "fragment/fragment_processor.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <optional>

#include "core/context.h"
#include "core/fast_paths.h"
#include "fragment/buffer_selection.h"
#include "fragment/color_conversion.h"
#include "fragment/color_sum.h"
#include "fragment/comparison.h"
#include "fragment/fog_hooks.h"
#include "glass/raster/triangle.h"
#include "fragment/logic_op.h"
#include "lighting/lighting_hooks.h"
#include "teaching/teaching_hooks.h"
#include "texture/texture_hooks.h"
#include "vertex/varyings.h"

namespace glass::gl {

void FragmentProcessor::prepare(Context& ctx, bool phong) {
  ctx_ = &ctx;
  const FragmentState& f = ctx.fragment;
  const bool lighting = lightingEnabled(ctx);

  s_.phong = phong;
  s_.texturing = texturingEnabled(ctx);
  s_.bumpMapping = phong && bumpMappingActive(ctx);
  // Spec 3.9: the secondary colour is added when lighting with GL_SEPARATE_SPECULAR_COLOR or,
  // without lighting, when GL_COLOR_SUM is enabled (the vertex stage then passes glSecondaryColor).
  s_.colorSum = lighting ? separateSpecularColor(ctx) : ctx.fog.colorSum;
  s_.secondaryVarying = s_.colorSum && !phong;
  s_.fog = fogEnabled(ctx);
  if (s_.fog) s_.fogState = ctx.fog;

  s_.alphaTest = f.alphaTest && f.alphaFunc != GL_ALWAYS;
  s_.alphaFunc = f.alphaFunc;
  s_.alphaRefByte = floatToColorByte(f.alphaRef);

  StencilDepthSettings& tests = s_.tests;
  tests.stencilTest = stencilTestActive(ctx);
  tests.stencilFunc = f.stencilFunc;
  tests.stencilRef = static_cast<uint8_t>(f.stencilRef);
  tests.stencilValueMask = f.stencilValueMask & 0xFFu;
  tests.stencilWriteMask = f.stencilWriteMask & 0xFFu;
  tests.stencilFail = f.stencilFail;
  tests.stencilDepthFail = f.stencilDepthFail;
  tests.stencilDepthPass = f.stencilDepthPass;

  tests.depthTest = depthTestActive(ctx);
  tests.depthFunc = f.depthFunc;
  tests.depthMask = f.depthMask;

  // With GL_COLOR_LOGIC_OP enabled, the logic op replaces blending (spec 4.1.10).
  s_.logicOp = f.colorLogicOp;
  s_.logicOpMode = f.logicOp;
  s_.blend = f.blend && !s_.logicOp;
  s_.blendSettings.srcRGB = f.blendSrcRGB;
  s_.blendSettings.dstRGB = f.blendDstRGB;
  s_.blendSettings.srcAlpha = f.blendSrcAlpha;
  s_.blendSettings.dstAlpha = f.blendDstAlpha;
  s_.blendSettings.equation = f.blendEquation;
  for (int i = 0; i < 4; ++i) {
    s_.blendSettings.constant[i] = floatToColorByte(f.blendColor[i]);
    s_.colorMask[i] = f.colorMask[i];
  }
  // Without the fast paths, blend() itself (the reference path's own function).
  s_.blendFunction = fastPathsEnabled() ? blendFunctionFor(s_.blendSettings) : &blend;
  s_.writesColor = drawsColor(f.drawBuffer) &&
                   (s_.colorMask[0] || s_.colorMask[1] || s_.colorMask[2] || s_.colorMask[3]);
  s_.storedAlpha = storedAlphaWord(ctx);
  s_.bothBuffers = s_.writesColor && writesBothBuffers(ctx);
  s_.allChannels = s_.colorMask[0] && s_.colorMask[1] && s_.colorMask[2] && (s_.colorMask[3] || s_.storedAlpha != 0);

  s_.fragmentCounts = nullptr;
  s_.fragmentColors = nullptr;
  if (TeachingCanvas* canvas = teachingCanvasFor(ctx)) {
    if (!canvas->fragmentCounts.empty()) {
      s_.fragmentCounts = canvas->fragmentCounts.data();
      s_.fragmentCountsWidth = canvas->width;
    }
    if (!canvas->fragmentColors.empty()) {
      s_.fragmentColors = canvas->fragmentColors.data();
      s_.fragmentColorsWidth = canvas->width;
      s_.fragmentColorsView = canvas->view;
    }
  }
  s_.statistics = frameStatisticsFor(ctx);
  s_.scissorTest = s_.statistics && f.scissorTest;
  if (s_.scissorTest) {
    const ScissorBox& box = f.scissor;
    s_.scissorX0 = box.x;
    s_.scissorY0 = box.y;
    s_.scissorX1 = static_cast<int>(std::min<long long>(INT_MAX, static_cast<long long>(box.x) + box.width));
    s_.scissorY1 = static_cast<int>(std::min<long long>(INT_MAX, static_cast<long long>(box.y) + box.height));
  }
  // One key for the state; a kernel for each kind of coverage.
  std::optional<BlockKernelKey> key = kernelKey();
  for (int c = 0; c < kKernelCoverageCount; ++c) {
    if (key) key->coverage = static_cast<KernelCoverage>(c);
    kernels_[c] = key ? blockKernelFor(*key) : nullptr;
  }
  lineKernel_ = chooseLineKernel();
  pixelOps_.tests = s_.tests;
  pixelOps_.blend = s_.blend;
  pixelOps_.blendSettings = s_.blendSettings;
  pixelOps_.blendRow = s_.blend ? blendRowFor(s_.blendSettings) : nullptr;
  pixelOps_.storedAlpha = s_.storedAlpha;
  if (kernels_[0] != nullptr && s_.texturing) kernelTexture_.prepare(ctx);
  // With the stencil test on, the kernel makes the depth test itself (block_kernels.h).
  kernelNeedsEarlyDepth_ = s_.tests.depthTest && s_.tests.depthFunc != GL_ALWAYS && !s_.tests.stencilTest;
}

bool FragmentProcessor::kernelsAllowed() const {
  return fastPathsEnabled() && s_.fragmentCounts == nullptr && s_.fragmentColors == nullptr &&
         s_.statistics == nullptr && !s_.bothBuffers;
}

bool FragmentProcessor::storesColorsAsGiven() const {
  return kernelsAllowed() && !s_.phong && !s_.texturing && !s_.colorSum && !s_.fog && !s_.alphaTest &&
         !s_.tests.stencilTest && !s_.tests.depthTest && !s_.blend && !s_.logicOp && s_.writesColor &&
         s_.allChannels;
}

std::optional<BlockKernelKey> FragmentProcessor::kernelKey() const {
  if (!kernelsAllowed()) return std::nullopt;
  // What no kernel does (block_kernels.h).
  if (s_.phong || s_.colorSum || s_.alphaTest || s_.logicOp || (s_.writesColor && !s_.allChannels))
    return std::nullopt;
  BlockKernelKey key;
  // With the stencil test on, the kernel's stencil and depth tests write the depth.
  key.writeDepth = s_.tests.depthTest && s_.tests.depthMask && !s_.tests.stencilTest;
  key.writeColor = s_.writesColor;
  key.fog = s_.fog;
  if (s_.texturing) {
    if (singleTexture2D(*ctx_) == nullptr) return std::nullopt;
    key.texturing = KernelTexturing::Single2D;
  }
  return key;
}

LineKernel FragmentProcessor::chooseLineKernel() const {
  if (!kernelsAllowed()) return nullptr;
  // The line kernels write the interpolated primary colour as it is (line_kernels.h).
  if (s_.phong || s_.texturing || s_.colorSum || s_.fog || s_.alphaTest || s_.tests.stencilTest ||
      s_.blend || s_.logicOp || (s_.writesColor && !s_.allChannels))
    return nullptr;
  LineKernelKey key;
  key.depthTest = s_.tests.depthTest;
  key.writeColor = s_.writesColor;
  return lineKernelFor(key);
}

void FragmentProcessor::processTriangleBlock(const raster::TriangleSetup& setup,
                                             const raster::CoveredBlock& block) {
  if (!shadeBlock(setup, block, KernelCoverage::None)) raster::FragmentSink::processTriangleBlock(setup, block);
}

bool FragmentProcessor::shadeBlock(const raster::TriangleSetup& setup, const raster::CoveredBlock& block,
                                   KernelCoverage coverage) {
  const BlockKernel kernel = kernels_[static_cast<int>(coverage)];
  if (kernel == nullptr) return false;
  // The kernel relies on the walk's early depth test, and a weighing one on the shape's payload.
  if (kernelNeedsEarlyDepth_ && setup.earlyDepth.buffer == nullptr) return false;
  if (coverage != KernelCoverage::None && setup.payload == nullptr) return false;
  kernel(*ctx_, pixelOps_, kernelTexture_, s_.fogState, setup, block);
  return true;
}

void FragmentProcessor::processLineRuns(const raster::LineRunBatch& batch) {
  if (lineKernel_ != nullptr) {
    lineKernel_(ctx_->framebuffer, s_.tests, s_.storedAlpha, batch);
  } else {
    raster::FragmentSink::processLineRuns(batch);
  }
}

void FragmentProcessor::processFragments(const raster::FragmentBatch& batch) {
  processFragments(batch, nullptr);
}

void FragmentProcessor::processFragments(const raster::FragmentBatch& batch,
                                         const float* coverage) {
  const Context& ctx = *ctx_;
  raster::Framebuffer& fb = ctx_->framebuffer;
  if (s_.fragmentCounts) countFragments(s_.fragmentCounts, s_.fragmentCountsWidth, batch);
  FragmentTally tally;
  const bool counting = s_.statistics != nullptr;

  for (int i = 0; i < batch.count; ++i) {
    const raster::Fragment& fragment = batch.fragments[i];
    const float* v = fragment.varyings;
    if (s_.scissorTest && (fragment.x < s_.scissorX0 || fragment.x >= s_.scissorX1 ||
                           fragment.y < s_.scissorY0 || fragment.y >= s_.scissorY1)) {
      ++tally.scissorRejected;  // spec 4.1.2, made here only while counting
      continue;
    }
    if (counting && s_.texturing) tally.texelReads += texelReadsOf(ctx, batch, i);

    // Chapter 3: the fragment's colour.
    float color[4] = {v[0], v[1], v[2], v[3]};
    float secondary[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (s_.secondaryVarying) {
      for (int c = 0; c < 4; ++c) secondary[c] = v[varying::kSecondaryColor + c];
    }
    if (s_.phong) {
      float normal[3] = {v[varying::kEyeNormal], v[varying::kEyeNormal + 1], v[varying::kEyeNormal + 2]};
      if (s_.bumpMapping) perturbNormal(ctx, batch, i, normal);
      lightFragment(ctx, v + varying::kEyePosition, normal, batch.frontFacing, color, secondary);
    }
    if (s_.texturing) applyTexturing(ctx, batch, i, color);
    if (s_.colorSum) applyColorSum(secondary, color);
    if (s_.fog) applyFog(s_.fogState, fragment, color);
    if (coverage) color[3] *= coverage[i];

    // Chapter 4.1: the tests, in order. The scissor test was the rasterizer's bounds.
    // Spec 4.1.4: the reference and the alpha are compared as the colour buffer's fixed-point
    // values, so an alpha that rounds to the reference's 8-bit value is equal to it.
    if (s_.alphaTest &&
        !passesComparison(s_.alphaFunc, floatToColorByte(color[3]), s_.alphaRefByte)) {
      ++tally.alphaRejected;
      continue;
    }

    uint8_t* stencil = s_.tests.stencilTest ? fb.stencilAt(fragment.x, fragment.y) : nullptr;
    uint32_t* depth = s_.tests.depthTest ? fb.depthAt(fragment.x, fragment.y) : nullptr;
    const StencilDepthOutcome outcome = testStencilAndDepth(s_.tests, stencil, depth, fragment.depth);
    if (outcome == StencilDepthOutcome::StencilFailed) {
      ++tally.stencilRejected;
      continue;
    }
    if (outcome == StencilDepthOutcome::DepthFailed) {
      ++tally.depthRejected;
      continue;
    }

    ++tally.passed;
    if (!s_.writesColor) continue;
    if (s_.fragmentColors) {
      paintFragmentView(ctx, s_.fragmentColorsView, s_.fragmentColors, s_.fragmentColorsWidth, batch, i,
                        v + varying::kEyeNormal);
    }
    writeColor(color, fb.colorAt(fragment.x, fragment.y));
    if (s_.bothBuffers) writeColor(color, fb.otherColorAt(fragment.x, fragment.y));
  }
  if (counting) addFragmentTally(*s_.statistics, batch.count, tally);
}

// Spec 4.1.7 to 4.1.10 and 4.2.2: blending or the logic op with the pixel, the colour mask.
void FragmentProcessor::writeColor(const float color[4], uint8_t* pixel) const {
  if (s_.allChannels && !s_.blend && !s_.logicOp) {
    // The common case, one whole-pixel store. The four bytes are put together in a register:
    // written to memory one by one and read back as a word, they would stall the store until
    // the processor had merged them.
    const uint32_t word = packColorBytes(floatToColorByte(color[0]), floatToColorByte(color[1]),
                                         floatToColorByte(color[2]), floatToColorByte(color[3])) |
                          s_.storedAlpha;
    std::memcpy(pixel, &word, 4);
    return;
  }
  uint8_t out[4];
  for (int c = 0; c < 4; ++c) out[c] = floatToColorByte(color[c]);
  if (s_.blend) {
    uint8_t blended[4];
    s_.blendFunction(s_.blendSettings, out, pixel, blended);
    for (int c = 0; c < 4; ++c) out[c] = blended[c];
  } else if (s_.logicOp) {
    for (int c = 0; c < 4; ++c) out[c] = applyLogicOp(s_.logicOpMode, out[c], pixel[c]);
  }
  if (s_.storedAlpha != 0) out[3] = 255;  // no alpha bitplanes: the result's alpha is not kept
  if (s_.allChannels) {
    std::memcpy(pixel, out, 4);
  } else {
    for (int c = 0; c < 4; ++c) {
      if (s_.colorMask[c]) pixel[c] = out[c];
    }
  }
}

}  // namespace glass::gl
