// The block rows of the triangle walk (rasterizer/src/block_rows.h) on every SIMD target this
// processor runs, for triangles and convex quadrilaterals, against a plain evaluation of each
// pixel: the edge functions at its centre,
// depthValue of its depth, passesDepthCompare against the stored value. And the stored depth
// range of whole block rows against std::min and std::max.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "block_rows.h"
#include "edge_functions.h"
#include "glass/raster/depth_value.h"
#include "glass/raster/triangle.h"

using glass::raster::BlockRows;
using glass::raster::CoveredBlock;
using glass::raster::DepthCompare;
using glass::raster::SimdTarget;

namespace {

constexpr int kSize = CoveredBlock::kSize;

// A depth plane value at a row or column: mostly in [0, 1], some beyond either end (polygon
// offset can push a depth out), some NaN.
double someDepthPart(std::mt19937_64& random) {
  std::uniform_real_distribution<double> spread(-0.25, 0.75);
  switch (random() % 16) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return 2.0;
    case 2: return -1.0;
    default: return spread(random);
  }
}

}  // namespace

TEST_CASE("block rows give each pixel's coverage, depth and early test on every SIMD target") {
  std::mt19937_64 random(20261205);
  constexpr int kFramebufferWidth = 32, kFramebufferHeight = 24;
  long pixels = 0, covered = 0, passed = 0, onEdges = 0, mismatches = 0, quads = 0;
  int targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    ++targets;
    for (int round = 0; round < 3000; ++round) {
      // A triangle around the block at (8, 8), up to a few blocks wide, with its corners on
      // pixel centres and corners half the time, so that edges pass exactly through centres
      // (the fill rule's ties) in every direction; every third round a convex quadrilateral,
      // its corners on a circle.
      std::uniform_real_distribution<float> position(0.0f, 24.0f);
      glass::raster::WindowVertex v[4] = {};
      const bool onGrid = round % 2 == 0, quad = round % 3 == 2;
      if (quad) {
        double angles[4];
        for (double& a : angles) a = std::uniform_real_distribution<double>(0.0, 6.283185307179586)(random);
        std::sort(angles, angles + 4);
        for (int c = 0; c < 4; ++c) {
          const float x = static_cast<float>(12.0 + 12.0 * std::cos(angles[c]));
          const float y = static_cast<float>(12.0 + 12.0 * std::sin(angles[c]));
          v[c].x = onGrid ? std::round(2.0f * x) / 2.0f : x;
          v[c].y = onGrid ? std::round(2.0f * y) / 2.0f : y;
        }
      } else {
        for (auto& vertex : v) {
          vertex.x = onGrid ? static_cast<float>(random() % 49) / 2.0f : position(random);
          vertex.y = onGrid ? static_cast<float>(random() % 49) / 2.0f : position(random);
        }
      }
      glass::raster::TriangleSettings settings;
      settings.bounds = {0, 0, kFramebufferWidth, kFramebufferHeight};
      glass::raster::TriangleSetup setup;
      if (quad ? !glass::raster::setupQuad(v[0], v[1], v[2], v[3], settings, setup)
               : !glass::raster::setupTriangle(v[0], v[1], v[2], settings, setup))
        continue;
      const int edgeCount = setup.edgeCount;
      quads += quad;
      // The edge functions at pixel centres, of the triangle's three edges or the quadrilateral's four.
      int64_t stepX[4], stepY[4], atOrigin[4];
      auto takeEdges = [&](const auto& functions) {
        for (int k = 0; k < edgeCount; ++k) {
          stepX[k] = functions.stepX[k];
          stepY[k] = functions.stepY[k];
          atOrigin[k] = functions.atOrigin[k];
        }
      };
      if (quad) {
        takeEdges(glass::raster::PixelEdgeFunctions<4>(setup));
      } else {
        takeEdges(glass::raster::PixelEdgeFunctions<3>(setup));
      }
      auto edgeAt = [&](int k, int x, int y) { return stepX[k] * x + stepY[k] * y + atOrigin[k]; };
      alignas(64) int64_t columnSteps[4][kSize];
      for (int k = 0; k < edgeCount; ++k)
        for (int i = 0; i < kSize; ++i) columnSteps[k][i] = stepX[k] * i;

      const int bx = 8, by = 8;
      const int i0 = static_cast<int>(random() % kSize), i1 = i0 + 1 + static_cast<int>(random() % (kSize - i0));
      const int j0 = static_cast<int>(random() % kSize), j1 = j0 + 1 + static_cast<int>(random() % (kSize - j0));
      double depthColumn[kSize], depthRow[kSize];
      for (double& d : depthColumn) d = someDepthPart(random);
      for (double& d : depthRow) d = someDepthPart(random);
      // Stored depths near the fragments' own, so that every comparison meets equal values.
      std::vector<uint32_t> stored(kFramebufferWidth * kFramebufferHeight);
      for (int y = 0; y < kFramebufferHeight; ++y)
        for (int x = 0; x < kFramebufferWidth; ++x) {
          const int i = std::clamp(x - bx, 0, kSize - 1), j = std::clamp(y - by, 0, kSize - 1);
          const int64_t near = glass::raster::depthValue(depthColumn[i] + depthRow[j]);
          const int64_t value = near + static_cast<int64_t>(random() % 5) - 2;
          stored[y * kFramebufferWidth + x] = static_cast<uint32_t>(std::clamp<int64_t>(value, 0, glass::raster::kDepthMax));
        }

      BlockRows rows;
      rows.edgeCount = edgeCount;
      for (int k = 0; k < edgeCount; ++k) {
        rows.rowStart[k] = edgeAt(k, bx, by + j0);
        rows.stepY[k] = stepY[k];
      }
      rows.columnStep = columnSteps;
      rows.accepted = random() % 8 == 0;  // as if every centre were inside: the mask is the box's
      rows.columns = (0xFFu << i0) & (0xFFu >> (kSize - i1));
      rows.firstRow = j0;
      rows.endRow = j1;
      rows.depthColumn = depthColumn;
      rows.depthRow = depthRow;
      const bool test = random() % 4 != 0;
      rows.stored = test ? stored.data() + by * kFramebufferWidth + bx : nullptr;
      rows.storedStride = kFramebufferWidth;
      rows.storedWhole = random() % 2 == 0;
      rows.compare = static_cast<DepthCompare>(random() % 8);

      CoveredBlock block;
      std::fill(&block.rowMask[0], &block.rowMask[0] + kSize, uint8_t{0xA5});  // must be overwritten
      const bool any = glass::raster::coverBlockRowsWith(target, rows, block);
      bool expectedAny = false;
      for (int j = 0; j < kSize; ++j) {
        unsigned expectedMask = 0;
        for (int i = 0; i < kSize; ++i) {
          if (j < j0 || j >= j1 || i < i0 || i >= i1) continue;
          ++pixels;
          bool inside = rows.accepted;
          if (!inside) {
            inside = true;
            for (int k = 0; k < edgeCount; ++k) {
              const int64_t e = edgeAt(k, bx + i, by + j);
              if (e < 0) inside = false;
              if (e == 0 || e == -1) ++onEdges;  // a centre on an edge, owned or not
            }
          }
          if (!inside) continue;
          ++covered;
          const uint32_t depth = glass::raster::depthValue(depthColumn[i] + depthRow[j]);
          if (test &&
              !glass::raster::passesDepthCompare(rows.compare, depth, stored[(by + j) * kFramebufferWidth + bx + i]))
            continue;
          ++passed;
          expectedMask |= 1u << i;
          if (block.depth[j][i] != depth && ++mismatches <= 10)
            MESSAGE("target ", t, " round ", round, " pixel ", i, ",", j, ": depth ", depth, " vs ", block.depth[j][i]);
        }
        if (block.rowMask[j] != expectedMask && ++mismatches <= 10)
          MESSAGE("target ", t, " round ", round, " row ", j, ": mask ", expectedMask, " vs ", int(block.rowMask[j]));
        expectedAny |= expectedMask != 0;
      }
      if (any != expectedAny) ++mismatches;
    }
  }
  CHECK(targets >= 1);
  CHECK(quads > 500 * targets);
  // The cases are not degenerate: many pixels covered, many of those passing, many not.
  CHECK(covered > pixels / 8);
  CHECK(passed > covered / 8);
  CHECK(passed < covered);
  CHECK(onEdges > pixels / 1000);
  CHECK(mismatches == 0);
}

TEST_CASE("the stored depth range of block rows, all columns or some, is their minimum and maximum on every SIMD target") {
  std::mt19937_64 random(7);
  long mismatches = 0, compared = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    for (int round = 0; round < 2000; ++round) {
      constexpr int kStride = 13;
      std::vector<uint32_t> stored(kStride * kSize);
      const uint32_t spread = round % 3 == 0 ? 3u : glass::raster::kDepthMax + 1;
      for (uint32_t& value : stored) value = static_cast<uint32_t>(random() % spread);
      const int rowCount = 1 + static_cast<int>(random() % kSize);
      // Whole rows (blockDepthRange), or a run of columns as a small triangle's box cuts a
      // block (blockColumnsDepthRange, every column one time in eight); the columns outside the
      // run hold random depths too, which must not count.
      const bool whole = round % 2 == 0;
      const int first = whole || round % 16 == 1 ? 0 : static_cast<int>(random() % kSize);
      const int end = whole || round % 16 == 1 ? kSize : first + 1 + static_cast<int>(random() % (kSize - first));
      const unsigned columns = (0xFFu << first) & (0xFFu >> (kSize - end));
      uint32_t lowest = 0, highest = 0;
      if (whole)
        glass::raster::blockDepthRangeWith(target, stored.data(), kStride, rowCount, lowest, highest);
      else
        glass::raster::blockColumnsDepthRangeWith(target, stored.data(), kStride, rowCount, columns, lowest, highest);
      uint32_t expectedLowest = glass::raster::kDepthMax, expectedHighest = 0;
      for (int r = 0; r < rowCount; ++r)
        for (int i = first; i < end; ++i) {
          expectedLowest = std::min(expectedLowest, stored[r * kStride + i]);
          expectedHighest = std::max(expectedHighest, stored[r * kStride + i]);
        }
      ++compared;
      if (lowest != expectedLowest || highest != expectedHighest) ++mismatches;
    }
  }
  CHECK(compared >= 2000);
  CHECK(mismatches == 0);
}
