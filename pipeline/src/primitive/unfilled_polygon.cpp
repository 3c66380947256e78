// GL_LINE and GL_POINT polygon modes (spec 3.5.4): the boundary edges of a polygon are drawn as
// lines, or the vertices that start boundary edges as points, with line and point rasterization
// state, and with the polygon's own offset when GL_POLYGON_OFFSET_LINE / _POINT is enabled.
//
// Edges are clipped one by one as lines. That draws exactly the parts of the boundary edges that
// survive clipping the polygon. Clipping also gives the polygon new edges along the clip planes;
// which of them are boundary edges the specification does not say. Mesa draws those along user
// clip planes and not those along the frustum, and so does glass: where an enabled user plane
// cuts the triangle, the cut is drawn too (as a line from the point where the boundary leaves the
// plane's inside to the point where it comes back, the clipped polygon's order), or, in GL_POINT
// mode, its ends (the exit always, the entry when the edge it lies on is a boundary edge, as
// Mesa flags the vertices clipping makes).
#include "core/context.h"
#include "primitive/draw_pipeline.h"

namespace glass::gl {

namespace {

// a + t (b - a) for every interpolated value of a clip vertex, as the clipper interpolates.
raster::ClipVertex lerp(const raster::ClipVertex& a, const raster::ClipVertex& b, float t,
                        int varyingCount) {
  raster::ClipVertex r;
  for (int i = 0; i < 4; ++i) r.clip[i] = a.clip[i] + t * (b.clip[i] - a.clip[i]);
  for (int i = 0; i < raster::kMaxUserClipPlanes; ++i) {
    r.userClipDistance[i] = a.userClipDistance[i] + t * (b.userClipDistance[i] - a.userClipDistance[i]);
  }
  for (int i = 0; i < varyingCount; ++i) r.varyings[i] = a.varyings[i] + t * (b.varyings[i] - a.varyings[i]);
  return r;
}

struct PlaneCut {
  raster::ClipVertex exit, entry;  // on the plane, in the order the boundary passes them
  bool entryOnBoundaryEdge = false;
};

// Where user plane `plane` cuts the triangle: false when all vertices are on one side.
bool cutByUserPlane(const raster::ClipVertex (&v)[3], int plane, unsigned boundaryEdges,
                    int varyingCount, PlaneCut& cut) {
  bool haveExit = false, haveEntry = false;
  for (int i = 0; i < 3; ++i) {
    const raster::ClipVertex& a = v[i];
    const raster::ClipVertex& b = v[(i + 1) % 3];
    const float da = a.userClipDistance[plane], db = b.userClipDistance[plane];
    const bool aInside = da >= 0.0f, bInside = db >= 0.0f;
    if (aInside == bInside) continue;
    raster::ClipVertex point = lerp(a, b, da / (da - db), varyingCount);
    point.userClipDistance[plane] = 0.0f;  // on the plane, hence inside it
    if (aInside) {
      cut.exit = point;
      haveExit = true;
    } else {
      cut.entry = point;
      cut.entryOnBoundaryEdge = (boundaryEdges >> i) & 1u;
      haveEntry = true;
    }
  }
  return haveExit && haveEntry;
}

}  // namespace

void DrawPipeline::drawTriangleEdges(const raster::ClipVertex (&v)[3], const unsigned (&codes)[3],
                                     unsigned boundaryEdges) {
  const double bias = polygonDepthBias(cornersOf(v, codes), ctx_.raster.polygonOffsetLine);
  for (int i = 0; i < 3; ++i) {
    if (!(boundaryEdges & (1u << i))) continue;
    startStippleRun(StippleRun::Alone);  // each edge is stippled alone
    rasterizeSegment(v[i], v[(i + 1) % 3], bias);
  }
  for (int plane = 0; plane < raster::kMaxUserClipPlanes; ++plane) {
    PlaneCut cut;
    if (!(clip_.userPlaneMask & (1u << plane)) ||
        !cutByUserPlane(v, plane, boundaryEdges, clip_.varyingCount, cut)) {
      continue;
    }
    startStippleRun(StippleRun::Alone);  // each edge is stippled alone
    rasterizeSegment(cut.exit, cut.entry, bias);
  }
}

void DrawPipeline::drawTriangleVertices(const raster::ClipVertex (&v)[3], const unsigned (&codes)[3],
                                        unsigned boundaryEdges) {
  const double bias = polygonDepthBias(cornersOf(v, codes), ctx_.raster.polygonOffsetPoint);
  for (int i = 0; i < 3; ++i) {
    if (boundaryEdges & (1u << i)) rasterizeVertexPoint(v[i], bias);
  }
  for (int plane = 0; plane < raster::kMaxUserClipPlanes; ++plane) {
    PlaneCut cut;
    if (!(clip_.userPlaneMask & (1u << plane)) ||
        !cutByUserPlane(v, plane, boundaryEdges, clip_.varyingCount, cut)) {
      continue;
    }
    rasterizeVertexPoint(cut.exit, bias);
    if (cut.entryOnBoundaryEdge) rasterizeVertexPoint(cut.entry, bias);
  }
}

}  // namespace glass::gl
