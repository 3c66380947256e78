#include "texture/texture_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "texture/depth_comparison.h"
#include "texture/texel_addressing.h"
#include "texture/texel_filter.h"

namespace glass::gl {
namespace {

struct LevelLookup {
  const TextureImage* image;
  GLenum wrapS, wrapT;
  bool twoD;
  const TextureObject::Sampling* sampling;  // the border texel
  int slice = 0;                            // the slice of a 3D image the 2D lookups read
};

// A colour lookup's result: components in texel_filter's fixed point (0 .. 65280 for 0 .. 1).
using FixedTexel = std::array<int, 4>;

// Texel (i, j) of a colour image, or the border texel outside it.
const uint8_t* colourTexel(const LevelLookup& l, int i, int j) {
  if (i < 0 || i >= l.image->width || j < 0 || j >= l.image->height) return l.sampling->borderBytes;
  return l.image->texel(i, j, l.slice);
}

// A whole texel (or the border's) as a filtered value.
FixedTexel unfilteredTexel(const uint8_t* texel) {
  FixedTexel out;
  for (int c = 0; c < 4; ++c) out[c] = texel_filter::fixedOfTexel(texel[c]);
  return out;
}

FixedTexel nearestColour(const LevelLookup& l, float s, float t) {
  const int width = l.image->width;
  const int i = wrapTexelIndex(floorToInt(texelCoordinate(s, width, l.wrapS)), width, l.wrapS, false);
  int j = 0;
  if (l.twoD) {
    const int height = l.image->height;
    j = wrapTexelIndex(floorToInt(texelCoordinate(t, height, l.wrapT)), height, l.wrapT, false);
  }
  return unfilteredTexel(colourTexel(l, i, j));
}

// The start of the LINEAR pair along one axis and its 8-bit weight (texel_filter.h).
struct LinearPair {
  int i0, i1, weight;
};
LinearPair linearPair(float s, int size, GLenum mode) {
  const int fixed = texel_filter::fixedCoordinate(texelCoordinate(s, size, mode) - 0.5f);
  LinearPair p;
  wrapTexelPair(texel_filter::wholeTexel(fixed), size, mode, &p.i0, &p.i1);
  p.weight = texel_filter::subtexelWeight(fixed);
  return p;
}

FixedTexel linearColour(const LevelLookup& l, float s, float t) {
  using texel_filter::mixTexels;
  const LinearPair u = linearPair(s, l.image->width, l.wrapS);
  FixedTexel out;
  if (!l.twoD) {
    const uint8_t* t0 = colourTexel(l, u.i0, 0);
    const uint8_t* t1 = colourTexel(l, u.i1, 0);
    for (int c = 0; c < 4; ++c) out[c] = mixTexels(t0[c], t1[c], u.weight);
    return out;
  }
  const LinearPair v = linearPair(t, l.image->height, l.wrapT);
  const uint8_t* t00 = colourTexel(l, u.i0, v.i0);
  const uint8_t* t10 = colourTexel(l, u.i1, v.i0);
  const uint8_t* t01 = colourTexel(l, u.i0, v.i1);
  const uint8_t* t11 = colourTexel(l, u.i1, v.i1);
  for (int c = 0; c < 4; ++c)
    out[c] = texel_filter::mixFixed(mixTexels(t00[c], t10[c], u.weight), mixTexels(t01[c], t11[c], u.weight),
                                    texel_filter::rowWeight(v.weight));
  return out;
}

FixedTexel mixColours(const FixedTexel& a, const FixedTexel& b, int weight) {
  FixedTexel out;
  for (int c = 0; c < 4; ++c) out[c] = texel_filter::mixFixed(a[c], b[c], weight);
  return out;
}

// A 3D lookup (spec 3.8.8 with the third axis): NEAREST reads slice k = wrap(floor(w)),
// LINEAR mixes the bilinear lookups of slices k0 = wrap(floor(w - 1/2)) and k1 = wrap(k0 + 1) by
// gamma = frac(w - 1/2), w = r * depth; a slice outside the image is the border colour.
FixedTexel volumeColour(LevelLookup l, bool linear, float s, float t, float r, GLenum wrapR) {
  const int depth = l.image->depth;
  auto sampleSlice = [&](int k) {
    if (k < 0 || k >= depth) return unfilteredTexel(l.sampling->borderBytes);
    l.slice = k;
    return linear ? linearColour(l, s, t) : nearestColour(l, s, t);
  };
  if (!linear) return sampleSlice(wrapTexelIndex(floorToInt(texelCoordinate(r, depth, wrapR)), depth, wrapR, false));
  const LinearPair w = linearPair(r, depth, wrapR);
  return mixColours(sampleSlice(w.i0), sampleSlice(w.i1), texel_filter::rowWeight(w.weight));
}

FixedTexel levelColour(const TextureObject& texture, int face, int level, bool linear, float s, float t, float r) {
  const LevelLookup l{&texture.image(face, level), texture.params.wrapS, texture.params.wrapT,
                      texture.target != GL_TEXTURE_1D, &texture.sampling};
  if (texture.target == GL_TEXTURE_3D) return volumeColour(l, linear, s, t, r, texture.params.wrapR);
  return linear ? linearColour(l, s, t) : nearestColour(l, s, t);
}

// Depth textures (1D or 2D) filter their values in float: texel values are depths or comparison
// results (depth_comparison.h), components in [0, 255].
void depthNearest(const DepthLookup& d, const TextureImage& image, bool twoD, GLenum wrapS, GLenum wrapT,
                  float s, float t, float out[4]) {
  const int i = wrapTexelIndex(floorToInt(texelCoordinate(s, image.width, wrapS)), image.width, wrapS, false);
  const int j = twoD ? wrapTexelIndex(floorToInt(texelCoordinate(t, image.height, wrapT)), image.height, wrapT, false) : 0;
  float scratch[4];
  const float* texel = depthTexel(d, image, i, j, scratch);
  for (int c = 0; c < 4; ++c) out[c] = texel[c] * (1.0f / 255.0f);
}

void depthLinear(const DepthLookup& d, const TextureImage& image, bool twoD, GLenum wrapS, GLenum wrapT,
                 float s, float t, float out[4]) {
  const float u = texelCoordinate(s, image.width, wrapS) - 0.5f;
  const float uFloor = std::floor(u);
  const float alpha = u - uFloor;
  int i0, i1;
  wrapTexelPair(static_cast<int>(uFloor), image.width, wrapS, &i0, &i1);
  float a[4], b[4];
  if (!twoD) {
    const float* t0 = depthTexel(d, image, i0, 0, a);
    const float* t1 = depthTexel(d, image, i1, 0, b);
    for (int c = 0; c < 4; ++c) out[c] = ((1.0f - alpha) * t0[c] + alpha * t1[c]) * (1.0f / 255.0f);
    return;
  }
  const float v = texelCoordinate(t, image.height, wrapT) - 0.5f;
  const float vFloor = std::floor(v);
  const float beta = v - vFloor;
  int j0, j1;
  wrapTexelPair(static_cast<int>(vFloor), image.height, wrapT, &j0, &j1);
  const float w00 = (1.0f - alpha) * (1.0f - beta), w10 = alpha * (1.0f - beta);
  const float w01 = (1.0f - alpha) * beta, w11 = alpha * beta;
  float c00[4], c10[4], c01[4], c11[4];
  const float* t00 = depthTexel(d, image, i0, j0, c00);
  const float* t10 = depthTexel(d, image, i1, j0, c10);
  const float* t01 = depthTexel(d, image, i0, j1, c01);
  const float* t11 = depthTexel(d, image, i1, j1, c11);
  for (int c = 0; c < 4; ++c)
    out[c] = (w00 * t00[c] + w10 * t10[c] + w01 * t01[c] + w11 * t11[c]) * (1.0f / 255.0f);
}

void depthLevel(const TextureObject& texture, const DepthLookup& d, int level, bool linear, float s, float t,
                float out[4]) {
  const bool twoD = texture.target != GL_TEXTURE_1D;
  (linear ? depthLinear : depthNearest)(d, texture.image(0, level), twoD, texture.params.wrapS,
                                        texture.params.wrapT, s, t, out);
}

// The levels a lookup reads (spec 3.8.8 and 3.8.9): one level, or two mixed by weight2.
struct LevelsRead {
  int level1, level2 = -1;
  float weight2 = 0.0f;
  bool linear;
};
LevelsRead levelsRead(const TextureObject& texture, float lambda) {
  const SamplerParameters& p = texture.params;
  if (lambda <= texture.sampling.switchOverPoint) return {p.baseLevel, -1, 0.0f, p.magFilter == GL_LINEAR};
  if (p.minFilter == GL_NEAREST || p.minFilter == GL_LINEAR) return {p.baseLevel, -1, 0.0f, p.minFilter == GL_LINEAR};
  const bool linearWithinLevel = p.minFilter == GL_LINEAR_MIPMAP_NEAREST || p.minFilter == GL_LINEAR_MIPMAP_LINEAR;
  const MipmapLevels m = selectMipmapLevels(lambda, p.minFilter, p.baseLevel, texture.lastLevel);
  const bool mixes = m.level2 != m.level1 && m.weight2 != 0.0f;
  return {m.level1, mixes ? m.level2 : -1, m.weight2, linearWithinLevel};
}

void sampleLevels(const TextureObject& texture, const LevelsRead& read, float s, float t, float out[4], int face,
                  float r) {
  DepthLookup depth;
  if (depthLookupOf(texture, r, &depth)) {
    depthLevel(texture, depth, read.level1, read.linear, s, t, out);
    if (read.level2 < 0) return;
    float second[4];
    depthLevel(texture, depth, read.level2, read.linear, s, t, second);
    for (int c = 0; c < 4; ++c) out[c] = (1.0f - read.weight2) * out[c] + read.weight2 * second[c];
    return;
  }
  FixedTexel colour = levelColour(texture, face, read.level1, read.linear, s, t, r);
  if (read.level2 >= 0)
    colour = mixColours(colour, levelColour(texture, face, read.level2, read.linear, s, t, r),
                        texel_filter::levelWeight(read.weight2));
  for (int c = 0; c < 4; ++c) out[c] = texel_filter::unitFromFixed(colour[c]);
}

}  // namespace

void borderTexel(const TextureObject& texture, float out[4]) {
  const float* b = texture.params.borderColor;
  const float r = std::clamp(b[0], 0.0f, 1.0f), g = std::clamp(b[1], 0.0f, 1.0f);
  const float bl = std::clamp(b[2], 0.0f, 1.0f), a = std::clamp(b[3], 0.0f, 1.0f);
  switch (texture.baseImage().base) {
    case BaseFormat::Alpha: out[0] = out[1] = out[2] = 0.0f; out[3] = a; break;
    case BaseFormat::Luminance: out[0] = out[1] = out[2] = r; out[3] = 1.0f; break;
    case BaseFormat::LuminanceAlpha: out[0] = out[1] = out[2] = r; out[3] = a; break;
    case BaseFormat::Intensity: out[0] = out[1] = out[2] = out[3] = r; break;
    case BaseFormat::RGB: out[0] = r; out[1] = g; out[2] = bl; out[3] = 1.0f; break;
    case BaseFormat::RGBA: out[0] = r; out[1] = g; out[2] = bl; out[3] = a; break;
  }
}

void sampleTextureMagnified(const TextureObject& texture, float s, float t, float out[4],
                            int face, float r) {
  const LevelsRead base{texture.params.baseLevel, -1, 0.0f, texture.params.magFilter == GL_LINEAR};
  sampleLevels(texture, base, s, t, out, face, r);
}

void sampleTexture(const TextureObject& texture, float s, float t, float lambda, float out[4],
                   int face, float r) {
  sampleLevels(texture, levelsRead(texture, lambda), s, t, out, face, r);
}

}  // namespace glass::gl
