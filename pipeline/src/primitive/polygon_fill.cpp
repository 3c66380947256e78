// GL_FILL polygons: clipping, perspective division and viewport, polygon offset, then the
// tiled rasterizer's triangle setup and coverage for each triangle of the clipped polygon's fan.
#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "primitive/polygon_offset.h"
#include "teaching/teaching_hooks.h"

namespace glass::gl {

int DrawPipeline::clipToWindow(const ClipCorners& corners, raster::WindowVertex* out) {
  const raster::ClipVertex* const* v = corners.v;
  const unsigned o0 = codeOf(*v[0], corners.code[0]);
  const unsigned o1 = codeOf(*v[1], corners.code[1]);
  const unsigned o2 = codeOf(*v[2], corners.code[2]);
  if (o0 & o1 & o2) return 0;  // all vertices outside one plane: trivially rejected

  if (o0 | o1 | o2) {
    const raster::ClipVertex triangle[3] = {*v[0], *v[1], *v[2]};
    const int count = raster::clipPolygon(triangle, 3, clip_, clipped_);
    if (count < 3) return 0;
    for (int i = 0; i < count; ++i)
      if (!toWindow(viewport_, clipped_[i], clip_.varyingCount, out[i])) return 0;
    return count;
  }
  for (int i = 0; i < 3; ++i)
    if (!toWindow(viewport_, *v[i], clip_.varyingCount, out[i])) return 0;
  return 3;
}

double DrawPipeline::polygonDepthBias(const ClipCorners& corners, bool offsetEnabled) {
  if (!offsetEnabled) return 0.0;
  const RasterState& r = ctx_.raster;
  if (r.polygonOffsetFactor == 0.0f && r.polygonOffsetUnits == 0.0f) return 0.0;
  const int count = clipToWindow(corners, window_);
  return count >= 3 ? polygonOffset(r.polygonOffsetFactor, r.polygonOffsetUnits, window_, count)
                    : 0.0;
}

void DrawPipeline::fillTriangle(const ClipCorners& corners, bool frontFacing) {
  const int count = clipToWindow(corners, window_);
  if (statistics_) {
    const unsigned o0 = codeOf(*corners.v[0], corners.code[0]), o1 = codeOf(*corners.v[1], corners.code[1]),
                   o2 = codeOf(*corners.v[2], corners.code[2]);
    countClipping(o0 | o1 | o2, o0 & o1 & o2, count - 2);
  }
  if (count < 3) return;
  if (recording_) return recorder_.polygon(window_, count);

  const RasterState& r = ctx_.raster;
  triangleSettings_.frontFacing = frontFacing;
  triangleSettings_.depthBias =
      r.polygonOffsetFill
          ? polygonOffset(r.polygonOffsetFactor, r.polygonOffsetUnits, window_, count)
          : 0.0;

  for (int i = 1; i + 1 < count; ++i) {
    if (teaching_) markTriangleEdges(*teaching_, window_[0], window_[i], window_[i + 1]);
    tiles_.triangle(window_[0], window_[i], window_[i + 1], triangleSettings_, *polygonSink_);
  }
}

}  // namespace glass::gl
