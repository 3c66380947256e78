// Antialiased lines and points (GL_LINE_SMOOTH, GL_POINT_SMOOTH): the rectangle or square of
// smooth_coverage.h, rasterized as two triangles by the triangle rule, each fragment carrying its
// coverage to the fragment stage. The two triangles are one quadrilateral of the tiled rasterizer
// (tiled_rasterizer.h), set up and walked once: they share every block along their diagonal,
// which drawn apart each triangle's fragments went through the fragment kernels separately
// (the smooth_lines frame took twice as long). The quadrilateral is queued with the draw's other
// primitives, carrying its shape's coverage parameters as its payload, so it is drawn tile by
// tile like any triangle, in submission order per pixel. A stippled smooth line
// is first cut into its dashes (stipple_dashes.h).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "core/context.h"
#include "primitive/draw_pipeline.h"
#include "primitive/smooth_coverage.h"
#include "primitive/stipple_dashes.h"

namespace glass::gl {
namespace {

// Queues the shape's rectangle (TiledRasterizer::quad: its two triangles in one pass) with the
// shape's Coverage as its payload, for `sink`.
template <class Coverage, class Shape>
void queueShape(raster::TiledRasterizer& tiles, const Shape& shape, raster::TriangleSettings settings,
                double depthBias, CoverageFilter<Coverage>& sink) {
  static_assert(std::is_base_of_v<Coverage, Shape>);
  float payload[CoverageFilter<Coverage>::kPayloadFloats];
  const Coverage& coverage = shape;
  std::memcpy(payload, &coverage, sizeof payload);
  settings.depthBias = depthBias;
  settings.frontFacing = true;
  settings.payload = payload;
  settings.payloadCount = CoverageFilter<Coverage>::kPayloadFloats;
  const auto& corner = [&](int i) -> const raster::WindowVertex& { return shape.corners[Shape::kBoundary[i]]; };
  tiles.quad(corner(0), corner(1), corner(2), corner(3), settings, sink);
}

// The window vertex at t along a -> b, every value linear in window coordinates (as Mesa's
// stipple stage interpolates the ends of a dash).
raster::WindowVertex along(const raster::WindowVertex& a, const raster::WindowVertex& b, float t,
                           int varyingCount) {
  auto mix = [t](float u, float v) { return u + t * (v - u); };
  raster::WindowVertex v;
  v.x = mix(a.x, b.x);
  v.y = mix(a.y, b.y);
  v.z = mix(a.z, b.z);
  v.invW = mix(a.invW, b.invW);
  for (int k = 0; k < varyingCount; ++k) v.varyings[k] = mix(a.varyings[k], b.varyings[k]);
  return v;
}

}  // namespace

void DrawPipeline::rasterizeSmoothSegment(const raster::WindowVertex& a,
                                          const raster::WindowVertex& b, double depthBias) {
  if (lineSettings_.stippleFactor == 0) return rasterizeSmoothDash(a, b, depthBias);
  const int varyingCount = std::clamp(vertex_.varyingCount, 0, raster::kMaxVaryings);
  const float dx = b.x - a.x, dy = b.y - a.y;
  stippleCounter_ = forEachStippleDash(
      std::sqrt(dx * dx + dy * dy), stippleCounter_, lineSettings_.stipplePattern,
      lineSettings_.stippleFactor, [&](float t0, float t1) {
        rasterizeSmoothDash(t0 > 0.0f ? along(a, b, t0, varyingCount) : a,
                            t1 < 1.0f ? along(a, b, t1, varyingCount) : b, depthBias);
      });
}

void DrawPipeline::rasterizeSmoothDash(const raster::WindowVertex& a,
                                       const raster::WindowVertex& b, double depthBias) {
  SmoothLineShape shape;
  // GL_SMOOTH_LINE_WIDTH_RANGE is GL_LINE_WIDTH_RANGE, 1 to kMaxLineWidth.
  const float width = std::fmin(std::fmax(ctx_.raster.lineWidth, 1.0f), kMaxLineWidth);
  // A fragment's depth and attributes depend on where it lies along the segment, not on which
  // end comes first (spec 3.4.1: z = (1 - t) z_a + t z_b, with t measured from a, equals the
  // same expression measured from b). The rectangle is built from the same end whichever way the
  // segment was given, so both directions give the same values to the last bit: a wireframe
  // whose edges are drawn once from each face then blends every pixel once under GL_LESS, as
  // the specification's values imply (docs/pipeline.md, "Smooth lines drawn twice").
  const bool reversed = b.x < a.x || (b.x == a.x && b.y < a.y);
  if (!makeSmoothLine(reversed ? b : a, reversed ? a : b, width, ctx_.framebuffer.height(),
                      vertex_.varyingCount, shape))
    return;
  queueShape(tiles_, shape, triangleSettings_, depthBias, stage().smoothLines);
}

void DrawPipeline::rasterizeSmoothPoint(const raster::WindowVertex& w, float size,
                                        double depthBias) {
  SmoothPointShape shape;
  makeSmoothPoint(w, smoothPointRadius(size, pointDistanceAttenuated_), ctx_.framebuffer.height(),
                  vertex_.varyingCount, shape);
  queueShape(tiles_, shape, triangleSettings_, depthBias, stage().smoothPoints);
}

}  // namespace glass::gl
