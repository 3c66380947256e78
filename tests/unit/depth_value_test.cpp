// depthValuePair, the two-lane form of depthValue the triangle walk uses for whole rows
// (glass/raster/depth_value.h), against depthValue itself: the same value for depths inside and
// outside [0, 1], at and next to the rounding halves, infinities and NaN.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "glass/raster/depth_value.h"

using glass::raster::depthValue;
using glass::raster::depthValuePair;
using glass::raster::kDepthMax;

TEST_CASE("depth_value_pairs_match") {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> depths = {0.0, -0.0, 1.0, 0.5, -1e-300, 1e-300, 1.0 + 1e-15, -0.25, 2.0, 1e30,
                                -1e30, inf, -inf, std::numeric_limits<double>::quiet_NaN()};
  // Around the halfway points between stored values, where the rounding decides.
  for (uint32_t k = 0; k < kDepthMax; k += 9973) {
    const double half = (k + 0.5) / double(kDepthMax);
    depths.push_back(half);
    depths.push_back(std::nextafter(half, 0.0));
    depths.push_back(std::nextafter(half, 1.0));
  }
  uint64_t state = 12345;
  for (int n = 0; n < 100000; ++n) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    depths.push_back(-0.5 + 2.0 * static_cast<double>(state >> 11) / 9007199254740992.0);
  }
  long mismatches = 0;
  for (std::size_t n = 0; n + 1 < depths.size(); ++n) {
    const double pair[2] = {depths[n], depths[n + 1]};
    uint32_t values[2];
    depthValuePair(pair, values);
    if (values[0] != depthValue(pair[0]) || values[1] != depthValue(pair[1])) ++mismatches;
  }
  CHECK(depths.size() > 100000);
  CHECK(mismatches == 0);
}
