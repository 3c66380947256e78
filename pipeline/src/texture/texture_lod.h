// Level of detail: how many texels one pixel covers, and which mipmap levels that selects
// (OpenGL 1.5 specification, sections 3.8.8 "Texture Minification" and 3.8.9 "Texture
// Magnification").
//
// glass evaluates lambda per pixel, from the exact screen-space derivatives of the texture
// coordinates at the pixel centre (the rasterizer's AttributePlanes), not from differences
// across a 2x2 quad.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

// Screen-space derivatives of the texture coordinates s and t (already divided by q).
struct TexCoordDerivatives {
  double dsdx = 0.0, dsdy = 0.0;
  double dtdx = 0.0, dtdy = 0.0;
};

// The scale factor rho (equation 3.21 with the 2D terms): with u = s * width and v = t * height
// of the base level image,
//   rho = max( sqrt((du/dx)^2 + (dv/dx)^2), sqrt((du/dy)^2 + (dv/dy)^2) ).
// A one-dimensional texture passes height = 0 (v is identically zero).
double textureScaleFactor(const TexCoordDerivatives& d, int width, int height);

// lambda = log2(rho), clamped to [minLod, maxLod] (equations 3.18 and 3.19). rho = 0 gives
// minLod.
float levelOfDetail(double rho, float minLod, float maxLod);

// c, the switch-over point between magnification (lambda <= c) and minification (lambda > c):
// 0.5 when the magnification filter is LINEAR and the minification filter is
// NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR (the wording of the 1.2 to 2.1
// specifications), 0 otherwise. The half keeps a minified texture from looking sharper than a
// magnified one where nearest texel selection takes over from linear.
float magnificationSwitchOverPoint(GLenum minFilter, GLenum magFilter);

// The mipmap levels a minifying lookup reads (section 3.8.8, "Mipmapping"), for lambda > c.
// base is TEXTURE_BASE_LEVEL and q the last level of the complete mipmap chain.
//   *_MIPMAP_NEAREST: one level d:
//      d = base                         if lambda <= 1/2
//        = base + ceil(lambda + 1/2) - 1 if lambda > 1/2 and base + lambda <= q + 1/2
//        = q                             otherwise
//   *_MIPMAP_LINEAR: two levels, d1 = base + floor(lambda) (q if base + lambda >= q) and
//      d2 = d1 + 1 (d1 if d1 >= q), mixed as (1 - frac(lambda)) * tau1 + frac(lambda) * tau2.
struct MipmapLevels {
  int level1 = 0;
  int level2 = 0;
  float weight2 = 0.0f;  // the share of level2
};
MipmapLevels selectMipmapLevels(float lambda, GLenum minFilter, int base, int q);

}  // namespace glass::gl
