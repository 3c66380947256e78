// What a textured fragment kernel (block_kernels.h, KernelTexturing::Single2D) needs of unit 0's
// texture, taken once per draw by FragmentProcessor::prepare instead of once per block: the
// lookups prepared by Sampler2D and the constants of the level of detail.
//
// A draw that textures is finished before the GL state moves on (DrawPipeline::
// finishIfReadingContext, at the end of every primitive), and no texture state can change while
// its primitives are drawn, so what prepare takes stays the state the reference path reads from
// the context fragment by fragment.
#pragma once

#include <optional>

#include "texture/level_of_detail.h"
#include "texture/sampler_2d.h"
#include "texture/texture_environment.h"
#include "texture/texture_image.h"

namespace glass::gl {

struct Context;

struct KernelTexture {
  // Reads unit 0's texture and environment from the context; `sampler` stays empty when the
  // unit samples nothing (an incomplete texture turns texturing off, spec 3.8.15).
  void prepare(const Context& ctx);

  const TextureEnvironment* env = nullptr;
  std::optional<Sampler2D> sampler;  // the texture's lookups
  BaseFormat base = BaseFormat::RGBA;
  bool needsLambda = false;  // a lambda per 2x2 quad decides the levels (texture_hooks.h)
  float minLod = 0.0f, maxLod = 0.0f, lodBias = 0.0f;  // textureLevelOfDetail's
  int baseWidth = 0, baseHeight = 0;
  // Every quad's levels when no lambda is needed: the magnification filter's.
  Sampler2D::LevelChoice magnified[kLevelOfDetailQuads] = {};
};

}  // namespace glass::gl
