// GLASS_STATS's clipping counts (teaching/frame_statistics.h).
#include "primitive/draw_pipeline.h"

namespace glass::gl {

// Outcodes (spec 2.12): a primitive with every vertex outside one plane, or nothing left after
// clipping, is clipped away; one with a vertex outside some plane is cut, into `produced`
// primitives (the triangles of the clipped polygon's fan, or the one clipped line).
void DrawPipeline::countClipping(unsigned outcodeUnion, unsigned outcodeIntersection, int produced) {
  if (outcodeUnion == 0) return;
  if (outcodeIntersection != 0 || produced <= 0) {
    ++statistics_->clippedAway;
    return;
  }
  ++statistics_->clipped;
  statistics_->producedByClipping += static_cast<std::uint64_t>(produced);
}

}  // namespace glass::gl
