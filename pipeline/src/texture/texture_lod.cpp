#include "texture/texture_lod.h"

#include <algorithm>
#include <cmath>

namespace glass::gl {

double textureScaleFactor(const TexCoordDerivatives& d, int width, int height) {
  const double dudx = d.dsdx * width, dudy = d.dsdy * width;
  const double dvdx = d.dtdx * height, dvdy = d.dtdy * height;
  const double rx = std::sqrt(dudx * dudx + dvdx * dvdx);
  const double ry = std::sqrt(dudy * dudy + dvdy * dvdy);
  return std::max(rx, ry);
}

float levelOfDetail(double rho, float minLod, float maxLod) {
  // log2(0) is -infinity and log2(NaN) is NaN: both end at minLod, the magnification side.
  const double lambda = rho > 0.0 ? std::log2(rho) : -HUGE_VAL;
  if (!(lambda > minLod)) return minLod;
  if (lambda > maxLod) return maxLod;
  return static_cast<float>(lambda);
}

float magnificationSwitchOverPoint(GLenum minFilter, GLenum magFilter) {
  if (magFilter == GL_LINEAR &&
      (minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_NEAREST_MIPMAP_LINEAR))
    return 0.5f;
  return 0.0f;
}

MipmapLevels selectMipmapLevels(float lambda, GLenum minFilter, int base, int q) {
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
    m.weight2 = 0.0f;
    return m;
  }
  // *_MIPMAP_LINEAR.
  if (base + lambda >= q) {
    m.level1 = m.level2 = q;
    m.weight2 = 0.0f;
    return m;
  }
  const float whole = std::floor(lambda);
  m.level1 = std::max(base, base + static_cast<int>(whole));
  m.level2 = m.level1 >= q ? m.level1 : m.level1 + 1;
  m.weight2 = lambda < 0.0f ? 0.0f : lambda - whole;
  return m;
}

}  // namespace glass::gl
