// The depths the triangle walk computes for a block row in vector lanes (rasterizer/src/
// block_rows.h), on every SIMD target, against depthValue itself (glass/raster/depth_value.h):
// the same value for depths inside and outside [0, 1], at and next to the rounding halves,
// infinities and NaN.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "block_rows.h"
#include "glass/raster/depth_value.h"

using glass::raster::depthValue;
using glass::raster::kDepthMax;

TEST_CASE("depth_value_lanes_match") {
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
  // Eight depths a block: each is a column's part of the plane, the row's part is 0 (adding 0.0
  // changes no value but -0.0's sign, which depthValue does not see); every centre is covered.
  constexpr int kSize = glass::raster::CoveredBlock::kSize;
  const int64_t noStep[3][kSize] = {};
  const double rowParts[kSize] = {};
  long mismatches = 0, compared = 0;
  for (int t = 0; t < static_cast<int>(glass::raster::SimdTarget::Count); ++t) {
    const auto target = static_cast<glass::raster::SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    for (std::size_t n = 0; n + kSize <= depths.size(); n += kSize) {
      glass::raster::BlockRows rows{};
      rows.columnStep = noStep;
      rows.accepted = true;
      rows.columns = 0xFFu;
      rows.firstRow = 0;
      rows.endRow = 1;
      rows.depthColumn = &depths[n];
      rows.depthRow = rowParts;
      rows.stored = nullptr;
      glass::raster::CoveredBlock block;
      glass::raster::coverBlockRowsWith(target, rows, block);
      for (int i = 0; i < kSize; ++i, ++compared)
        if (block.depth[0][i] != depthValue(depths[n + i])) ++mismatches;
    }
  }
  CHECK(depths.size() > 100000);
  CHECK(compared >= static_cast<long>(depths.size()) - kSize);
  CHECK(mismatches == 0);
}
