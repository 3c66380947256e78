// Antialiased lines and points (GL_LINE_SMOOTH, GL_POINT_SMOOTH): the rectangle or square of
// smooth_coverage.h, rasterized as two triangles by the triangle rule, each fragment carrying its
// coverage to the fragment stage. Line stipple does not apply to smooth lines here.
#include <algorithm>

#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "primitive/smooth_coverage.h"

namespace glass::gl {
namespace {

template <class Shape>
void fillShape(const Shape& shape, raster::TriangleSettings settings, double depthBias,
               FragmentProcessor& fragments) {
  settings.depthBias = depthBias;
  settings.frontFacing = true;
  CoverageFilter<Shape> filter(shape, fragments);
  for (const auto& t : Shape::kTriangles) {
    raster::TriangleSetup setup;
    if (!raster::setupTriangle(shape.corners[t[0]], shape.corners[t[1]], shape.corners[t[2]],
                               settings, setup)) {
      continue;
    }
    raster::rasterizeTriangle(setup, filter);
  }
}

}  // namespace

void DrawPipeline::rasterizeSmoothSegment(const raster::WindowVertex& a,
                                          const raster::WindowVertex& b, double depthBias) {
  SmoothLineShape shape;
  // GL_SMOOTH_LINE_WIDTH_RANGE is GL_LINE_WIDTH_RANGE, 1 to kMaxLineWidth.
  const float width = std::min(ctx_.raster.lineWidth, kMaxLineWidth);
  if (!makeSmoothLine(a, b, width, ctx_.framebuffer.height(), vertex_.varyingCount, shape)) return;
  fillShape(shape, triangleSettings_, depthBias, fragments_);
}

void DrawPipeline::rasterizeSmoothPoint(const raster::WindowVertex& w, float size,
                                        double depthBias) {
  SmoothPointShape shape;
  makeSmoothPoint(w, smoothPointRadius(size, pointDistanceAttenuated_), ctx_.framebuffer.height(),
                  vertex_.varyingCount, shape);
  fillShape(shape, triangleSettings_, depthBias, fragments_);
}

}  // namespace glass::gl
