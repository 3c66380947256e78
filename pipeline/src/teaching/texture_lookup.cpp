#include "teaching/texture_lookup.h"

#include "core/context.h"
#include "texture/texture_hooks.h"
#include "texture/texture_object.h"
#include "texture/texture_state.h"
#include "vertex/varyings.h"

namespace glass::gl {

TextureLookup textureLookupOf(const Context& ctx, const TextureObject& texture, int unit,
                              const raster::FragmentBatch& batch, int index) {
  const SamplerParameters& p = texture.params;
  const raster::Fragment& f = batch.fragments[index];
  float lambda = 0.0f;
  bool minified = false;
  if (needsLevelOfDetail(texture) && batch.planes != nullptr && texture.target != GL_TEXTURE_CUBE_MAP) {
    lambda = quadLevelOfDetail(ctx, texture, varying::texCoordSlot(unit), ctx.texture.units[unit].env.lodBias,
                               *batch.planes, f.x, f.y);
    minified = lambda > texture.sampling.switchOverPoint;
  }
  TextureLookup lookup;
  lookup.levels.level1 = lookup.levels.level2 = p.baseLevel;
  if (minified && isMipmapFilter(p.minFilter)) {
    lookup.levels = selectMipmapLevels(lambda, p.minFilter, p.baseLevel, texture.lastLevel);
  }
  // sampleTexture reads the second level only when it differs and has a weight.
  lookup.levelsRead = lookup.levels.level2 != lookup.levels.level1 && lookup.levels.weight2 != 0.0f ? 2 : 1;
  const GLenum filter = minified ? p.minFilter : p.magFilter;
  const bool linear = filter == GL_LINEAR || filter == GL_LINEAR_MIPMAP_NEAREST || filter == GL_LINEAR_MIPMAP_LINEAR;
  if (linear) {
    lookup.texelsPerLevel = texture.target == GL_TEXTURE_1D ? 2 : texture.target == GL_TEXTURE_3D ? 8 : 4;
  }
  return lookup;
}

}  // namespace glass::gl
