#include "primitive/polygon_stipple.h"

namespace glass::gl {

void PolygonStippleFilter::processFragments(const raster::FragmentBatch& batch) {
  // The kept fragments are copied into a batch of their own; the attribute planes stay valid,
  // they describe the primitive, not the fragments.
  constexpr int kCapacity = 64;
  raster::Fragment kept[kCapacity];
  raster::FragmentBatch out = batch;
  out.fragments = kept;
  out.count = 0;
  for (int i = 0; i < batch.count; ++i) {
    const raster::Fragment& f = batch.fragments[i];
    if (!pattern_->covers(f.x, f.y)) continue;
    kept[out.count++] = f;
    if (out.count == kCapacity) {
      next_->processFragments(out);
      out.count = 0;
    }
  }
  if (out.count > 0) next_->processFragments(out);
}

}  // namespace glass::gl
