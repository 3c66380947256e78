// The prepared 2D sampler of the fragment kernels (texture/sampler_2d.h) against the reference
// sampler (texture/texture_sampler.h): for every filter pair, wrap mode pair, a range of texture
// sizes (power of two or not, 1 x 1, wide, tall), base levels, LOD clamps, border colours and base
// formats, and coordinates that include negative, huge, infinite and NaN values and values on
// and next to texel edges, both must return the same bits.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "core/simd_dispatch.h"
#include "texture/row_sampler_2d.h"
#include "texture/sampler_2d.h"
#include "texture/texture_sampler.h"

using glass::gl::BaseFormat;
using glass::gl::lastMipmapLevel;
using glass::gl::kSampledRowPixels;
using glass::gl::Sampler2D;
using glass::gl::SimdTarget;
using glass::gl::sampleTexture;
using glass::gl::sampleTextureMagnified;
using glass::gl::TextureImage;
using glass::gl::TextureObject;

namespace {

// A small linear congruential generator: the same numbers on every machine.
struct Random {
  uint32_t state;
  uint32_t next() {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  }
  float unit() { return static_cast<float>(next()) / 16777216.0f; }  // [0, 1)
  float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

// A 2D texture of width x height from `base` with the full mipmap chain, its texels random.
std::unique_ptr<TextureObject> makeTexture(int width, int height, int base, BaseFormat format,
                                           Random& random) {
  auto texture = std::make_unique<TextureObject>();
  texture->target = GL_TEXTURE_2D;
  texture->params.baseLevel = base;
  const int last = lastMipmapLevel(base, width, height);
  for (int level = base; level <= last; ++level) {
    TextureImage& image = texture->levels[level];
    image.width = std::max(1, width >> (level - base));
    image.height = std::max(1, height >> (level - base));
    image.internalFormat = GL_RGBA;
    image.base = format;
    image.texels.resize(static_cast<size_t>(image.width) * image.height * 4);
    for (uint8_t& byte : image.texels) byte = static_cast<uint8_t>(random.next());
  }
  return texture;
}

// Coordinates that stress the addressing: ordinary ones, texel centres and edges of each level,
// negative ones, huge ones beyond the reduction limit, infinities and NaN.
std::vector<float> interestingCoordinates(Random& random, int size) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1.5f, -0.5f, 2.0f, 1e-8f, -1e-8f,
                               0.99999994f, 1.0000001f, 1048575.0f, 1048577.0f, -1048577.0f,
                               3.0e7f, -3.0e7f, 1e30f, -1e30f, inf, -inf, nan};
  for (int level = 0; (size >> level) > 0; ++level) {
    const float n = static_cast<float>(size >> level);
    for (int k = -2; k <= static_cast<int>(n) + 2 && k < 40; ++k) {
      values.push_back(static_cast<float>(k) / n);                  // texel edges
      values.push_back((static_cast<float>(k) + 0.5f) / n);         // texel centres
      values.push_back(std::nextafter(static_cast<float>(k) / n, -inf));
    }
  }
  for (int k = 0; k < 64; ++k) values.push_back(random.range(-3.0f, 4.0f));
  for (int k = 0; k < 16; ++k) values.push_back(random.range(-5000.0f, 5000.0f));
  return values;
}

bool sameBits(const float a[4], const float b[4]) { return std::memcmp(a, b, 4 * sizeof(float)) == 0; }

}  // namespace

TEST_CASE("sampler_2d_matches_reference") {
  const GLenum minFilters[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                               GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                               GL_LINEAR_MIPMAP_LINEAR};
  const GLenum magFilters[] = {GL_NEAREST, GL_LINEAR};
  const GLenum wraps[] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE,
                          GL_CLAMP_TO_BORDER};
  struct Size {
    int width, height;
  };
  const Size sizes[] = {{1, 1}, {2, 2}, {8, 8}, {16, 4}, {3, 5}, {7, 1}, {1, 6}, {64, 64}, {13, 17}};
  const float lambdas[] = {-2.0f, 0.0f, 0.25f, 0.5f, 0.75f, 1.0f, 1.5f, 2.3f, 3.999f, 7.0f, 20.0f,
                           std::numeric_limits<float>::quiet_NaN()};
  const BaseFormat formats[] = {BaseFormat::RGBA, BaseFormat::RGB, BaseFormat::Luminance,
                                BaseFormat::Alpha, BaseFormat::Intensity};
  Random random{12345u};
  long compared = 0, mismatches = 0;
  int sizeIndex = 0;
  for (const Size size : sizes) {
    const int base = (sizeIndex++ % 3 == 2) ? 1 : 0;  // some textures start at level 1
    const BaseFormat format = formats[sizeIndex % 5];
    auto texture = makeTexture(size.width, size.height, base, format, random);
    const std::vector<float> coordinates = interestingCoordinates(random, std::max(size.width, size.height));
    for (const GLenum minFilter : minFilters)
      for (const GLenum magFilter : magFilters)
        for (const GLenum wrapS : wraps)
          for (const GLenum wrapT : wraps) {
            texture->params.minFilter = minFilter;
            texture->params.magFilter = magFilter;
            texture->params.wrapS = wrapS;
            texture->params.wrapT = wrapT;
            texture->params.maxLevel = (wrapS == GL_CLAMP) ? base + 1 : 1000;  // a shorter chain
            for (int c = 0; c < 4; ++c) texture->params.borderColor[c] = random.range(-0.5f, 1.5f);
            texture->updateCompleteness();
            REQUIRE(texture->complete);
            const Sampler2D sampler(*texture);
            // Pairs of coordinates: each s with a few t's, each with a few lambdas.
            for (size_t k = 0; k < coordinates.size(); ++k) {
              const float s = coordinates[k];
              const float t = coordinates[(k * 7 + 3) % coordinates.size()];
              const float lambda = lambdas[k % std::size(lambdas)];
              float expected[4], actual[4];
              sampleTexture(*texture, s, t, lambda, expected);
              sampler.sample(s, t, lambda, actual);
              ++compared;
              if (!sameBits(expected, actual)) {
                if (++mismatches <= 10)
                  MESSAGE("sample differs: min ", minFilter, " mag ", magFilter, " wrap ", wrapS,
                          "/", wrapT, " size ", size.width, "x", size.height, " s ", s, " t ", t,
                          " lambda ", lambda, ": ", expected[0], " vs ", actual[0]);
              }
              sampleTextureMagnified(*texture, s, t, expected);
              sampler.sampleMagnified(s, t, actual);
              ++compared;
              if (!sameBits(expected, actual) && ++mismatches <= 10)
                MESSAGE("magnified sample differs: s ", s, " t ", t);
            }
          }
  }
  CHECK(compared > 500000);
  CHECK(mismatches == 0);
}

// The row sampler of the fragment kernels (texture/row_sampler_2d-inl.h), compiled for every SIMD
// target this processor runs, against Sampler2D pixel by pixel: rows of eight pixels whose four
// 2x2 quads read different levels (lambdas across level boundaries, below the switch-over point,
// NaN), with random coverage masks, coordinates in and far out of range, on textures that take
// the vector route (power-of-two GL_REPEAT, LINEAR filters) and on ones that do not.
TEST_CASE("row_sampler_2d_matches_sampler") {
  struct Case {
    int width, height, base;
    GLenum minFilter, magFilter, wrapS, wrapT;
  };
  const Case cases[] = {
      {256, 256, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {64, 16, 1, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {32, 32, 0, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {16, 64, 0, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {32, 32, 0, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {32, 32, 0, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, GL_REPEAT},
      {24, 20, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
      {32, 32, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_REPEAT},
      {1, 1, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT},
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Random random{777u};
  long compared = 0, mismatches = 0, targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::gl::simdTargetRuns(target)) continue;
    ++targets;
    for (const Case& c : cases) {
      auto texture = makeTexture(c.width, c.height, c.base, BaseFormat::RGBA, random);
      texture->params.minFilter = c.minFilter;
      texture->params.magFilter = c.magFilter;
      texture->params.wrapS = c.wrapS;
      texture->params.wrapT = c.wrapT;
      texture->updateCompleteness();
      REQUIRE(texture->complete);
      const Sampler2D sampler(*texture);
      for (int row = 0; row < 3000; ++row) {
        alignas(64) float s[kSampledRowPixels], tc[kSampledRowPixels];
        Sampler2D::LevelChoice quadChoice[kSampledRowPixels / 2];
        const float spread = row % 3 == 0 ? 2.0f : (row % 3 == 1 ? 40.0f : 3.0e6f);
        for (int i = 0; i < kSampledRowPixels; ++i) {
          s[i] = random.range(-spread, spread);
          tc[i] = random.range(-spread, spread);
          if (random.next() % 97 == 0) s[i] = nan;
        }
        if (row % 3 == 1) {
          // A row as a triangle's interior gives it: s one way in steps of up to two texels of
          // the base level, t within one texel row or across two, anywhere along the row and
          // at its right edge (the stretch read whole, and where it must not be).
          const float texel = 1.0f / static_cast<float>(c.width);
          const float step = random.range(-2.2f, 2.2f) * texel;
          const float start = random.next() % 4 == 0 ? 1.0f - random.range(0.0f, 16.0f) * texel
                                                     : random.range(-3.0f, 3.0f);
          const float t0 = random.range(-3.0f, 3.0f);
          const float tStep = random.next() % 2 == 0 ? 0.0f : random.range(-0.2f, 0.2f) / static_cast<float>(c.height);
          for (int i = 0; i < kSampledRowPixels; ++i) {
            s[i] = start + step * static_cast<float>(i);
            tc[i] = t0 + tStep * static_cast<float>(i);
          }
        }
        for (int k = 0; k < kSampledRowPixels / 2; ++k) {
          const uint32_t pick = random.next() % 8;
          const float lambda = pick == 0 ? nan : (pick == 1 ? -1.0f : random.range(-0.5f, 9.0f));
          quadChoice[k] = sampler.choose(lambda);
        }
        if (row % 5 == 0) quadChoice[1] = sampler.chooseMagnified();  // below the switch-over point
        if (row % 7 == 0)  // one level pair for the whole row, as along most rows drawn
          for (Sampler2D::LevelChoice& quad : quadChoice) quad = quadChoice[2];
        const unsigned mask = row % 4 == 0 ? 0xFFu : (random.next() & 0xFFu);
        alignas(64) float texel[4][kSampledRowPixels] = {};
        glass::gl::sampleTextureRowWith(target, sampler, s, tc, quadChoice, mask, texel);
        for (int i = 0; i < kSampledRowPixels; ++i) {
          if ((mask >> i & 1u) == 0) continue;
          float expected[4];
          const Sampler2D::LevelChoice& choice = quadChoice[i / 2];
          sampler.sampleChosen(choice, s[i], tc[i], expected);
          const float actual[4] = {texel[0][i], texel[1][i], texel[2][i], texel[3][i]};
          ++compared;
          if (!sameBits(expected, actual) && ++mismatches <= 10)
            MESSAGE("row sample differs: target ", t, " size ", c.width, "x", c.height, " s ", s[i],
                    " t ", tc[i], " level ", choice.level1, ": ", expected[0], " vs ", actual[0]);
        }
      }
    }
  }
  CHECK(targets >= 1);
  CHECK(compared > 100000);
  CHECK(mismatches == 0);
}
