// The reference path for a line's runs (glass/raster/line_run.h): each run expanded into its
// fragments, all with the run's depth and varyings.
#include "glass/raster/line_run.h"

#include <algorithm>

namespace glass::raster {

void emitLineRunFragments(const LineRunBatch& batch, FragmentSink& sink) {
  constexpr int kBatchSize = 64;
  Fragment fragments[kBatchSize];
  int count = 0;
  const auto flush = [&] {
    if (count == 0) return;
    FragmentBatch fragmentBatch;
    fragmentBatch.fragments = fragments;
    fragmentBatch.count = count;
    fragmentBatch.varyingCount = batch.varyingCount;
    sink.processFragments(fragmentBatch);
    count = 0;
  };
  for (int r = 0; r < batch.count; ++r) {
    const LineRun& run = batch.runs[r];
    for (int i = 0; i < run.length; ++i) {
      Fragment& f = fragments[count++];
      f.x = run.first.x + (batch.alongX ? i : 0);
      f.y = run.first.y + (batch.alongX ? 0 : i);
      f.depth = run.first.depth;
      std::copy(run.first.varyings, run.first.varyings + batch.varyingCount, f.varyings);
      if (count == kBatchSize) flush();
    }
  }
  flush();
}

void FragmentSink::processLineRuns(const LineRunBatch& batch) { emitLineRunFragments(batch, *this); }

}  // namespace glass::raster
