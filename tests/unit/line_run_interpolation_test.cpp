// The interpolation of a batch of line runs (rasterizer/src/line_run_interpolation.h) on every
// SIMD target this processor runs, against the evaluation of one run at a time that line.cpp
// describes, written here plainly with its branches: the same depth and the same bits of every
// varying, for segments with and without perspective, ends beyond the segment (extrapolated t),
// denominators that reach zero (exactly, too) or below (t clamped), polygon offset pushing depth out of [0, 1],
// varyings extrapolated beyond the float range, and batches of every length from 1 to kMaxRuns.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "glass/raster/depth_value.h"
#include "line_run_interpolation.h"

using glass::raster::LineRunBatch;
using glass::raster::LineRunEnds;
using glass::raster::SimdTarget;

namespace {

constexpr int kVaryings = 7;

struct Expected {
  uint32_t depth;
  float varyings[kVaryings];
};

Expected interpolateOneRun(const LineRunEnds& ends, int major) {
  double t = (major + 0.5 - ends.start) / ends.length;
  double wa = (1.0 - t) * ends.qa, wb = t * ends.qb, q = wa + wb;
  if (!(q > 0.0)) {
    t = std::clamp(t, 0.0, 1.0);
    wa = (1.0 - t) * ends.qa, wb = t * ends.qb, q = wa + wb;
  }
  Expected e;
  e.depth = glass::raster::depthValue((1.0 - t) * ends.za + t * ends.zb + ends.depthBias);
  for (int k = 0; k < kVaryings; ++k)
    e.varyings[k] = static_cast<float>((wa / q) * double(ends.varyingsA[k]) + (wb / q) * double(ends.varyingsB[k]));
  return e;
}

}  // namespace

TEST_CASE("line runs interpolate as one run at a time does, on every SIMD target") {
  std::mt19937 random(20261206);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), position(-20.0f, 300.0f);
  long runs = 0, clampedRuns = 0, zeroDenominators = 0, infiniteVaryings = 0, mismatches = 0;
  int targets = 0;
  for (int t = 0; t < static_cast<int>(SimdTarget::Count); ++t) {
    const auto target = static_cast<SimdTarget>(t);
    if (!glass::raster::simdTargetRuns(target)) continue;
    ++targets;
    for (int round = 0; round < 4000; ++round) {
      float varyingsA[kVaryings], varyingsB[kVaryings];
      // Now and then ends near the largest floats, whose extrapolation leaves the float range.
      const float scale = round % 20 == 8 ? 1.5e38f : 1.0f;
      for (int k = 0; k < kVaryings; ++k) {
        varyingsA[k] = (unit(random) * 4.0f - 2.0f) * scale;
        varyingsB[k] = (unit(random) * 4.0f - 2.0f) * scale;
      }
      LineRunEnds ends;
      const float a = position(random);
      // Segments of a pixel or less often, so that end runs extrapolate far.
      const float b = round % 4 == 0 ? a + unit(random) * 2.0f - 1.0f : position(random);
      if (a == b) continue;
      ends.start = a;
      ends.length = double(b) - ends.start;
      const bool perspective = round % 2 == 1;
      // Very different w at the two ends make the extrapolated denominator reach zero.
      ends.qa = perspective ? double(unit(random) * (round % 8 == 1 ? 100.0f : 2.0f) + 0.001f) : 1.0;
      ends.qb = perspective ? double(unit(random) * 2.0f + 0.001f) : 1.0;
      ends.za = unit(random) * 1.4f - 0.2f;
      ends.zb = unit(random) * 1.4f - 0.2f;
      ends.depthBias = round % 3 == 0 ? double(unit(random)) - 0.5 : 0.0;
      ends.varyingsA = varyingsA;
      ends.varyingsB = varyingsB;
      if (round % 50 == 7) {
        // A denominator of exactly zero at run 9: t = (9.5 - 10.5) / 2 = -0.5, 1.5 - 1.5 = 0.
        ends.start = 10.5;
        ends.length = 2.0;
        ends.qa = 1.0;
        ends.qb = 3.0;
      }

      LineRunBatch batch;
      batch.varyingCount = kVaryings;
      batch.count = 1 + round % LineRunBatch::kMaxRuns;
      int majors[LineRunBatch::kMaxRuns] = {};
      // The runs of the segment from a pixel before its start on, and junk past the count.
      const int first = static_cast<int>(std::floor(std::min(ends.start, ends.start + ends.length))) - 2;
      for (int r = 0; r < LineRunBatch::kMaxRuns; ++r) majors[r] = r < batch.count ? first + r : -77777 * r;
      glass::raster::interpolateLineRunsWith(target, ends, majors, batch);
      for (int r = 0; r < batch.count; ++r) {
        const Expected e = interpolateOneRun(ends, majors[r]);
        const double tRaw = (majors[r] + 0.5 - ends.start) / ends.length;
        const double denominator = (1.0 - tRaw) * ends.qa + tRaw * ends.qb;
        if (!(denominator > 0.0)) ++clampedRuns;
        if (denominator == 0.0) ++zeroDenominators;
        ++runs;
        if (!std::isfinite(e.varyings[0])) ++infiniteVaryings;
        bool same = batch.depth[r] == e.depth;
        for (int k = 0; k < kVaryings; ++k)
          same = same && std::bit_cast<uint32_t>(batch.varyings[k][r]) == std::bit_cast<uint32_t>(e.varyings[k]);
        if (!same) ++mismatches;
      }
    }
  }
  CHECK(targets >= 1);
  CHECK(runs > 10000);
  CHECK(clampedRuns > 100);  // the clamp is exercised
  CHECK(zeroDenominators > 10);  // and its boundary
  CHECK(infiniteVaryings > 10);  // values rounded to infinity
  CHECK(mismatches == 0);
}
