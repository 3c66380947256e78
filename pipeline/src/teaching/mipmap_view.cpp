// The mipmap view's colour of one fragment: the level its texture lookup reads.
#include <cmath>

#include "core/context.h"
#include "glass/geometry/teaching_scales.h"
#include "teaching/teaching_hooks.h"
#include "teaching/texture_lookup.h"
#include "texture/texture_state.h"

namespace glass::gl {

void paintMipmapLevel(const Context& ctx, const raster::FragmentBatch& batch, int index,
                      std::uint8_t* rgba) {
  rgba[3] = 255;
  for (int u = 0; u < kTextureUnitCount; ++u) {
    const TextureUnit& unit = ctx.texture.units[u];
    if (!unit.anyTargetEnabled()) continue;
    const TextureObject* texture = unit.activeTexture();
    if (texture == nullptr) continue;
    const MipmapLevels m = textureLookupOf(ctx, *texture, u, batch, index).levels;
    const auto first = geometry::mipmapScaleColor(m.level1);
    const auto second = geometry::mipmapScaleColor(m.level2);
    // The two levels' colours mixed with the texels' weights (spec 3.8.8).
    for (int c = 0; c < 3; ++c) {
      rgba[c] = static_cast<std::uint8_t>(
          std::lround((1.0 - m.weight2) * first[c] + static_cast<double>(m.weight2) * second[c]));
    }
    return;
  }
  const auto grey = geometry::kMipmapUntexturedColor;
  rgba[0] = grey[0], rgba[1] = grey[1], rgba[2] = grey[2];
}

}  // namespace glass::gl
