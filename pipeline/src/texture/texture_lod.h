// Level of detail: how many texels one pixel covers, and which mipmap levels that selects
// (OpenGL 1.5 specification, sections 3.8.8 "Texture Minification" and 3.8.9 "Texture
// Magnification").
//
// glass evaluates lambda per pixel, from the exact screen-space derivatives of the texture
// coordinates at the pixel centre (the rasterizer's AttributePlanes), not from differences
// across a 2x2 quad.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

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
// (The functions here run once per fragment, so they are defined inline below.)
inline double textureScaleFactorSquared(const TexCoordDerivatives& d, int width, int height) {
  const double dudx = d.dsdx * width, dudy = d.dsdy * width;
  const double dvdx = d.dtdx * height, dvdy = d.dtdy * height;
  return std::max(dudx * dudx + dvdx * dvdx, dudy * dudy + dvdy * dvdy);
}
inline double textureScaleFactor(const TexCoordDerivatives& d, int width, int height) {
  return std::sqrt(textureScaleFactorSquared(d, width, height));
}

// lambda = log2(rho), clamped to [minLod, maxLod] (equations 3.18 and 3.19), computed from
// rho^2 as log2(rho^2) / 2. rho = 0 gives minLod.
inline float levelOfDetailFromSquaredScale(double rhoSquared, float minLod, float maxLod) {
  // log2(0) is -infinity and log2(NaN) is NaN: both end at minLod, the magnification side.
  const float lambda = rhoSquared > 0.0 ? 0.5f * std::log2(static_cast<float>(rhoSquared)) : -HUGE_VALF;
  if (!(lambda > minLod)) return minLod;
  if (lambda > maxLod) return maxLod;
  return lambda;
}
inline float levelOfDetail(double rho, float minLod, float maxLod) {
  return levelOfDetailFromSquaredScale(rho * rho, minLod, maxLod);
}

// c, the switch-over point between magnification (lambda <= c) and minification (lambda > c):
// 0.5 when the magnification filter is LINEAR and the minification filter is
// NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR (the wording of the 1.2 to 2.1
// specifications), 0 otherwise. The half keeps a minified texture from looking sharper than a
// magnified one where nearest texel selection takes over from linear.
inline float magnificationSwitchOverPoint(GLenum minFilter, GLenum magFilter) {
  if (magFilter == GL_LINEAR &&
      (minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_NEAREST_MIPMAP_LINEAR))
    return 0.5f;
  return 0.0f;
}

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
inline MipmapLevels selectMipmapLevels(float lambda, GLenum minFilter, int base, int q) {
  MipmapLevels m;
  if (minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_LINEAR_MIPMAP_NEAREST) {
    int d;
    if (lambda <= 0.5f) {
      d = base;
    } else if (base + lambda <= q + 0.5f) {
      d = base + static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
    } else {
      d = q;
    }
    m.level1 = m.level2 = std::clamp(d, base, q);
    return m;
  }
  // *_MIPMAP_LINEAR.
  if (base + lambda >= q) {
    m.level1 = m.level2 = q;
    return m;
  }
  const float whole = std::floor(lambda);
  m.level1 = std::max(base, base + static_cast<int>(whole));
  m.level2 = m.level1 >= q ? m.level1 : m.level1 + 1;
  m.weight2 = lambda < 0.0f ? 0.0f : lambda - whole;
  return m;
}

}  // namespace glass::gl
