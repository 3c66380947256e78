// The line kernels' colour conversion (packColorColumnsWith, fragment/line_kernels.h) converts a
// vector of colours at a time, on every SIMD target; it must give floatToColorByte's bytes,
// packed as packColorBytes packs them, for every float in every lane and in the colours after the
// last whole vector: the kernels use it in place of the reference path's four scalar conversions
// per fragment. The block kernels' rows share its lanes (fragment/color_packing-inl.h).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "fragment/color_conversion.h"
#include "fragment/line_kernels.h"

using glass::gl::floatToColorByte;
using glass::gl::packColorBytes;
using glass::gl::SimdTarget;

namespace {

uint32_t packedOneByOne(const float c[4]) {
  return packColorBytes(floatToColorByte(c[0]), floatToColorByte(c[1]), floatToColorByte(c[2]),
                        floatToColorByte(c[3]));
}

}  // namespace

TEST_CASE("the line kernels' colour conversion gives floatToColorByte's bytes on every lane and target") {
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 0.3f, 0.9f, 2.0f, 1e-30f, -1e-30f,
                               std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::quiet_NaN()};
  // Every 8-bit value and the floats next to it, and next to the rounding ties between two.
  for (int i = 0; i <= 512; ++i) {
    const float v = static_cast<float>(i) / 510.0f;
    values.push_back(v);
    values.push_back(std::nextafter(v, 0.0f));
    values.push_back(std::nextafter(v, 2.0f));
  }
  values.push_back(std::nextafter(1.0f, 0.0f));
  values.push_back(std::nextafter(1.0f, 2.0f));
  std::mt19937 random(7);
  std::uniform_real_distribution<float> around(-0.25f, 1.25f);
  for (int i = 0; i < 20000; ++i) values.push_back(around(random));

  // Columns of 0 to 40 colours (up to two whole vectors of 16 and a rest), the values taken in
  // turn so that each lands in every component and position, on every target.
  const size_t n = values.size();
  int targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::gl::simdTargetRuns(target)) continue;
    ++targets;
    size_t next = 0;
    for (int round = 0; next < 4 * n; ++round) {
      constexpr int kMost = 40;
      const int count = round % (kMost + 1);
      float columns[4][kMost];
      for (int i = 0; i < count; ++i)
        for (int c = 0; c < 4; ++c) columns[c][i] = values[next++ % n];
      const float* const component[4] = {columns[0], columns[1], columns[2], columns[3]};
      uint32_t words[kMost];
      glass::gl::packColorColumnsWith(target, component, count, words);
      for (int i = 0; i < count; ++i) {
        const float c[4] = {columns[0][i], columns[1][i], columns[2][i], columns[3][i]};
        CAPTURE(t);
        CAPTURE(c[0]);
        CAPTURE(c[1]);
        CAPTURE(c[2]);
        CAPTURE(c[3]);
        REQUIRE(words[i] == packedOneByOne(c));
      }
    }
  }
  CHECK(targets >= 1);
}
