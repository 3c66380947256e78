#include "texture/texture_environment.h"

#include <algorithm>

namespace glass::gl {
namespace {

bool hasColor(BaseFormat base) { return base != BaseFormat::Alpha; }

bool hasAlpha(BaseFormat base) {
  return base == BaseFormat::Alpha || base == BaseFormat::LuminanceAlpha ||
         base == BaseFormat::Intensity || base == BaseFormat::RGBA;
}

}  // namespace

void applyTextureEnvironment(GLenum mode, BaseFormat base, const float texel[4],
                             const float envColor[4], float color[4]) {
  // In the stored layout, luminance and intensity already sit in R, G and B (and intensity in A),
  // so "Lt" and "It" of the tables are texel[0..2] and the colour rows read the same for every
  // base format that has colour; only which components exist differs.
  const bool c = hasColor(base);
  const bool a = hasAlpha(base);
  switch (mode) {
    case GL_REPLACE:
      if (c)
        for (int k = 0; k < 3; ++k) color[k] = texel[k];
      if (a) color[3] = texel[3];
      break;
    case GL_MODULATE:
      if (c)
        for (int k = 0; k < 3; ++k) color[k] *= texel[k];
      if (a) color[3] *= texel[3];
      break;
    case GL_DECAL:
      if (base == BaseFormat::RGB) {
        for (int k = 0; k < 3; ++k) color[k] = texel[k];
      } else if (base == BaseFormat::RGBA) {
        for (int k = 0; k < 3; ++k) color[k] = color[k] * (1.0f - texel[3]) + texel[k] * texel[3];
      }
      break;
    case GL_BLEND:
      if (c)
        for (int k = 0; k < 3; ++k) color[k] = color[k] * (1.0f - texel[k]) + envColor[k] * texel[k];
      if (base == BaseFormat::Intensity) {
        color[3] = color[3] * (1.0f - texel[3]) + envColor[3] * texel[3];
      } else if (a) {
        color[3] *= texel[3];
      }
      break;
    case GL_ADD:
      if (c)
        for (int k = 0; k < 3; ++k) color[k] = std::min(color[k] + texel[k], 1.0f);
      if (base == BaseFormat::Intensity) {
        color[3] = std::min(color[3] + texel[3], 1.0f);
      } else if (a) {
        color[3] *= texel[3];
      }
      break;
    default:
      break;
  }
}

}  // namespace glass::gl
