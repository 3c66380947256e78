#include "texture/texture_sampler.h"

#include <algorithm>
#include <cmath>

#include "texture/depth_comparison.h"
#include "texture/texel_addressing.h"

namespace glass::gl {
namespace {

struct LevelLookup {
  const TextureImage* image;
  GLenum wrapS, wrapT;
  bool twoD;
  const float* border;  // the border texel, components in [0, 255]
  int slice = 0;        // the slice of a 3D image the 2D lookups read
  const DepthLookup* depth = nullptr;  // a depth texture's values or comparisons
};

// Texel (i, j) with components in [0, 255] (the scale to [0, 1] is applied once per lookup).
const float* fetchTexel(const LevelLookup& l, int i, int j, float scratch[4]) {
  if (l.depth != nullptr) return depthTexel(*l.depth, *l.image, i, j, scratch);
  if (i < 0 || i >= l.image->width || j < 0 || j >= l.image->height) return l.border;
  const uint8_t* texel = l.image->texel(i, j, l.slice);
  for (int c = 0; c < 4; ++c) scratch[c] = static_cast<float>(texel[c]);
  return scratch;
}

void sampleNearest(const LevelLookup& l, float s, float t, float out[4]) {
  const int width = l.image->width;
  const float u = texelCoordinate(s, width, l.wrapS);
  const int i = wrapTexelIndex(static_cast<int>(std::floor(u)), width, l.wrapS, false);
  int j = 0;
  if (l.twoD) {
    const int height = l.image->height;
    const float v = texelCoordinate(t, height, l.wrapT);
    j = wrapTexelIndex(static_cast<int>(std::floor(v)), height, l.wrapT, false);
  }
  float scratch[4];
  const float* texel = fetchTexel(l, i, j, scratch);
  for (int c = 0; c < 4; ++c) out[c] = texel[c] * (1.0f / 255.0f);
}

void sampleLinear(const LevelLookup& l, float s, float t, float out[4]) {
  const int width = l.image->width;
  const float u = texelCoordinate(s, width, l.wrapS) - 0.5f;
  const float uFloor = std::floor(u);
  const float alpha = u - uFloor;
  int i0, i1;
  wrapTexelPair(static_cast<int>(uFloor), width, l.wrapS, &i0, &i1);
  float a[4], b[4];
  if (!l.twoD) {
    const float* t0 = fetchTexel(l, i0, 0, a);
    const float* t1 = fetchTexel(l, i1, 0, b);
    for (int c = 0; c < 4; ++c) out[c] = ((1.0f - alpha) * t0[c] + alpha * t1[c]) * (1.0f / 255.0f);
    return;
  }
  const int height = l.image->height;
  const float v = texelCoordinate(t, height, l.wrapT) - 0.5f;
  const float vFloor = std::floor(v);
  const float beta = v - vFloor;
  int j0, j1;
  wrapTexelPair(static_cast<int>(vFloor), height, l.wrapT, &j0, &j1);
  const float w00 = (1.0f - alpha) * (1.0f - beta), w10 = alpha * (1.0f - beta);
  const float w01 = (1.0f - alpha) * beta, w11 = alpha * beta;
  if (l.depth == nullptr && i0 >= 0 && i1 >= 0 && j0 >= 0 && j1 >= 0 && i0 < width && i1 < width && j0 < height && j1 < height) {
    // All four texels inside the image (always so except near a CLAMP or CLAMP_TO_BORDER edge):
    // read the bytes directly.
    const uint8_t* p00 = l.image->texel(i0, j0, l.slice);
    const uint8_t* p10 = l.image->texel(i1, j0, l.slice);
    const uint8_t* p01 = l.image->texel(i0, j1, l.slice);
    const uint8_t* p11 = l.image->texel(i1, j1, l.slice);
    for (int c = 0; c < 4; ++c)
      out[c] = (w00 * p00[c] + w10 * p10[c] + w01 * p01[c] + w11 * p11[c]) * (1.0f / 255.0f);
    return;
  }
  float c00[4], c10[4], c01[4], c11[4];
  const float* t00 = fetchTexel(l, i0, j0, c00);
  const float* t10 = fetchTexel(l, i1, j0, c10);
  const float* t01 = fetchTexel(l, i0, j1, c01);
  const float* t11 = fetchTexel(l, i1, j1, c11);
  for (int c = 0; c < 4; ++c)
    out[c] = (w00 * t00[c] + w10 * t10[c] + w01 * t01[c] + w11 * t11[c]) * (1.0f / 255.0f);
}

// A 3D lookup (spec 3.8.8 with the third axis): NEAREST reads slice k = wrap(floor(w)),
// LINEAR mixes the bilinear lookups of slices k0 = wrap(floor(w - 1/2)) and k1 = wrap(k0 + 1) by
// gamma = frac(w - 1/2), w = r * depth; a slice outside the image is the border colour.
void sampleVolume(LevelLookup l, bool linear, float s, float t, float r, GLenum wrapR,
                  float out[4]) {
  const int depth = l.image->depth;
  auto sampleSlice = [&](int k, float result[4]) {
    if (k < 0 || k >= depth) {
      for (int c = 0; c < 4; ++c) result[c] = l.border[c] * (1.0f / 255.0f);
      return;
    }
    l.slice = k;
    if (linear) {
      sampleLinear(l, s, t, result);
    } else {
      sampleNearest(l, s, t, result);
    }
  };
  if (!linear) {
    const float w = texelCoordinate(r, depth, wrapR);
    sampleSlice(wrapTexelIndex(static_cast<int>(std::floor(w)), depth, wrapR, false), out);
    return;
  }
  const float w = texelCoordinate(r, depth, wrapR) - 0.5f;
  const float wFloor = std::floor(w);
  const float gamma = w - wFloor;
  int k0, k1;
  wrapTexelPair(static_cast<int>(wFloor), depth, wrapR, &k0, &k1);
  float a[4], b[4];
  sampleSlice(k0, a);
  sampleSlice(k1, b);
  for (int c = 0; c < 4; ++c) out[c] = (1.0f - gamma) * a[c] + gamma * b[c];
}

void sampleLevel(const TextureObject& texture, int face, int level, bool linear, float s, float t,
                 float r, float out[4]) {
  DepthLookup depth;
  const bool isDepth = depthLookupOf(texture, r, &depth);
  const LevelLookup l{&texture.image(face, level), texture.params.wrapS, texture.params.wrapT,
                      texture.target != GL_TEXTURE_1D, texture.sampling.border, 0,
                      isDepth ? &depth : nullptr};
  if (texture.target == GL_TEXTURE_3D) {
    sampleVolume(l, linear, s, t, r, texture.params.wrapR, out);
  } else if (linear) {
    sampleLinear(l, s, t, out);
  } else {
    sampleNearest(l, s, t, out);
  }
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
  sampleLevel(texture, face, texture.params.baseLevel, texture.params.magFilter == GL_LINEAR, s, t,
              r, out);
}

void sampleTexture(const TextureObject& texture, float s, float t, float lambda, float out[4],
                   int face, float r) {
  const SamplerParameters& p = texture.params;
  if (lambda <= texture.sampling.switchOverPoint) {
    sampleTextureMagnified(texture, s, t, out, face, r);
    return;
  }
  switch (p.minFilter) {
    case GL_NEAREST:
      sampleLevel(texture, face, p.baseLevel, false, s, t, r, out);
      return;
    case GL_LINEAR:
      sampleLevel(texture, face, p.baseLevel, true, s, t, r, out);
      return;
    default:
      break;
  }
  const bool linearWithinLevel = p.minFilter == GL_LINEAR_MIPMAP_NEAREST || p.minFilter == GL_LINEAR_MIPMAP_LINEAR;
  const MipmapLevels m = selectMipmapLevels(lambda, p.minFilter, p.baseLevel, texture.lastLevel);
  sampleLevel(texture, face, m.level1, linearWithinLevel, s, t, r, out);
  if (m.level2 == m.level1 || m.weight2 == 0.0f) return;
  float second[4];
  sampleLevel(texture, face, m.level2, linearWithinLevel, s, t, r, second);
  for (int c = 0; c < 4; ++c) out[c] = (1.0f - m.weight2) * out[c] + m.weight2 * second[c];
}

}  // namespace glass::gl
