// Sinks and vertex builders shared by the raster unit tests.
#pragma once

#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "glass/raster/fragment.h"
#include "glass/raster/vertex.h"

namespace glass::raster::test {

// Counts how many times each pixel is written, and keeps every fragment and batch size. The
// tiled rasterizer calls it from several threads at once (one per tile), hence the lock.
class RecordingSink : public FragmentSink {
 public:
  void processFragments(const FragmentBatch& batch) override {
    std::lock_guard<std::mutex> lock(mutex_);
    ++batches;
    batchSizes.push_back(batch.count);
    for (int i = 0; i < batch.count; ++i) {
      const Fragment& f = batch.fragments[i];
      ++writes[{f.x, f.y}];
      fragments.push_back(f);
      frontFacing.push_back(batch.frontFacing);
    }
  }
  int writesAt(int x, int y) const {
    auto it = writes.find({x, y});
    return it == writes.end() ? 0 : it->second;
  }
  void clear() {
    writes.clear();
    fragments.clear();
    batchSizes.clear();
    frontFacing.clear();
    batches = 0;
  }

  std::map<std::pair<int, int>, int> writes;
  std::vector<Fragment> fragments;
  std::vector<int> batchSizes;
  std::vector<bool> frontFacing;
  int batches = 0;

 private:
  std::mutex mutex_;
};

inline WindowVertex windowVertex(float x, float y, float z = 0.5f, float invW = 1.0f) {
  WindowVertex v{};
  v.x = x;
  v.y = y;
  v.z = z;
  v.invW = invW;
  return v;
}

inline ClipVertex clipVertex(float x, float y, float z, float w) {
  ClipVertex v{};
  v.clip[0] = x;
  v.clip[1] = y;
  v.clip[2] = z;
  v.clip[3] = w;
  return v;
}

inline PixelRect rect(int x0, int y0, int x1, int y1) {
  PixelRect r;
  r.x0 = x0;
  r.y0 = y0;
  r.x1 = x1;
  r.y1 = y1;
  return r;
}

}  // namespace glass::raster::test
