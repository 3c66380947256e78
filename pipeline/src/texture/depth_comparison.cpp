#include "texture/depth_comparison.h"

#include <algorithm>

namespace glass::gl {
namespace {

BaseFormat baseFormatOfDepthMode(GLenum mode) {
  switch (mode) {
    case GL_INTENSITY: return BaseFormat::Intensity;
    case GL_ALPHA: return BaseFormat::Alpha;
    default: return BaseFormat::Luminance;
  }
}

// `r func D_t` for the eight comparison functions (table 3.22a of OpenGL 1.5).
bool comparisonPasses(GLenum func, float r, float depth) {
  switch (func) {
    case GL_LEQUAL: return r <= depth;
    case GL_GEQUAL: return r >= depth;
    case GL_LESS: return r < depth;
    case GL_GREATER: return r > depth;
    case GL_EQUAL: return r == depth;
    case GL_NOTEQUAL: return r != depth;
    case GL_ALWAYS: return true;
    default: return false;  // GL_NEVER
  }
}

}  // namespace

bool depthLookupOf(const TextureObject& texture, float r, DepthLookup* lookup) {
  if (!texture.baseImage().isDepth()) return false;
  const SamplerParameters& p = texture.params;
  lookup->compare = p.compareMode == GL_COMPARE_R_TO_TEXTURE;
  lookup->func = p.compareFunc;
  lookup->reference = r == r ? std::clamp(r, 0.0f, 1.0f) : 0.0f;
  lookup->borderDepth = std::clamp(p.borderColor[0], 0.0f, 1.0f);
  lookup->base = baseFormatOfDepthMode(p.depthTextureMode);
  return true;
}

const float* depthTexel(const DepthLookup& lookup, const TextureImage& image, int i, int j,
                        float scratch[4]) {
  const bool inside = i >= 0 && i < image.width && j >= 0 && j < image.height;
  const float depth = inside ? image.depths[image.texelIndex(i, j, 0)] : lookup.borderDepth;
  const float value =
      lookup.compare ? (comparisonPasses(lookup.func, lookup.reference, depth) ? 255.0f : 0.0f)
                     : depth * 255.0f;
  switch (lookup.base) {
    case BaseFormat::Intensity: scratch[0] = scratch[1] = scratch[2] = scratch[3] = value; break;
    case BaseFormat::Alpha:
      scratch[0] = scratch[1] = scratch[2] = 0.0f;
      scratch[3] = value;
      break;
    default:
      scratch[0] = scratch[1] = scratch[2] = value;
      scratch[3] = 255.0f;
      break;
  }
  return scratch;
}

BaseFormat environmentBaseFormat(const TextureObject& texture) {
  const TextureImage& base = texture.baseImage();
  return base.isDepth() ? baseFormatOfDepthMode(texture.params.depthTextureMode) : base.base;
}

}  // namespace glass::gl
