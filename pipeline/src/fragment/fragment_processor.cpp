#include "fragment/fragment_processor.h"

#include <cstring>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "fragment/color_conversion.h"
#include "fragment/color_sum.h"
#include "fragment/comparison.h"
#include "fragment/fog_hooks.h"
#include "fragment/logic_op.h"
#include "fragment/stencil_operation.h"
#include "lighting/lighting_hooks.h"
#include "texture/texture_hooks.h"
#include "vertex/varyings.h"

namespace glass::gl {

void FragmentProcessor::prepare(Context& ctx, bool phong) {
  ctx_ = &ctx;
  const FragmentState& f = ctx.fragment;
  const bool lighting = lightingEnabled(ctx);

  phong_ = phong;
  texturing_ = texturingEnabled(ctx);
  bumpMapping_ = phong && bumpMappingActive(ctx);
  // Spec 3.9: the secondary colour is added when lighting with GL_SEPARATE_SPECULAR_COLOR or,
  // without lighting, when GL_COLOR_SUM is enabled (the vertex stage then passes glSecondaryColor).
  colorSum_ = lighting ? separateSpecularColor(ctx) : ctx.fog.colorSum;
  secondaryVarying_ = colorSum_ && !phong;
  fog_ = fogEnabled(ctx);

  alphaTest_ = f.alphaTest && f.alphaFunc != GL_ALWAYS;
  alphaFunc_ = f.alphaFunc;
  alphaRefByte_ = floatToColorByte(f.alphaRef);

  stencilTest_ = f.stencilTest;
  stencilFunc_ = f.stencilFunc;
  stencilRef_ = static_cast<uint8_t>(f.stencilRef);
  stencilValueMask_ = f.stencilValueMask & 0xFFu;
  stencilWriteMask_ = f.stencilWriteMask & 0xFFu;
  stencilFail_ = f.stencilFail;
  stencilDepthFail_ = f.stencilDepthFail;
  stencilDepthPass_ = f.stencilDepthPass;

  depthTest_ = f.depthTest;
  depthFunc_ = f.depthFunc;
  depthMask_ = f.depthMask;

  // With GL_COLOR_LOGIC_OP enabled, the logic op replaces blending (spec 4.1.10).
  logicOp_ = f.colorLogicOp;
  logicOpMode_ = f.logicOp;
  blend_ = f.blend && !logicOp_;
  blendSettings_.srcRGB = f.blendSrcRGB;
  blendSettings_.dstRGB = f.blendDstRGB;
  blendSettings_.srcAlpha = f.blendSrcAlpha;
  blendSettings_.dstAlpha = f.blendDstAlpha;
  blendSettings_.equation = f.blendEquation;
  for (int i = 0; i < 4; ++i) {
    blendSettings_.constant[i] = floatToColorByte(f.blendColor[i]);
    colorMask_[i] = f.colorMask[i];
  }
  writesColor_ = drawsColor(f.drawBuffer) &&
                 (colorMask_[0] || colorMask_[1] || colorMask_[2] || colorMask_[3]);
  allChannels_ = colorMask_[0] && colorMask_[1] && colorMask_[2] && colorMask_[3];
}

void FragmentProcessor::processFragments(const raster::FragmentBatch& batch) {
  processFragments(batch, nullptr);
}

void FragmentProcessor::processFragments(const raster::FragmentBatch& batch,
                                         const float* coverage) {
  const Context& ctx = *ctx_;
  raster::Framebuffer& fb = ctx_->framebuffer;

  for (int i = 0; i < batch.count; ++i) {
    const raster::Fragment& fragment = batch.fragments[i];
    const float* v = fragment.varyings;

    // Chapter 3: the fragment's colour.
    float color[4] = {v[0], v[1], v[2], v[3]};
    float secondary[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (secondaryVarying_) {
      for (int c = 0; c < 4; ++c) secondary[c] = v[varying::kSecondaryColor + c];
    }
    if (phong_) {
      float normal[3] = {v[varying::kEyeNormal], v[varying::kEyeNormal + 1], v[varying::kEyeNormal + 2]};
      if (bumpMapping_) perturbNormal(ctx, batch, i, normal);
      lightFragment(ctx, v + varying::kEyePosition, normal, batch.frontFacing, color, secondary);
    }
    if (texturing_) applyTexturing(ctx, batch, i, color);
    if (colorSum_) applyColorSum(secondary, color);
    if (fog_) applyFog(ctx, fragment, color);
    if (coverage) color[3] *= coverage[i];

    // Chapter 4.1: the tests, in order. The scissor test was the rasterizer's bounds.
    // Spec 4.1.4: the reference and the alpha are compared as the colour buffer's fixed-point
    // values, so an alpha that rounds to the reference's 8-bit value is equal to it.
    if (alphaTest_ && !passesComparison(alphaFunc_, floatToColorByte(color[3]), alphaRefByte_)) continue;

    uint8_t* stencil = stencilTest_ ? fb.stencilAt(fragment.x, fragment.y) : nullptr;
    if (stencil) {
      const unsigned stored = *stencil & stencilValueMask_;
      if (!passesComparison(stencilFunc_, stencilRef_ & stencilValueMask_, stored)) {
        writeStencil(*stencil, applyStencilOperation(stencilFail_, *stencil, stencilRef_),
                     stencilWriteMask_);
        continue;
      }
    }
    if (depthTest_) {
      uint32_t* depth = fb.depthAt(fragment.x, fragment.y);
      if (!passesComparison(depthFunc_, fragment.depth, *depth)) {
        if (stencil) {
          writeStencil(*stencil, applyStencilOperation(stencilDepthFail_, *stencil, stencilRef_),
                       stencilWriteMask_);
        }
        continue;
      }
      if (depthMask_) *depth = fragment.depth;
    }
    if (stencil) {
      writeStencil(*stencil, applyStencilOperation(stencilDepthPass_, *stencil, stencilRef_),
                   stencilWriteMask_);
    }

    if (!writesColor_) continue;
    uint8_t* pixel = fb.colorAt(fragment.x, fragment.y);
    uint8_t out[4];
    for (int c = 0; c < 4; ++c) out[c] = floatToColorByte(color[c]);
    if (blend_) {
      uint8_t blended[4];
      blend(blendSettings_, out, pixel, blended);
      for (int c = 0; c < 4; ++c) out[c] = blended[c];
    } else if (logicOp_) {
      for (int c = 0; c < 4; ++c) out[c] = applyLogicOp(logicOpMode_, out[c], pixel[c]);
    }
    if (allChannels_) {
      std::memcpy(pixel, out, 4);
    } else {
      for (int c = 0; c < 4; ++c) {
        if (colorMask_[c]) pixel[c] = out[c];
      }
    }
  }
}

}  // namespace glass::gl
