// The stencil and depth tests of a block row (fragment/stencil_depth_rows.h) leave every pixel's
// stencil and depth values, and give every pixel's outcome, as testStencilAndDepth does for it,
// on every SIMD target this processor runs: every pair of stencil and depth functions, every
// stencil operation in each of its three places, the tests on and off, the depth mask on and
// off, random masks and references; and they touch no pixel outside the row's mask.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "fragment/stencil_depth_rows.h"

using glass::gl::kStencilDepthRowPixels;
using glass::gl::StencilDepthOutcome;
using glass::gl::StencilDepthSettings;
using glass::raster::SimdTarget;

namespace {

constexpr GLenum kFunctions[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
constexpr GLenum kOperations[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};

// A row of stored values and fragments, with guards on both sides that nothing may change.
struct Row {
  static constexpr int kGuard = 4;
  uint8_t stencil[kGuard + kStencilDepthRowPixels + kGuard];
  uint32_t depth[kGuard + kStencilDepthRowPixels + kGuard];
  uint32_t fragment[kStencilDepthRowPixels];
  bool operator==(const Row& other) const {
    return std::memcmp(stencil, other.stencil, sizeof stencil) == 0 &&
           std::memcmp(depth, other.depth, sizeof depth) == 0;
  }
};

// Values near the ends and equal to each other often, so that every comparison goes both ways.
uint32_t depthValue(std::mt19937& random) {
  constexpr uint32_t kSpecial[] = {0u, 1u, 2u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  return random() % 2 ? kSpecial[random() % 7] : static_cast<uint32_t>(random());
}
uint8_t stencilValue(std::mt19937& random, uint8_t reference) {
  constexpr uint8_t kSpecial[] = {0, 1, 2, 127, 128, 254, 255};
  switch (random() % 3) {
    case 0: return kSpecial[random() % 7];
    case 1: return reference;
    default: return static_cast<uint8_t>(random());
  }
}

// Masks: empty, full, runs and scattered pixels.
unsigned rowMask(std::mt19937& random) {
  switch (random() % 4) {
    case 0: return random() % 8 == 0 ? 0u : 0xFFu;
    case 1: {
      const int first = static_cast<int>(random() % 8), count = 1 + static_cast<int>(random() % (8 - first));
      return ((1u << count) - 1u) << first;
    }
    default: return static_cast<unsigned>(random() & 0xFF);
  }
}

}  // namespace

TEST_CASE("stencil and depth rows test each pixel as testStencilAndDepth does, on every SIMD target") {
  std::mt19937 random(40105);
  int targets = 0;
  long rows = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    ++targets;
    CAPTURE(t);
    int combination = 0;
    for (const GLenum stencilFunc : kFunctions) {
      for (const GLenum depthFunc : kFunctions) {
        for (int k = 0; k < 8; ++k, ++combination) {
          StencilDepthSettings s;
          s.stencilTest = combination % 4 != 3;
          s.depthTest = combination % 5 != 4;
          s.depthMask = combination % 3 != 2;
          s.stencilFunc = stencilFunc;
          s.depthFunc = depthFunc;
          s.stencilFail = kOperations[k];
          s.stencilDepthFail = kOperations[(k + 3) % 8];
          s.stencilDepthPass = kOperations[(k + 5) % 8];
          s.stencilRef = static_cast<uint8_t>(random() % 3 == 0 ? 255 : random());
          s.stencilValueMask = random() % 2 ? 0xFFu : static_cast<unsigned>(random() & 0xFF);
          s.stencilWriteMask = random() % 2 ? 0xFFu : static_cast<unsigned>(random());
          CAPTURE(s.stencilTest);
          CAPTURE(s.depthTest);
          CAPTURE(s.depthMask);
          CAPTURE(stencilFunc);
          CAPTURE(depthFunc);
          CAPTURE(k);
          for (int n = 0; n < 6; ++n) {
            Row before;
            for (uint8_t& v : before.stencil) v = stencilValue(random, s.stencilRef);
            for (uint32_t& v : before.depth) v = depthValue(random);
            for (int i = 0; i < kStencilDepthRowPixels; ++i)
              before.fragment[i] = random() % 3 == 0 ? before.depth[Row::kGuard + i] : depthValue(random);
            const unsigned mask = rowMask(random);

            Row expected = before;
            unsigned expectedPassed = 0;
            for (int i = 0; i < kStencilDepthRowPixels; ++i) {
              if (!(mask >> i & 1u)) continue;
              uint8_t* stencil = s.stencilTest ? &expected.stencil[Row::kGuard + i] : nullptr;
              uint32_t* depth = s.depthTest ? &expected.depth[Row::kGuard + i] : nullptr;
              if (glass::gl::testStencilAndDepth(s, stencil, depth, expected.fragment[i]) == StencilDepthOutcome::Passed)
                expectedPassed |= 1u << i;
            }
            Row got = before;
            const unsigned passed = glass::gl::testStencilAndDepthRowWith(
                target, s, s.stencilTest ? got.stencil + Row::kGuard : nullptr,
                s.depthTest ? got.depth + Row::kGuard : nullptr, got.fragment, mask);
            CAPTURE(mask);
            REQUIRE(passed == expectedPassed);
            REQUIRE(got == expected);
            ++rows;
          }
        }
      }
    }
  }
  CHECK(targets >= 1);
  MESSAGE(targets << " targets, " << rows << " rows compared");
}
