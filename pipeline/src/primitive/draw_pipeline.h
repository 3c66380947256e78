// The primitive stages between primitive assembly and the rasterizer, in the spirit of Mesa's
// gallium draw module: each primitive passes through small stages, each in a file of its own.
//
//   triangles (triangle_stage.cpp):  facing and culling (facing.h, culling.h) -> two-sided colour
//     and flat shading (vertex_colors.h) -> polygon mode per face: GL_FILL (polygon_fill.cpp),
//     GL_LINE or GL_POINT (unfilled_polygon.cpp) with edge flags -> polygon offset
//     (polygon_offset.h)
//   lines (line_stage.cpp):           flat shading -> clipping -> viewport -> rasterizeLine, or
//     for GL_LINE_SMOOTH a rectangle of two triangles with coverage (smooth_stage.cpp)
//   points (point_stage.cpp):         clipping -> size (point parameters) -> viewport ->
//     rasterizePoint, or for GL_POINT_SMOOTH a disc with coverage (smooth_stage.cpp)
//
// Clipping uses the rasterizer's clipPolygon, clipLine and pointInside with the enabled user
// planes; perspective division and the viewport are in viewport_transform.h. Every fragment goes
// to the FragmentProcessor, those of filled polygons through the polygon stipple first
// (polygon_stipple.h) when GL_POLYGON_STIPPLE is on.
//
// In GL_SELECT and GL_FEEDBACK render modes nothing is rasterized: each point, line and polygon
// that survives clipping goes to the PrimitiveRecorder (select/primitive_recorder.h) instead, in
// window coordinates (spec 5.2, 5.3).
#pragma once

#include "fragment/fragment_processor.h"
#include "glass/raster/clip.h"
#include "glass/raster/line.h"
#include "glass/raster/triangle.h"
#include "primitive/polygon_stipple.h"
#include "primitive/viewport_transform.h"
#include "select/primitive_recorder.h"
#include "vertex/pipeline_vertex.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {

struct Context;

// Edge flags of an assembled triangle (a, b, c): bit 0 for edge a->b, 1 for b->c, 2 for c->a.
inline constexpr unsigned kAllEdges = 7u;

class DrawPipeline {
 public:
  explicit DrawPipeline(Context& ctx) : ctx_(ctx) {}

  // Derives the vertex, primitive and fragment setup from the GL state (at glBegin).
  void prepare();
  const VertexStageSetup& vertexSetup() const { return vertex_; }
  // The vertex lies outside a frustum plane or an enabled user clip plane.
  bool needsClipping(const PipelineVertex& v) const { return raster::outcode(v.clip, clip_) != 0; }

  void drawPoint(const PipelineVertex& v);
  // restartStipple: the segment starts a new line (GL_LINES, the first of a strip).
  void drawLine(const PipelineVertex& a, const PipelineVertex& b, const PipelineVertex& provoking,
                bool restartStipple);
  void drawTriangle(const PipelineVertex& a, const PipelineVertex& b, const PipelineVertex& c,
                    const PipelineVertex& provoking, unsigned boundaryEdges);

 private:
  // polygon_fill.cpp
  void fillTriangle(const raster::ClipVertex (&v)[3], bool frontFacing);
  // unfilled_polygon.cpp
  void drawTriangleEdges(const raster::ClipVertex (&v)[3], unsigned boundaryEdges);
  void drawTriangleVertices(const raster::ClipVertex (&v)[3], unsigned boundaryEdges);
  // The offset of a polygon for a polygon mode whose offset is enabled, else 0.
  double polygonDepthBias(const raster::ClipVertex (&v)[3], bool offsetEnabled);
  // line_stage.cpp, point_stage.cpp: clip, viewport, rasterize.
  void rasterizeSegment(raster::ClipVertex a, raster::ClipVertex b, double depthBias);
  void rasterizeVertexPoint(const raster::ClipVertex& v, double depthBias);
  // The size of a point at clip position v: glPointSize, or the derived size of the point
  // parameters (point_stage.cpp).
  float pointSizeAt(const raster::ClipVertex& v) const;
  // smooth_stage.cpp: antialiased segments and points (primitive/smooth_coverage.h).
  void rasterizeSmoothSegment(const raster::WindowVertex& a, const raster::WindowVertex& b,
                              double depthBias);
  void rasterizeSmoothDash(const raster::WindowVertex& a, const raster::WindowVertex& b,
                           double depthBias);
  void rasterizeSmoothPoint(const raster::WindowVertex& v, float size, double depthBias);
  // Clips a triangle to a polygon in window coordinates; returns its vertex count (0: nothing
  // visible). polygon_fill.cpp
  int clipToWindow(const raster::ClipVertex (&v)[3], raster::WindowVertex* out);

  Context& ctx_;
  VertexStageSetup vertex_;
  FragmentProcessor fragments_;
  raster::ClipSettings clip_;
  ViewportTransform viewport_;
  raster::TriangleSettings triangleSettings_;
  raster::LineSettings lineSettings_;
  raster::PointSettings pointSettings_;
  bool smoothLines_ = false;         // GL_LINE_SMOOTH
  bool smoothPoints_ = false;        // GL_POINT_SMOOTH
  bool pointSizeAttenuated_ = false; // the point parameters change sizes
  bool pointDistanceAttenuated_ = false;  // ... by distance, not only by GL_POINT_SIZE_MIN/MAX
  Matrix4 projectionInverse_;        // eye = P^-1 clip, for the points' eye distance
  bool flat_ = false;
  int stippleCounter_ = 0;
  PolygonStippleFilter polygonStipple_;
  raster::FragmentSink* polygonSink_ = &fragments_;  // polygonStipple_ when stippling
  bool recording_ = false;   // GL_SELECT or GL_FEEDBACK: primitives go to recorder_
  bool lineReset_ = false;   // the next recorded line starts a new line (GL_LINE_RESET_TOKEN)
  PrimitiveRecorder recorder_;
  // Scratch space for clipped polygons.
  raster::ClipVertex clipped_[raster::kMaxClippedPolygonVertices + 3];
  raster::WindowVertex window_[raster::kMaxClippedPolygonVertices + 3];
};

}  // namespace glass::gl
