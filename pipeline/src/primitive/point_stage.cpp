// Points: clipping (a point survives when its vertex is inside, spec 2.12), the size (glPointSize
// or the point parameters' derived size, spec 3.3), perspective division and viewport, then
// rasterizePoint, or the smooth point of smooth_stage.cpp.
#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "primitive/point_parameters.h"

namespace glass::gl {

void DrawPipeline::drawPoint(const PipelineVertex& v) {
  if (statistics_) {
    ++statistics_->points;
    // A point is not cut: it is drawn whole or clipped away (spec 2.12).
    if (!raster::pointInside(v.clip, clip_)) ++statistics_->clippedAway;
  }
  rasterizeVertexPoint(v.clip, 0.0);
}

float DrawPipeline::pointSizeAt(const raster::ClipVertex& v) const {
  const RasterState& r = ctx_.raster;
  if (!pointSizeAttenuated_) return std::min(r.pointSize, kMaxPointSize);
  // The eye distance d of spec 3.3 (from the eye, the origin of eye coordinates, to the vertex;
  // Mesa's fixed-function vertex program takes |z_e| instead, which agrees on the eye axis). The
  // vertex stage hands on clip coordinates, clip = P eye, so eye = P^-1 clip.
  float eye[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  if (pointDistanceAttenuated_) transformVector4(projectionInverse_, v.clip, eye);
  const float d = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  const float size = derivedPointSize(r, d);
  if (!(size >= 0.0f)) return 0.0f;  // a distance that is not a number: the smallest point
  return std::min(size, kMaxPointSize);  // GL_ALIASED_POINT_SIZE_RANGE
}

void DrawPipeline::rasterizeVertexPoint(const raster::ClipVertex& v, double depthBias) {
  if (!raster::pointInside(v, clip_)) return;
  raster::WindowVertex w;
  if (!toWindow(viewport_, v, clip_.varyingCount, w)) return;
  if (recording_) return recorder_.point(w);
  const float size = pointSizeAt(v);
  if (smoothPoints_) return rasterizeSmoothPoint(w, size, depthBias);  // smooth_stage.cpp
  pointSettings_.size = size;
  pointSettings_.depthBias = depthBias;
  tiles_.point(w, pointSettings_, stage().processor);
}

}  // namespace glass::gl
