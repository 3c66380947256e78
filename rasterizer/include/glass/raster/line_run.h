// Runs of a line segment: what the line walk (rasterizer/src/line.cpp) hands to a fragment sink.
//
// A run is one column of an x-major segment or one row of a y-major one. Attributes are
// interpolated along the major axis only (spec 3.4.2), so every fragment of a run has the same
// depth and varyings: a run is its first fragment and the number of fragments that follow it
// across the minor axis, each one pixel further.
//
// The sink's default treatment (FragmentSink::processLineRuns) is the reference path: expand the
// runs into fragments and pass them on as FragmentBatches. A sink may instead run a kernel
// specialised for its state on the runs (the pipeline's fast paths, docs/pipeline.md), which must
// write the same bytes.
#pragma once

#include "glass/raster/fragment.h"

namespace glass::raster {

// Left uninitialised by construction: the walk fills a batch's runs one by one.
struct LineRun {
  Fragment first;  // position, depth and varyings[0 .. varyingCount) of the run's first fragment
  int length;      // fragments in the run, at least 1
};

struct LineRunBatch {
  static constexpr int kMaxRuns = 64;
  const LineRun* runs = nullptr;
  int count = 0;
  int varyingCount = 0;
  // The direction a run extends in: rows (+x) for a y-major segment, columns (+y) for an x-major.
  bool alongX = false;
};

// The reference path: the runs' fragments, in order, handed to sink.processFragments in batches.
void emitLineRunFragments(const LineRunBatch& batch, FragmentSink& sink);

}  // namespace glass::raster
