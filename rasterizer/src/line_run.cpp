// The reference path for a line's runs (glass/raster/line_run.h): each run expanded into its
// fragments, all with the run's depth and varyings.
#include "glass/raster/line_run.h"

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
    for (int i = 0; i < batch.length[r]; ++i) {
      Fragment& f = fragments[count++];
      f.x = batch.x[r] + (batch.alongX ? i : 0);
      f.y = batch.y[r] + (batch.alongX ? 0 : i);
      f.depth = batch.depth[r];
      for (int k = 0; k < batch.varyingCount; ++k) f.varyings[k] = batch.varyings[k][r];
      if (count == kBatchSize) flush();
    }
  }
  flush();
}

void FragmentSink::processLineRuns(const LineRunBatch& batch) { emitLineRunFragments(batch, *this); }

}  // namespace glass::raster
