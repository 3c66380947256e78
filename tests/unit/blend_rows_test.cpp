// The blend rows (fragment/blend_rows.h) give blend()'s bytes for every pixel, on every SIMD
// target this processor runs: every equation, every pair of colour factors with alpha factors
// of their own (the same ones, too), random blend colours and random pixels; and the copies
// compiled for the common settings over every source alpha and destination byte.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "fragment/blend_rows.h"

using glass::gl::blend;
using glass::gl::BlendRow;
using glass::gl::BlendSettings;
using glass::gl::kBlendRowPixels;
using glass::raster::SimdTarget;

namespace {

constexpr GLenum kSourceFactors[] = {
    GL_ZERO,           GL_ONE,           GL_SRC_COLOR,      GL_ONE_MINUS_SRC_COLOR,   GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,       GL_ONE_MINUS_DST_ALPHA,
    GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
    GL_SRC_ALPHA_SATURATE};
// GL_SRC_ALPHA_SATURATE is a source factor only.
constexpr int kDestinationFactorCount = sizeof kSourceFactors / sizeof kSourceFactors[0] - 1;
constexpr GLenum kEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

struct Row {
  uint32_t source[kBlendRowPixels], destination[kBlendRowPixels];
};

// The row against blend() pixel by pixel; false at the first difference.
bool rowMatches(BlendRow row, const BlendSettings& settings, const Row& pixels) {
  uint32_t got[kBlendRowPixels];
  row(settings, pixels.source, pixels.destination, got);
  for (int p = 0; p < kBlendRowPixels; ++p) {
    uint8_t s[4], d[4], expected[4];
    std::memcpy(s, &pixels.source[p], 4);
    std::memcpy(d, &pixels.destination[p], 4);
    blend(settings, s, d, expected);
    if (std::memcmp(expected, &got[p], 4) != 0) return false;
  }
  return true;
}

Row randomRow(std::mt19937& random) {
  Row r;
  for (int p = 0; p < kBlendRowPixels; ++p) {
    r.source[p] = static_cast<uint32_t>(random());
    r.destination[p] = static_cast<uint32_t>(random());
  }
  return r;
}

}  // namespace

TEST_CASE("blend rows give blend()'s bytes on every SIMD target") {
  std::mt19937 random(61206);
  std::uniform_int_distribution<int> byte(0, 255), factor(0, kDestinationFactorCount);
  int targets = 0;
  long rows = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    ++targets;
    CAPTURE(t);
    for (const GLenum equation : kEquations) {
      for (const GLenum srcRGB : kSourceFactors) {
        for (int k = 0; k < kDestinationFactorCount; ++k) {
          BlendSettings b;
          b.equation = equation;
          b.srcRGB = srcRGB;
          b.dstRGB = kSourceFactors[k];
          // Alpha factors: the colour ones half the time, others chosen at random otherwise.
          const bool sameAlpha = random() % 2 == 0;
          b.srcAlpha = sameAlpha ? srcRGB : kSourceFactors[factor(random)];
          b.dstAlpha = sameAlpha ? b.dstRGB : kSourceFactors[factor(random) % kDestinationFactorCount];
          for (uint8_t& c : b.constant) c = static_cast<uint8_t>(byte(random));
          CAPTURE(equation);
          CAPTURE(b.srcRGB);
          CAPTURE(b.dstRGB);
          CAPTURE(b.srcAlpha);
          CAPTURE(b.dstAlpha);
          const BlendRow row = glass::gl::blendRowFor(target, b);
          for (int i = 0; i < 8; ++i) {
            REQUIRE(rowMatches(row, b, randomRow(random)));
            ++rows;
          }
        }
      }
    }
    // The compiled copies, over rows whose source alphas and destination bytes run through
    // all 256 x 256 pairs (the other bytes random).
    BlendSettings general;
    general.srcRGB = general.srcAlpha = GL_CONSTANT_ALPHA;
    for (const glass::gl::CommonBlend& common : glass::gl::kCommonBlends) {
      BlendSettings b;
      b.srcRGB = b.srcAlpha = common.source;
      b.dstRGB = b.dstAlpha = common.destination;
      for (uint8_t& c : b.constant) c = static_cast<uint8_t>(byte(random));
      CAPTURE(b.srcRGB);
      CAPTURE(b.dstRGB);
      const BlendRow row = glass::gl::blendRowFor(target, b);
      CHECK((row != glass::gl::blendRowFor(target, general)));  // a copy of its own
      for (int alpha = 0; alpha < 256; ++alpha) {
        for (int value = 0; value < 256; value += kBlendRowPixels) {
          Row r = randomRow(random);
          for (int p = 0; p < kBlendRowPixels; ++p) {
            r.destination[p] = static_cast<uint32_t>(value + p) * 0x01010101u;
            uint8_t s[4];
            std::memcpy(s, &r.source[p], 4);
            s[3] = static_cast<uint8_t>(alpha);
            std::memcpy(&r.source[p], s, 4);
          }
          REQUIRE(rowMatches(row, b, r));
          ++rows;
        }
      }
    }
  }
  CHECK(targets >= 1);
  MESSAGE(targets << " targets, " << rows << " rows compared");
}
