// The level of detail the fragment kernels compute four quads at a time
// (texture/level_of_detail-inl.h) against the scalar levelOfDetailFromSquaredScale, bit for bit,
// on every SIMD target this machine runs; and selectMipmapLevels, whose floor and ceiling are
// conversions to int, against the specification's formulas written with std::floor and std::ceil.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/simd_dispatch.h"
#include "lcg_random.h"
#include "texture/level_of_detail.h"
#include "texture/texture_lod.h"

using glass::gl::kLevelOfDetailQuads;
using glass::gl::levelOfDetailFromSquaredScale;
using glass::gl::SimdTarget;

namespace {

struct Random : LcgRandom {
  double unit() { return static_cast<double>(next() >> 11) / 4294967296.0; }  // [0, 1)
};

// A rho^2 of every kind the kernels meet and some they should not: spread over many binades,
// exact powers of two, values at the edge of the float range, zero, infinity and NaN.
double someRhoSquared(Random& random) {
  switch (random.next() % 16) {
    case 0: return 0.0;
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return std::numeric_limits<double>::quiet_NaN();
    case 3: return std::ldexp(1.0, static_cast<int>(random.next() % 80) - 40);
    case 4: return std::ldexp(1.0 + random.unit(), -160 + static_cast<int>(random.next() % 20));  // 0 as a float
    case 5: return std::ldexp(1.0 + random.unit(), 120 + static_cast<int>(random.next() % 20));  // beyond FLT_MAX
    case 6: return std::ldexp(1.0 + random.unit(), -149 + static_cast<int>(random.next() % 24));  // float subnormals
    case 7: {  // just around sqrt(2) times a power of two, where log2 halves the mantissa
      const double m = 1.41421356237309504880 * (1.0 + (random.unit() - 0.5) * 1e-7);
      return std::ldexp(m, static_cast<int>(random.next() % 40) - 20);
    }
    default: return std::ldexp(random.unit() + 0.5, static_cast<int>(random.next() % 60) - 30);
  }
}

}  // namespace

TEST_CASE("level_of_detail_lanes_match: four quads' lambdas at once are the scalar lambdas, bit for bit, on every SIMD target") {
  struct Limits {
    float minLod, maxLod, bias;
  };
  const Limits limits[] = {
      {-1000.0f, 1000.0f, 0.0f}, {0.0f, 4.0f, 0.0f}, {-2.5f, 7.25f, 1.5f}, {2.0f, 9.0f, -16.0f},
      {3.0f, 1.0f, 0.0f},  // min above max: the scalar function's order decides
      {-1000.0f, 1000.0f, 16.0f},
  };
  Random random{{12345u}};
  long compared = 0, mismatches = 0;
  int targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::gl::simdTargetRuns(target)) continue;
    ++targets;
    for (const Limits& l : limits) {
      for (int round = 0; round < 20000; ++round) {
        alignas(64) double rhoSquared[kLevelOfDetailQuads];
        for (double& r : rhoSquared) r = someRhoSquared(random);
        float lambda[kLevelOfDetailQuads];
        glass::gl::levelsOfDetailWith(target, rhoSquared, l.minLod, l.maxLod, l.bias, lambda);
        for (int i = 0; i < kLevelOfDetailQuads; ++i) {
          const float expected = levelOfDetailFromSquaredScale(rhoSquared[i], l.minLod, l.maxLod, l.bias);
          ++compared;
          if (std::bit_cast<uint32_t>(expected) != std::bit_cast<uint32_t>(lambda[i]) && ++mismatches <= 10)
            MESSAGE("target ", t, " rho^2 ", rhoSquared[i], ": ", expected, " vs ", lambda[i]);
        }
      }
    }
  }
  CHECK(targets >= 1);
  CHECK(compared == static_cast<long>(targets) * 6 * 20000 * kLevelOfDetailQuads);
  CHECK(mismatches == 0);
}

TEST_CASE("selectMipmapLevels takes the specification's floor and ceiling of lambda") {
  // Section 3.8.8 with std::floor and std::ceil, as written there.
  auto expected = [](float lambda, GLenum filter, int base, int q) {
    glass::gl::MipmapLevels m;
    if (filter == GL_NEAREST_MIPMAP_NEAREST || filter == GL_LINEAR_MIPMAP_NEAREST) {
      int d = q;
      if (lambda <= 0.5f) d = base;
      else if (base + lambda <= q + 0.5f) d = base + static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
      m.level1 = m.level2 = std::max(base, std::min(d, q));
      return m;
    }
    if (!(base + lambda < q)) {
      m.level1 = m.level2 = q;
      return m;
    }
    const float whole = std::floor(std::max(lambda, 0.0f));
    m.level1 = std::max(base, base + static_cast<int>(whole));
    m.level2 = m.level1 >= q ? m.level1 : m.level1 + 1;
    m.weight2 = lambda < 0.0f ? 0.0f : lambda - whole;
    return m;
  };
  Random random{{99u}};
  long checked = 0;
  for (const GLenum filter : {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR}) {
    for (int base = 0; base <= 3; ++base)
      for (int q = base; q <= 13; ++q)
        for (int i = 0; i < 4000; ++i) {
          // Whole and half lambdas, the floats next to them, and values between.
          float lambda = static_cast<float>(static_cast<int>(random.next() % 40) - 10) * 0.5f;
          if (i % 3 == 1) lambda = std::nextafter(lambda, 100.0f);
          if (i % 3 == 2) lambda = std::nextafter(lambda, -100.0f);
          if (i % 5 == 4) lambda = static_cast<float>(random.unit() * 20.0 - 3.0);
          const glass::gl::MipmapLevels want = expected(lambda, filter, base, q);
          const glass::gl::MipmapLevels got = glass::gl::selectMipmapLevels(lambda, filter, base, q);
          REQUIRE(got.level1 == want.level1);
          REQUIRE(got.level2 == want.level2);
          REQUIRE(std::bit_cast<uint32_t>(got.weight2) == std::bit_cast<uint32_t>(want.weight2));
          ++checked;
        }
  }
  CHECK(checked == 2 * 4000 * (14 + 13 + 12 + 11));
}
