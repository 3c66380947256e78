// The depth and varyings of a batch of line runs (glass/raster/line_run.h), all its runs at once,
// as lanes of vectors. Compiled for every SIMD target (glass/raster/simd_target.h); each gives
// the values of the one-run-at-a-time evaluation line.cpp describes to the bit (the same IEEE
// operations in the same order on each lane, selects where that evaluation branches), which the
// unit test line_run_interpolation compares run by run on every target.
#pragma once

#include "glass/raster/line_run.h"
#include "glass/raster/simd_target.h"

namespace glass::raster {

// A segment's ends, as the interpolation along its major axis reads them.
struct LineRunEnds {
  double start, length;  // the major coordinate of end a, and b's minus a's
  double qa, qb;         // the ends' 1/w, or 1 and 1 without perspective correction
  double za, zb;         // the ends' window depths
  double depthBias;      // polygon offset's, added before the conversion
  const float* varyingsA;
  const float* varyingsB;
};

// The most runs interpolated as one vector (a divisor of LineRunBatch::kMaxRuns).
inline constexpr int kLineRunLanes = 16;
static_assert(LineRunBatch::kMaxRuns % kLineRunLanes == 0);

// For runs r < batch.count, at major coordinates majors[r], sets batch.depth[r] and
// batch.varyings[k][r] for k < batch.varyingCount:
//   t = (majors[r] + 0.5 - start) / length, clamped to [0, 1] where (1 - t) qa + t qb <= 0 (or
//       is NaN), as it is not otherwise;
//   wa = (1 - t) qa, wb = t qb, q = wa + wb;
//   depth = depthValue((1 - t) za + t zb + depthBias);
//   varying k = float((wa / q) a_k + (wb / q) b_k).
// `majors` holds kMaxRuns entries: those up to the next multiple of kLineRunLanes past
// batch.count are read (any values) and their results, written past count, are not used.
void interpolateLineRuns(const LineRunEnds& ends, const int* majors, LineRunBatch& batch);

// The same with the copy compiled for `target` (tests; the target must run here).
void interpolateLineRunsWith(SimdTarget target, const LineRunEnds& ends, const int* majors,
                             LineRunBatch& batch);

}  // namespace glass::raster
