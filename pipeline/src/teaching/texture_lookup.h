// Which mipmap levels a fragment's texture lookup reads, and how many texels of each: what the
// mipmap view shows and what GLASS_STATS counts, found the way applyTexturing samples
// (texture/texture_hooks.cpp, texture_sampler.cpp).
#pragma once

#include "glass/raster/fragment.h"
#include "texture/texture_lod.h"

namespace glass::gl {

struct Context;
struct TextureObject;

struct TextureLookup {
  MipmapLevels levels;     // level2 == level1 when one level is read
  int levelsRead = 1;      // 2 when a *_MIPMAP_LINEAR lookup mixes two levels
  int texelsPerLevel = 1;  // 1 nearest; 2, 4, 8 linear in 1D, 2D (and cube faces), 3D
};

// The lookup of `texture`, bound to texture unit `unit`, for fragment `index` of the batch:
// lambda of its pixel quad (spec 3.8.8) decides between magnification (lambda <= c, the base
// level with the magnification filter, spec 3.8.9) and minification. Points and lines carry no
// derivatives and are magnified, as applyTexturing samples them. Cube maps are taken as
// magnified (the base level): their lambda is not computed here.
TextureLookup textureLookupOf(const Context& ctx, const TextureObject& texture, int unit,
                              const raster::FragmentBatch& batch, int index);

}  // namespace glass::gl
