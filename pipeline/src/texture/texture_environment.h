// The texture environment of one texture unit: how the unit's filtered texel combines with the
// colour the previous unit passed on (OpenGL 1.5 specification, section 3.8.13, tables 3.22 to
// 3.25).
//
// With Cf, Af the incoming colour, Ct, At (or Lt, It) the texel, Cc, Ac the environment colour:
//   base format      REPLACE        MODULATE            DECAL                      BLEND                          ADD
//   ALPHA            Cf, At         Cf, Af At           (Cf, Af)                   Cf, Af At                      Cf, Af At
//   LUMINANCE        Lt, Af         Cf Lt, Af           (Cf, Af)                   Cf(1-Lt)+Cc Lt, Af             Cf+Lt, Af
//   LUMINANCE_ALPHA  Lt, At         Cf Lt, Af At        (Cf, Af)                   Cf(1-Lt)+Cc Lt, Af At          Cf+Lt, Af At
//   INTENSITY        It, It         Cf It, Af It        (Cf, Af)                   Cf(1-It)+Cc It, Af(1-It)+Ac It Cf+It, Af+It
//   RGB              Ct, Af         Cf Ct, Af           Ct, Af                     Cf(1-Ct)+Cc Ct, Af             Cf+Ct, Af
//   RGBA             Ct, At         Cf Ct, Af At        Cf(1-At)+Ct At, Af         Cf(1-Ct)+Cc Ct, Af At          Cf+Ct, Af At
// DECAL is undefined for the first four base formats; glass leaves the fragment unchanged there,
// as Mesa does. ADD results are clamped to [0, 1]. GL_COMBINE is texture_combine.h.
#pragma once

#include <GL/gl.h>

#include <algorithm>

#include "texture/texture_image.h"

namespace glass::gl {

// glTexEnv state of one unit (table 6.19 and its defaults), and the unit's level-of-detail bias
// (GL_TEXTURE_FILTER_CONTROL, OpenGL 1.4).
struct TextureEnvironment {
  GLenum mode = GL_MODULATE;
  float color[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  // GL_COMBINE (OpenGL 1.3 and 1.4, section 3.8.13): functions, three sources and operands each
  // for RGB and alpha, and the scales (1, 2 or 4).
  GLenum combineRGB = GL_MODULATE;
  GLenum combineAlpha = GL_MODULATE;
  GLenum sourceRGB[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum sourceAlpha[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum operandRGB[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  GLenum operandAlpha[3] = {GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgbScale = 1.0f;
  float alphaScale = 1.0f;
  float lodBias = 0.0f;  // glTexEnv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS)
};

// Whether a base format has colour (R, G, B) and alpha components (table 3.15).
inline bool baseFormatHasColor(BaseFormat base) { return base != BaseFormat::Alpha; }

inline bool baseFormatHasAlpha(BaseFormat base) {
  return base == BaseFormat::Alpha || base == BaseFormat::LuminanceAlpha ||
         base == BaseFormat::Intensity || base == BaseFormat::RGBA;
}

// Combines `texel` (in the layout of texture_image.h) into `color` (the incoming colour, RGBA in
// [0, 1]) in place, for the modes REPLACE, MODULATE, DECAL, BLEND and ADD. Inline: the fragment
// kernels call it for every pixel.
inline void applyTextureEnvironment(GLenum mode, BaseFormat base, const float texel[4],
                                    const float envColor[4], float color[4]) {
  // In the stored layout, luminance and intensity already sit in R, G and B (and intensity in A),
  // so "Lt" and "It" of the tables are texel[0..2] and the colour rows read the same for every
  // base format that has colour; only which components exist differs.
  const bool c = baseFormatHasColor(base);
  const bool a = baseFormatHasAlpha(base);
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
