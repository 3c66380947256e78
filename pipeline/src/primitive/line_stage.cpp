// Lines: flat shading, clipping, perspective division and viewport, then rasterizeLine, or the
// smooth segment of smooth_stage.cpp.
#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "primitive/vertex_colors.h"

namespace glass::gl {

void DrawPipeline::drawLine(const PipelineVertex& a, const PipelineVertex& b,
                            const PipelineVertex& provoking, StippleRun stipple) {
  startStippleRun(stipple);
  if (statistics_) {
    ++statistics_->lines;
    const unsigned oa = raster::outcode(a.clip, clip_), ob = raster::outcode(b.clip, clip_);
    raster::ClipVertex ca = a.clip, cb = b.clip;
    countClipping(oa | ob, oa & ob, (oa & ob) == 0 && ((oa | ob) == 0 || raster::clipLine(ca, cb, clip_)));
  }
  if (!flat_) return rasterizeSegment(a.clip, b.clip, 0.0);
  raster::ClipVertex va = a.clip, vb = b.clip;
  useProvokingColors(provoking, false, va);
  useProvokingColors(provoking, false, vb);
  rasterizeSegment(va, vb, 0.0);
}

void DrawPipeline::startStippleRun(StippleRun run) {
  if (run != StippleRun::Continued) {
    stippleCounter_ = 0;
    lineReset_ = true;
  }
  stippleEndNeeded_ = run != StippleRun::Alone;
}

// The vertices are copied only to be clipped: a copy of a whole vertex (with its 48 varyings)
// per segment cost more than the rest of a short segment's path through this stage.
void DrawPipeline::rasterizeSegment(const raster::ClipVertex& a, const raster::ClipVertex& b,
                                    double depthBias) {
  const unsigned oa = raster::outcode(a, clip_), ob = raster::outcode(b, clip_);
  if (oa & ob) return;
  if ((oa | ob) == 0) return rasterizeUnclippedSegment(a, b, depthBias);
  raster::ClipVertex ca = a, cb = b;
  if (raster::clipLine(ca, cb, clip_)) rasterizeUnclippedSegment(ca, cb, depthBias);
}

void DrawPipeline::rasterizeUnclippedSegment(const raster::ClipVertex& a, const raster::ClipVertex& b,
                                             double depthBias) {
  raster::WindowVertex wa, wb;
  if (!toWindow(viewport_, a, clip_.varyingCount, wa) ||
      !toWindow(viewport_, b, clip_.varyingCount, wb))
    return;
  if (recording_) {
    recorder_.line(wa, wb, lineReset_);
    lineReset_ = false;
    return;
  }
  if (smoothLines_) return rasterizeSmoothSegment(wa, wb, depthBias);  // smooth_stage.cpp
  lineSettings_.depthBias = depthBias;
  // A segment whose counter nobody goes on from starts at 0 (it was just restarted): no counter.
  lineSettings_.stippleCounter = stippleEndNeeded_ ? &stippleCounter_ : nullptr;
  tiles_.line(wa, wb, lineSettings_, stage().processor);
}

}  // namespace glass::gl
