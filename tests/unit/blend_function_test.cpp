// blendFunctionFor (fragment/blending.h) gives, for the settings programs use most, a copy of
// blend() compiled with the equation and factors fixed; the fast paths and the reference path
// blend through it. Each must give blend()'s bytes for every source and destination.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "fragment/blending.h"

using glass::gl::blend;
using glass::gl::BlendFunction;
using glass::gl::blendFunctionFor;
using glass::gl::BlendSettings;

namespace {

BlendSettings adding(GLenum source, GLenum destination) {
  BlendSettings b;
  b.srcRGB = b.srcAlpha = source;
  b.dstRGB = b.dstAlpha = destination;
  b.equation = GL_FUNC_ADD;
  return b;
}

// The chosen function against blend() on every pair of source alpha and destination value (with
// the other components random), then on random pixels; the number of pixels compared.
int compareWithBlend(const BlendSettings& settings, std::mt19937& random) {
  const BlendFunction chosen = blendFunctionFor(settings);
  std::uniform_int_distribution<int> byte(0, 255);
  int compared = 0;
  auto compare = [&](const uint8_t s[4], const uint8_t d[4]) {
    uint8_t expected[4], got[4];
    blend(settings, s, d, expected);
    chosen(settings, s, d, got);
    REQUIRE(std::memcmp(expected, got, sizeof got) == 0);
    ++compared;
  };
  for (int alpha = 0; alpha < 256; ++alpha) {
    for (int value = 0; value < 256; ++value) {
      uint8_t s[4], d[4];
      for (int c = 0; c < 4; ++c) {
        s[c] = static_cast<uint8_t>(byte(random));
        d[c] = static_cast<uint8_t>(value);
      }
      s[3] = static_cast<uint8_t>(alpha);
      compare(s, d);
    }
  }
  for (int i = 0; i < 100000; ++i) {
    uint8_t s[4], d[4];
    for (int c = 0; c < 4; ++c) {
      s[c] = static_cast<uint8_t>(byte(random));
      d[c] = static_cast<uint8_t>(byte(random));
    }
    compare(s, d);
  }
  return compared;
}

}  // namespace

TEST_CASE("the blend function chosen for a setting gives blend()'s bytes") {
  std::mt19937 random(20261206);
  // The settings with a compiled copy: each must have one (or this test would compare blend()
  // with itself).
  const BlendSettings compiled[] = {
      adding(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), adding(GL_ONE, GL_ONE_MINUS_SRC_ALPHA),
      adding(GL_SRC_ALPHA, GL_ONE),                 adding(GL_ONE, GL_ONE),
      adding(GL_DST_COLOR, GL_ZERO),                adding(GL_ZERO, GL_SRC_COLOR),
  };
  for (const BlendSettings& settings : compiled) {
    CAPTURE(settings.srcRGB);
    CAPTURE(settings.dstRGB);
    const bool compiledCopy = blendFunctionFor(settings) != &blend;
    CHECK(compiledCopy);
    for (const uint8_t constant : {uint8_t{0}, uint8_t{77}, uint8_t{255}}) {
      BlendSettings withConstant = settings;
      std::memset(withConstant.constant, constant, sizeof withConstant.constant);
      CHECK(compareWithBlend(withConstant, random) > 100000);
    }
  }
  // Other settings blend through blend() itself, and so give its bytes.
  BlendSettings subtracting = adding(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  subtracting.equation = GL_FUNC_REVERSE_SUBTRACT;
  BlendSettings separateAlpha = adding(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  separateAlpha.srcAlpha = GL_ONE;
  BlendSettings constantColor = adding(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
  constantColor.constant[0] = 10, constantColor.constant[1] = 128, constantColor.constant[2] = 250;
  for (const BlendSettings& settings : {subtracting, separateAlpha, constantColor}) {
    const bool byBlend = blendFunctionFor(settings) == &blend;
    CHECK(byBlend);
    CHECK(compareWithBlend(settings, random) > 100000);
  }
}
