// Points: clipping (a point survives when its vertex is inside, spec 2.12), perspective division
// and viewport, then rasterizePoint.
#include "core/context.h"
#include "primitive/draw_pipeline.h"

namespace glass::gl {

void DrawPipeline::drawPoint(const PipelineVertex& v) { rasterizeVertexPoint(v.clip, 0.0); }

void DrawPipeline::rasterizeVertexPoint(const raster::ClipVertex& v, double depthBias) {
  if (!raster::pointInside(v, clip_)) return;
  raster::WindowVertex w;
  toWindow(viewport_, v, clip_.varyingCount, w);
  if (recording_) return recorder_.point(w);
  pointSettings_.depthBias = depthBias;
  raster::rasterizePoint(w, pointSettings_, fragments_);
}

}  // namespace glass::gl
