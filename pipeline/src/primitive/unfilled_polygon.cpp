// GL_LINE and GL_POINT polygon modes (spec 3.5.4): the boundary edges of a polygon are drawn as
// lines, or the vertices that start boundary edges as points, with line and point rasterization
// state, and with the polygon's own offset when GL_POLYGON_OFFSET_LINE / _POINT is enabled.
//
// Edges are clipped one by one as lines. That draws exactly the parts of the boundary edges that
// survive clipping the polygon, and no edge along a clip plane: Mesa leaves such edges out for
// the frustum planes (it draws them for user clip planes; glass does not).
#include "core/context.h"
#include "primitive/draw_pipeline.h"

namespace glass::gl {

void DrawPipeline::drawTriangleEdges(const raster::ClipVertex (&v)[3], unsigned boundaryEdges) {
  const double bias = polygonDepthBias(v, ctx_.raster.polygonOffsetLine);
  for (int i = 0; i < 3; ++i) {
    if (!(boundaryEdges & (1u << i))) continue;
    stippleCounter_ = 0;
    lineReset_ = true;
    rasterizeSegment(v[i], v[(i + 1) % 3], bias);
  }
}

void DrawPipeline::drawTriangleVertices(const raster::ClipVertex (&v)[3], unsigned boundaryEdges) {
  const double bias = polygonDepthBias(v, ctx_.raster.polygonOffsetPoint);
  for (int i = 0; i < 3; ++i) {
    if (boundaryEdges & (1u << i)) rasterizeVertexPoint(v[i], bias);
  }
}

}  // namespace glass::gl
