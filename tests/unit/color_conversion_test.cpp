// packColorFloats (fragment/color_conversion.h) converts four components on the lanes of one
// vector; it must give floatToColorByte's bytes, packed as packColorBytes packs them, for every
// float: the line kernels use it in place of the reference path's four scalar conversions.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "fragment/color_conversion.h"

using glass::gl::floatToColorByte;
using glass::gl::packColorBytes;
using glass::gl::packColorFloats;

namespace {

uint32_t packedOneByOne(const float c[4]) {
  return packColorBytes(floatToColorByte(c[0]), floatToColorByte(c[1]), floatToColorByte(c[2]),
                        floatToColorByte(c[3]));
}

}  // namespace

TEST_CASE("packColorFloats gives floatToColorByte's bytes on every lane") {
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

  // Each value in each lane, beside the values before it.
  for (size_t i = 0; i < values.size(); ++i) {
    const float c[4] = {values[i], values[(i + 1) % values.size()], values[(i + 2) % values.size()],
                        values[(i + 3) % values.size()]};
    CAPTURE(values[i]);
    REQUIRE(packColorFloats(c) == packedOneByOne(c));
  }
}
