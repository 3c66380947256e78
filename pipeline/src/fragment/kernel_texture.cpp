#include "fragment/kernel_texture.h"

#include "core/context.h"
#include "texture/texture_hooks.h"

namespace glass::gl {

void KernelTexture::prepare(const Context& ctx) {
  const TextureObject* texture = ctx.texture.units[0].activeTexture();
  env = &ctx.texture.units[0].env;
  sampler.reset();
  if (texture == nullptr) return;
  sampler.emplace(*texture);
  base = texture->baseImage().base;
  needsLambda = needsLevelOfDetail(*texture);
  minLod = texture->params.minLod;
  maxLod = texture->params.maxLod;
  lodBias = textureLodBias(*texture, env->lodBias);
  baseWidth = texture->baseImage().width;
  baseHeight = texture->baseImage().height;
  for (Sampler2D::LevelChoice& quad : magnified) quad = sampler->chooseMagnified();
}

}  // namespace glass::gl
