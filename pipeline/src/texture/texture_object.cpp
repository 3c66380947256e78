#include "texture/texture_object.h"

#include <algorithm>
#include <cmath>

#include "texture/texture_lod.h"
#include "texture/texture_sampler.h"

namespace glass::gl {

bool isMipmapFilter(GLenum minFilter) {
  return minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_LINEAR_MIPMAP_NEAREST ||
         minFilter == GL_NEAREST_MIPMAP_LINEAR || minFilter == GL_LINEAR_MIPMAP_LINEAR;
}

int lastMipmapLevel(int base, int width, int height, int depth) {
  int size = std::max({width, height, depth});
  int p = base;
  while (size > 1) {
    size /= 2;
    ++p;
  }
  return std::min(p, kMaxTextureLevels - 1);
}

void TextureObject::updateCompleteness() {
  complete = false;
  lastLevel = params.baseLevel;
  const int base = params.baseLevel;
  if (base < 0 || base >= kMaxTextureLevels) return;
  const TextureImage& b = levels[base];
  if (!b.defined()) return;
  // Spec 3.8.10, "cube complete": the six base images are defined, square, of one size, one
  // internal format and one border.
  for (int face = 1; face < faceCount(); ++face) {
    const TextureImage& f = image(face, base);
    if (!f.defined() || f.width != b.width || f.height != b.height ||
        f.internalFormat != b.internalFormat || f.border != b.border)
      return;
  }
  float border[4];
  borderTexel(*this, border);
  for (int c = 0; c < 4; ++c) sampling.borderBytes[c] = static_cast<uint8_t>(std::round(border[c] * 255.0f));
  sampling.switchOverPoint = magnificationSwitchOverPoint(params.minFilter, params.magFilter);
  if (!isMipmapFilter(params.minFilter)) {
    complete = true;
    return;
  }
  if (params.maxLevel < base) return;
  const int q = std::min(lastMipmapLevel(base, b.width, b.height, b.depth), params.maxLevel);
  for (int face = 0; face < faceCount(); ++face) {
    for (int i = base + 1; i <= q; ++i) {
      const TextureImage& level = image(face, i);
      const int shift = i - base;
      const int w = std::max(1, b.width >> shift);
      const int h = std::max(1, b.height >> shift);
      const int d = std::max(1, b.depth >> shift);
      if (level.width != w || level.height != h || level.depth != d ||
          level.internalFormat != b.internalFormat ||
          level.border != b.border)
        return;
    }
  }
  lastLevel = q;
  complete = true;
}

}  // namespace glass::gl
