// The fixed-point arithmetic of LINEAR filtering (texture/texel_filter.h) against the real-valued
// formulas of the specification (3.8.8), and the reference sampler's lookups built on it.
#include "texture/texel_filter.h"

#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "texture/texture_object.h"
#include "texture/texture_sampler.h"

namespace tf = glass::gl::texel_filter;

namespace {

uint32_t nextRandom(uint32_t& state) {
  state = state * 1664525u + 1013904223u;
  return state >> 8;
}

}  // namespace

TEST_CASE("texel_filter_coordinate_rounds_to_256ths") {
  // U = round(256 u'): texel centres give weight 0, quarter texels 64, and the pair starts at
  // floor(u') also for negative u'.
  CHECK(tf::fixedCoordinate(0.0f) == 0);
  CHECK(tf::fixedCoordinate(3.0f) == 768);
  CHECK(tf::fixedCoordinate(3.25f) == 3 * 256 + 64);
  CHECK(tf::fixedCoordinate(-0.5f) == -128);
  CHECK(tf::wholeTexel(tf::fixedCoordinate(-0.5f)) == -1);
  CHECK(tf::subtexelWeight(tf::fixedCoordinate(-0.5f)) == 128);
  CHECK(tf::fixedCoordinate(1.0f / 512.0f) == 1);            // a half 256th rounds up
  CHECK(tf::fixedCoordinate(1.0f / 512.0f - 1e-6f) == 0);
  for (int k = -3000; k <= 3000; ++k) {
    const float u = static_cast<float>(k) / 1024.0f + 0.0001f;
    CHECK(tf::fixedCoordinate(u) == static_cast<int>(std::floor(256.0 * u + 0.5)));
  }
}

TEST_CASE("texel_filter_mixes_within_one_unit_of_the_exact_mix") {
  uint32_t state = 12345u;
  int worst = 0;
  for (int n = 0; n < 200000; ++n) {
    const int t00 = nextRandom(state) & 255, t10 = nextRandom(state) & 255;
    const int t01 = nextRandom(state) & 255, t11 = nextRandom(state) & 255;
    const int a = nextRandom(state) & 255, b = nextRandom(state) & 255;
    const int fixed = tf::mixFixed(tf::mixTexels(t00, t10, a), tf::mixTexels(t01, t11, a), tf::rowWeight(b));
    // The specification's sum with alpha = a / 256 and beta = b / 256, in 1/65280ths.
    const double exact = ((256.0 - a) * (256.0 - b) * t00 + a * (256.0 - b) * t10 +
                          (256.0 - a) * b * t01 + static_cast<double>(a) * b * t11) / 256.0;
    const int error = static_cast<int>(std::ceil(std::fabs(fixed - exact)));
    worst = std::max(worst, error);
    REQUIRE(fixed >= 0);
    REQUIRE(fixed <= tf::kFixedMax);
  }
  CHECK(worst <= 1);
  // Two levels by a 16-bit weight: the same bound, and equal values stay equal.
  for (int n = 0; n < 100000; ++n) {
    const int x0 = static_cast<int>(nextRandom(state) % (tf::kFixedMax + 1));
    const int x1 = static_cast<int>(nextRandom(state) % (tf::kFixedMax + 1));
    const int w = static_cast<int>(nextRandom(state) & 0xFFFF);
    const double exact = x0 + (x1 - x0) * (w / 65536.0);
    CHECK(std::fabs(tf::mixFixed(x0, x1, w) - exact) < 1.0);
    CHECK(tf::mixFixed(x0, x0, w) == x0);
  }
  CHECK(tf::mixFixed(1000, 5000, 0) == 1000);
  CHECK(tf::levelWeight(0.0f) == 0);
  CHECK(tf::levelWeight(0.5f) == 32768);
  CHECK(tf::levelWeight(0.99999994f) == 65535);
}

TEST_CASE("texel_filter_whole_texels_give_t_over_255") {
  for (int t = 0; t <= 255; ++t) {
    const float expected = static_cast<float>(t) * (1.0f / 255.0f);
    const float actual = tf::unitFromFixed(tf::fixedOfTexel(t));
    CHECK(std::memcmp(&expected, &actual, sizeof expected) == 0);
  }
  CHECK(tf::unitFromFixed(tf::kFixedMax) == 1.0f);
}

TEST_CASE("reference_sampler_filters_in_fixed_point") {
  // A 4 x 1 texture (REPEAT, LINEAR): texels 0, 200, 100, 255 in red.
  glass::gl::TextureObject texture;
  texture.target = GL_TEXTURE_2D;
  glass::gl::TextureImage& image = texture.levels[0];
  image.width = 4;
  image.height = 1;
  image.internalFormat = GL_RGBA;
  image.base = glass::gl::BaseFormat::RGBA;
  image.texels = {0, 0, 0, 255, 200, 0, 0, 255, 100, 0, 0, 255, 255, 0, 0, 255};
  texture.params.minFilter = GL_LINEAR;
  texture.params.magFilter = GL_LINEAR;
  texture.updateCompleteness();
  REQUIRE(texture.complete);
  float out[4];
  // u = 4 s = 0.75: u' = 0.25 between texels 0 and 1, a quarter of the way: 200 / 4 = 50.
  glass::gl::sampleTextureMagnified(texture, 0.75f / 4.0f, 0.5f, out);
  CHECK(out[0] == 50.0f * (1.0f / 255.0f));
  CHECK(out[3] == 1.0f);
  // u' = 1 + 1/3: the weight rounds to 85/256, (200 * 171 + 100 * 85) / 256 = 166.796875.
  glass::gl::sampleTextureMagnified(texture, (1.5f + 1.0f / 3.0f) / 4.0f, 0.5f, out);
  CHECK(out[0] == static_cast<float>(200 * 171 + 100 * 85) * (1.0f / 65280.0f));
  // u' = -0.5 wraps: texel 3 (255) and texel 0 (0) half and half.
  glass::gl::sampleTextureMagnified(texture, 0.0f, 0.5f, out);
  CHECK(out[0] == static_cast<float>(255 * 128) * (1.0f / 65280.0f));
  // The border colour is rounded to 8 bits, as texels are: 0.3 -> 77 (76.5 rounds up).
  texture.params.wrapS = GL_CLAMP_TO_BORDER;
  texture.params.borderColor[0] = 0.3f;
  texture.updateCompleteness();
  glass::gl::sampleTextureMagnified(texture, -1.0f, 0.5f, out);
  CHECK(out[0] == 77.0f * (1.0f / 255.0f));
}
