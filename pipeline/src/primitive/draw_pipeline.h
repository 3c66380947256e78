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
// Rasterization is deferred: primitives go to a TiledRasterizer (glass/raster/tiled_rasterizer.h),
// which bins them into 64 x 64 tiles and rasterizes the tiles later on GLASS_THREADS threads,
// with the same bytes as one thread. The fragment stage's settings are a copy made at glBegin
// (FragmentProcessor::prepare), so queued draws keep them while the GL state moves on, with two
// exceptions, finished at the end of their draw instead (finishIfReadingContext):
//   - draws whose fragment stage reads GL state by reference for each fragment: texturing (the
//     texture objects are changed in place), fog and per-fragment lighting;
//   - polygon-stippled draws (the filter reads the pattern in the context).
// Each queued primitive points at the fragment stage of its draw (FragmentStage: the processor
// and the filters before it). A draw whose settings match none of the queued draws' takes a
// stage of its own, so that a frame that changes its depth, stencil or blend state from draw to
// draw keeps the threads busy; when all kFragmentStages are taken, the queued draws are finished
// first (prepare). Everything that reads or writes the
// framebuffer outside a draw (glClear, glReadPixels, glCopyTexImage, pixel rectangles, bitmaps,
// glAccum, glFinish, glFlush, glassWritePNG, ...) calls finishQueuedDrawing first
// (primitive/queued_drawing.h), and the pipeline's destructor finishes what is left.
//
// In GL_SELECT and GL_FEEDBACK render modes nothing is rasterized: each point, line and polygon
// that survives clipping goes to the PrimitiveRecorder (select/primitive_recorder.h) instead, in
// window coordinates (spec 5.2, 5.3).
#pragma once

#include "fragment/fragment_processor.h"
#include "glass/raster/clip.h"
#include "glass/raster/line.h"
#include "glass/raster/tiled_rasterizer.h"
#include "glass/raster/triangle.h"
#include "primitive/polygon_stipple.h"
#include "primitive/smooth_coverage.h"
#include "primitive/viewport_transform.h"
#include "select/primitive_recorder.h"
#include "teaching/frame_statistics.h"
#include "teaching/teaching_view.h"
#include "vertex/pipeline_vertex.h"
#include "vertex/vertex_stage.h"

namespace glass::gl {

struct Context;

// Edge flags of an assembled triangle (a, b, c): bit 0 for edge a->b, 1 for b->c, 2 for c->a.
inline constexpr unsigned kAllEdges = 7u;

class DrawPipeline {
 public:
  explicit DrawPipeline(Context& ctx);

  // Derives the vertex, primitive and fragment setup from the GL state (at glBegin).
  void prepare();
  // Finishes the draw's queued fragments if they read GL state by reference: at glEnd, and
  // before glMaterial changes such state between glBegin and glEnd.
  void finishIfReadingContext();
  // Rasterizes everything queued; returns when the framebuffer holds every queued fragment.
  void finishQueuedWork();
  // Queues a clear of the framebuffer in order with the draws (fragment/clear.cpp).
  void queueClear(const raster::ClearRequest& request) { tiles_.clear(request); }
  // Before glColor changes the material under GL_COLOR_MATERIAL between glBegin and glEnd.
  // Per-fragment lighting reads the material from the context, but takes the tracked parameters
  // from the fragment's own colour (materialWithColor), so the queued fragments light the same
  // with the old or the new material and need not be drawn first. Only, no thread may be reading
  // the material while it is written: this waits for the threads if they may be.
  void beforeColorMaterialChange();
  const VertexStageSetup& vertexSetup() const { return vertex_; }
  // GLASS_STATS's counts of the frame, or nullptr (teaching/frame_statistics.h).
  FrameStatistics* statistics() const { return statistics_; }
  // The vertex's outcode (raster::outcode) under this draw's clip settings.
  unsigned clipCodeOf(const raster::ClipVertex& v) const { return raster::outcode(v, clip_); }
  // No user clip plane is enabled: raster::frustumOutcodes gives clipCodeOf's codes.
  bool clipsToFrustumOnly() const { return clip_.userPlaneMask == 0; }
  // The vertex lies outside a frustum plane or an enabled user clip plane.
  bool needsClipping(const PipelineVertex& v) const { return codeOf(v.clip, v.clipCode) != 0; }

  void drawPoint(const PipelineVertex& v);
  // Where a segment's line stipple counter starts (spec 3.4.2) and whether another segment goes
  // on from where it ends: Alone starts at 0 and none does (every segment of GL_LINES), First
  // starts at 0 and the next goes on (a strip's first), Continued goes on from the previous one.
  enum class StippleRun { Alone, First, Continued };
  void drawLine(const PipelineVertex& a, const PipelineVertex& b, const PipelineVertex& provoking,
                StippleRun stipple);
  void drawTriangle(const PipelineVertex& a, const PipelineVertex& b, const PipelineVertex& c,
                    const PipelineVertex& provoking, unsigned boundaryEdges);

 private:
  // A triangle's three vertices where they are, so that a triangle drawn with its vertices'
  // own colours is not copied (polygon_fill.cpp), with their outcodes if known.
  struct ClipCorners {
    const raster::ClipVertex* v[3];
    unsigned code[3];  // PipelineVertex::clipCode of each
  };
  static ClipCorners cornersOf(const raster::ClipVertex (&v)[3], const unsigned (&codes)[3]) {
    return {{&v[0], &v[1], &v[2]}, {codes[0], codes[1], codes[2]}};
  }
  // A vertex's outcode: `known` unless it is kClipCodeUnknown.
  unsigned codeOf(const raster::ClipVertex& v, unsigned known) const {
    return known != kClipCodeUnknown ? known : raster::outcode(v, clip_);
  }
  // polygon_fill.cpp
  void fillTriangle(const ClipCorners& corners, bool frontFacing);
  // unfilled_polygon.cpp
  void drawTriangleEdges(const raster::ClipVertex (&v)[3], const unsigned (&codes)[3], unsigned boundaryEdges);
  void drawTriangleVertices(const raster::ClipVertex (&v)[3], const unsigned (&codes)[3],
                            unsigned boundaryEdges);
  // The offset of a polygon for a polygon mode whose offset is enabled, else 0.
  double polygonDepthBias(const ClipCorners& corners, bool offsetEnabled);
  // line_stage.cpp, point_stage.cpp: clip, viewport, rasterize.
  void rasterizeSegment(const raster::ClipVertex& a, const raster::ClipVertex& b, double depthBias);
  // A segment inside the clip volume: viewport, rasterize.
  void rasterizeUnclippedSegment(const raster::ClipVertex& a, const raster::ClipVertex& b, double depthBias);
  // Where the next segment's stipple counter starts (drawLine's StippleRun; a polygon's edges are
  // each Alone).
  void startStippleRun(StippleRun run);
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
  int clipToWindow(const ClipCorners& corners, raster::WindowVertex* out);
  // GLASS_STATS: whether clipping cut a primitive with these outcodes or rejected it whole;
  // `produced` is what the cut one became (primitive_statistics.cpp).
  void countClipping(unsigned outcodeUnion, unsigned outcodeIntersection, int produced);

  // The fragment stage of a draw: its processor, and the filters that pass fragments on to it.
  struct FragmentStage {
    FragmentProcessor processor;
    PolygonStippleFilter polygonStipple;
    // The sinks of antialiased lines' and points' triangles, whose fragments carry their shape.
    CoverageFilter<SmoothLineCoverage> smoothLines{processor};
    CoverageFilter<SmoothPointCoverage> smoothPoints{processor};
  };
  static constexpr int kFragmentStages = 8;
  FragmentStage& stage() { return stages_[stage_]; }

  Context& ctx_;
  VertexStageSetup vertex_;
  FragmentStage stages_[kFragmentStages];
  int stage_ = 0;        // the current draw's
  int stagesInUse_ = 0;  // stages [0, stagesInUse_) hold the settings of queued draws
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
  TeachingCanvas* teaching_ = nullptr;  // the context's GLASS_VIEW, if any (teaching/)
  FrameStatistics* statistics_ = nullptr;  // GLASS_STATS, if set (teaching/)
  bool drawReadsContext_ = false;  // this draw's fragments read GL state by reference
  int stippleCounter_ = 0;
  // Whether the segment being drawn must leave stippleCounter_ where it ends (a next segment goes
  // on from there): otherwise the rasterizer need not walk the whole segment to count it.
  bool stippleEndNeeded_ = true;
  raster::FragmentSink* polygonSink_ = &stages_[0].processor;  // or its polygonStipple
  bool recording_ = false;   // GL_SELECT or GL_FEEDBACK: primitives go to recorder_
  bool lineReset_ = false;   // the next recorded line starts a new line (GL_LINE_RESET_TOKEN)
  PrimitiveRecorder recorder_;
  // Scratch space for clipped polygons.
  raster::ClipVertex clipped_[raster::kMaxClippedPolygonVertices + 3];
  raster::WindowVertex window_[raster::kMaxClippedPolygonVertices + 3];
  // Declared last, so that it is destroyed first: its destructor finishes the queued work,
  // which uses the fragment processor and the stipple filter above.
  raster::TiledRasterizer tiles_;
};

}  // namespace glass::gl
