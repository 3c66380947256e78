// Triangles: facing, culling, colour selection, then the polygon mode of the facing side.
#include "core/context.h"
#include "primitive/culling.h"
#include "primitive/draw_pipeline.h"
#include "primitive/facing.h"
#include "primitive/vertex_colors.h"

namespace glass::gl {

void DrawPipeline::drawTriangle(const PipelineVertex& a, const PipelineVertex& b,
                                const PipelineVertex& c, const PipelineVertex& provoking,
                                unsigned boundaryEdges) {
  const RasterState& r = ctx_.raster;
  const bool front =
      isFrontFacing(isCounterClockwise(a.clip, b.clip, c.clip), r.frontFace);
  if (statistics_) {
    ++statistics_->triangles;
    if (isCulled(r, front)) ++statistics_->culled;
  }
  if (isCulled(r, front)) return;

  const bool back = vertex_.twoSided && !front;
  const GLenum mode = front ? r.polygonModeFront : r.polygonModeBack;
  // Filled with the vertices' own colours (smooth shading, front colours): drawn from the
  // vertices where they are.
  const unsigned codes[3] = {a.clipCode, b.clipCode, c.clipCode};
  if (mode == GL_FILL && !flat_ && !back)
    return fillTriangle({{&a.clip, &b.clip, &c.clip}, {codes[0], codes[1], codes[2]}}, front);

  raster::ClipVertex v[3] = {a.clip, b.clip, c.clip};
  if (flat_) {
    for (raster::ClipVertex& vertex : v) useProvokingColors(provoking, back, vertex);
  } else if (back) {
    useBackColors(a, v[0]);
    useBackColors(b, v[1]);
    useBackColors(c, v[2]);
  }

  switch (mode) {
    case GL_LINE:
      drawTriangleEdges(v, codes, boundaryEdges);
      break;
    case GL_POINT:
      drawTriangleVertices(v, codes, boundaryEdges);
      break;
    default:
      fillTriangle(cornersOf(v, codes), front);
      break;
  }
}

}  // namespace glass::gl
