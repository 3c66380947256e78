// Runs of a line segment: what the line walk (rasterizer/src/line.cpp) hands to a fragment sink.
//
// A run is one column of an x-major segment or one row of a y-major one. Attributes are
// interpolated along the major axis only (spec 3.4.2), so every fragment of a run has the same
// depth and varyings: a run is its first fragment's position, the number of fragments from there
// across the minor axis, each one pixel further, and the depth and varyings they share.
//
// A batch holds its runs as arrays, one per field and one per varying (run r's varying k is
// varyings[k][r]), so that the walk interpolates a varying for all the runs of a batch in one
// loop and a kernel converts the colours of several runs at once.
//
// The sink's default treatment (FragmentSink::processLineRuns) is the reference path: expand the
// runs into fragments and pass them on as FragmentBatches. A sink may instead run a kernel
// specialised for its state on the runs (the pipeline's fast paths, docs/pipeline.md), which must
// write the same bytes.
#pragma once

#include <cstdint>

#include "glass/raster/fragment.h"

namespace glass::raster {

// The arrays are left uninitialised by construction: the walk fills runs 0 .. count - 1 of each.
struct LineRunBatch {
  static constexpr int kMaxRuns = 64;
  int count = 0;
  int varyingCount = 0;
  // The direction a run extends in: rows (+x) for a y-major segment, columns (+y) for an x-major.
  bool alongX = false;
  int x[kMaxRuns], y[kMaxRuns];    // the run's first fragment
  int length[kMaxRuns];            // fragments in the run, at least 1
  uint32_t depth[kMaxRuns];        // as Fragment::depth
  float varyings[kMaxVaryings][kMaxRuns];  // varyings[k][r] for k < varyingCount
};

// The reference path: the runs' fragments, in order, handed to sink.processFragments in batches.
void emitLineRunFragments(const LineRunBatch& batch, FragmentSink& sink);

}  // namespace glass::raster
