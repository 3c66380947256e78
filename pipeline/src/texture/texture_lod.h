// Level of detail: how many texels one pixel covers, and which mipmap levels that selects
// (OpenGL 1.5 specification, sections 3.8.8 "Texture Minification" and 3.8.9 "Texture
// Magnification").
//
// glass computes one lambda per 2x2 pixel quad, from the differences of the texture coordinates
// between the quad's pixels (quadTexCoordDifferences below), as Mesa's llvmpipe does.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "glass/raster/fragment.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl {

// Screen-space derivatives of the texture coordinates s and t (already divided by q), or the
// differences across a pixel quad that stand in for them.
struct TexCoordDerivatives {
  double dsdx = 0.0, dsdy = 0.0;
  double dtdx = 0.0, dtdy = 0.0;
};

// The 2x2 pixel quad that shares one level of detail.
//
// Section 3.8.8 lets an implementation approximate rho (the derivatives of u and v enter only
// through it). glass uses the approximation of Mesa's llvmpipe, the renderer the image tests
// compare with, so that mipmap level boundaries fall on the same pixels: the window is cut into
// 2x2 quads, and every fragment of a quad takes the quad's lambda, computed from differences of
// the texture coordinates between the quad's pixel centres (covered by the primitive or not):
//   du/dx ~ u(upper right) - u(upper left),   du/dy ~ u(upper left) - u(lower left),
// and the same for v; the lower-right pixel is not used.
//
// llvmpipe pairs rows from the top of the window (it renders a window's top row first, and
// OSMesa turns the picture the right way up afterwards), so glass pairs them the same way: with
// an even window height the quads are {2i, 2i + 1} x {2j, 2j + 1} in window coordinates; with an
// odd height the bottom row pairs with the row below the window.
struct PixelQuad {
  int left;  // window x of the quad's left column
  int top;   // window y of the quad's upper row; the lower row is top - 1
};
inline PixelQuad pixelQuadOf(int x, int y, int windowHeight) {
  const int rowFromTop = windowHeight - 1 - y;
  return {x & ~1, windowHeight - 1 - (rowFromTop & ~1)};
}

// The differences of s/q and t/q across `quad` (see PixelQuad), from the triangle's attribute
// planes. The planes give s/w, t/w and q/w as affine functions A, C, B of window (x, y), so the
// projected coordinate at a pixel centre is s/q = A / B (the 1/w cancels). With A and B taken at
// the upper-left centre (a and b below), the right neighbour has A + A_x, B + B_x and the lower
// one A - A_y, B - B_y, so
//   s/q(right) - s/q(upper left) = (A + A_x)/(B + B_x) - A/B = (A_x B - A B_x) / (B (B + B_x)),
//   s/q(upper left) - s/q(lower) = A/B - (A - A_y)/(B - B_y) = (A_y B - A B_y) / (B (B - B_y)):
// the same differences, without the cancellation of subtracting two nearly equal quotients.
// s, t and q are the varying indices of the coordinates; t is skipped unless withT.
inline TexCoordDerivatives quadTexCoordDifferences(const raster::AttributePlanes& planes, int s,
                                                   int t, int q, PixelQuad quad, bool withT) {
  const double x = quad.left + 0.5, y = quad.top + 0.5;  // the upper-left pixel centre
  const double a = planes.a0[s] + planes.dx[s] * x + planes.dy[s] * y;
  const double b = planes.a0[q] + planes.dx[q] * x + planes.dy[q] * y;
  const double bx = planes.dx[q], by = planes.dy[q];
  const double inverseRight = 1.0 / (b * (b + bx));
  const double inverseLower = 1.0 / (b * (b - by));
  TexCoordDerivatives d;
  d.dsdx = (planes.dx[s] * b - a * bx) * inverseRight;
  d.dsdy = (planes.dy[s] * b - a * by) * inverseLower;
  if (withT) {
    const double c = planes.a0[t] + planes.dx[t] * x + planes.dy[t] * y;
    d.dtdx = (planes.dx[t] * b - c * bx) * inverseRight;
    d.dtdy = (planes.dy[t] * b - c * by) * inverseLower;
  }
  return d;
}

// The scale factor rho (equation 3.21 with the 2D terms): with u = s * width and v = t * height
// of the base level image,
//   rho = max( sqrt((du/dx)^2 + (dv/dx)^2), sqrt((du/dy)^2 + (dv/dy)^2) ),
// the full Euclidean lengths, as llvmpipe computes them by default (it has the cheaper
// max-of-absolute-values form of the specification behind a switch that is off).
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

// GL_MAX_TEXTURE_LOD_BIAS, Mesa's llvmpipe's value.
inline constexpr float kMaxTextureLodBias = 16.0f;

// lambda = log2(rho) + bias, clamped to [minLod, maxLod] (equations 3.18 and 3.19; OpenGL 1.4
// adds the bias, the sum of the unit's and the texture's GL_TEXTURE_LOD_BIAS clamped to
// +-GL_MAX_TEXTURE_LOD_BIAS), computed from rho^2 as log2(rho^2) / 2. rho = 0 gives minLod.
inline float levelOfDetailFromSquaredScale(double rhoSquared, float minLod, float maxLod,
                                           float bias = 0.0f) {
  // log2(0) is -infinity and log2(NaN) is NaN: both end at minLod, the magnification side.
  const float lambda =
      rhoSquared > 0.0 ? 0.5f * portable::log2(static_cast<float>(rhoSquared)) + bias : -HUGE_VALF;
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
// floor(x) for 0 <= x < 2^31 and ceil(x) for 0 < x < 2^31, exact: the conversion to int
// truncates, which is the floor of a non-negative number. (std::floor and std::ceil are calls
// into the C library on baseline x86-64, which has no rounding instruction; selectMipmapLevels
// runs once per pixel quad.)
inline int floorOfNonNegative(float x) { return static_cast<int>(x); }
inline int ceilOfPositive(float x) {
  const int whole = static_cast<int>(x);
  return static_cast<float>(whole) < x ? whole + 1 : whole;
}

[[gnu::always_inline]] inline MipmapLevels selectMipmapLevels(float lambda, GLenum minFilter, int base, int q) {
  MipmapLevels m;
  if (minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_LINEAR_MIPMAP_NEAREST) {
    int d;
    if (lambda <= 0.5f) {
      d = base;
    } else if (base + lambda <= q + 0.5f) {
      d = base + ceilOfPositive(lambda + 0.5f) - 1;
    } else {
      d = q;
    }
    m.level1 = m.level2 = std::clamp(d, base, q);
    return m;
  }
  // *_MIPMAP_LINEAR. A NaN lambda (from NaN or infinite coordinates) takes the last level, as
  // it does in the branch above; it must not reach the conversion to int below.
  if (!(base + lambda < q)) {
    m.level1 = m.level2 = q;
    return m;
  }
  // A negative lambda reads the base level alone (weight2 = 0); its floor is not converted.
  const float whole = static_cast<float>(floorOfNonNegative(std::max(lambda, 0.0f)));
  m.level1 = std::max(base, base + static_cast<int>(whole));
  m.level2 = m.level1 >= q ? m.level1 : m.level1 + 1;
  m.weight2 = lambda < 0.0f ? 0.0f : lambda - whole;
  return m;
}

}  // namespace glass::gl
