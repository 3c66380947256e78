#include "primitive/draw_pipeline.h"

#include <algorithm>

#include "core/context.h"
#include "glass/raster/thread_count.h"
#include "primitive/point_parameters.h"
#include "primitive/queued_drawing.h"

namespace glass::gl {
namespace {

// The early depth test of triangles (glass/raster/depth_test.h): only when a fragment that fails
// the depth test has no effect. With the stencil test on, its depth-fail operation still writes
// the stencil buffer, so the test must wait for the fragment stage.
raster::EarlyDepthTest earlyDepthTest(const Context& ctx) {
  const FragmentState& f = ctx.fragment;
  raster::EarlyDepthTest early;
  if (!depthTestActive(ctx) || stencilTestActive(ctx) || f.depthFunc == GL_ALWAYS) return early;
  switch (f.depthFunc) {
    case GL_NEVER: early.compare = raster::DepthCompare::Never; break;
    case GL_LESS: early.compare = raster::DepthCompare::Less; break;
    case GL_EQUAL: early.compare = raster::DepthCompare::Equal; break;
    case GL_LEQUAL: early.compare = raster::DepthCompare::LessEqual; break;
    case GL_GREATER: early.compare = raster::DepthCompare::Greater; break;
    case GL_NOTEQUAL: early.compare = raster::DepthCompare::NotEqual; break;
    case GL_GEQUAL: early.compare = raster::DepthCompare::GreaterEqual; break;
    default: return early;
  }
  early.buffer = &ctx.framebuffer;
  return early;
}

}  // namespace

DrawPipeline::DrawPipeline(Context& ctx)
    : ctx_(ctx), tiles_(ctx.framebuffer, raster::configuredThreadCount()) {}

void DrawPipeline::prepare() {
  Context& ctx = ctx_;
  prepareVertexStage(ctx, vertex_);

  // Queued primitives of earlier draws still go through their stages, which change only when
  // nothing is queued: a draw whose fragments are treated as a queued draw's shares its stage
  // (the common case of many glBegin/glEnd pairs), another takes a free one, or finishes the
  // queued draws first when none is free.
  FragmentProcessor fragments;
  fragments.prepare(ctx, vertex_.phong);
  // (A queued glClear calls no sink, so it need not be finished first.)
  if (!tiles_.primitivesQueued()) stagesInUse_ = 0;
  stage_ = 0;
  while (stage_ < stagesInUse_ && !stages_[stage_].processor.sameSettings(fragments)) ++stage_;
  if (stage_ == stagesInUse_) {
    if (stagesInUse_ == kFragmentStages) {
      tiles_.finish();
      stage_ = stagesInUse_ = 0;
    }
    ++stagesInUse_;
    stage().processor = fragments;
    stage().polygonStipple.prepare(ctx.raster.polygonStipplePattern, stage().processor);
  }
  drawReadsContext_ = stage().processor.readsContextState() || ctx.raster.polygonStipple;

  clip_.userPlaneMask = vertex_.clipPlaneMask;
  clip_.varyingCount = vertex_.varyingCount;
  viewport_ = makeViewportTransform(ctx.transform.viewport, ctx.transform.depthNear,
                                    ctx.transform.depthFar);

  // The scissor test as rasterization bounds (spec 4.1.2).
  raster::PixelRect bounds{0, 0, ctx.framebuffer.width(), ctx.framebuffer.height()};
  statistics_ = frameStatisticsFor(ctx);
  // GLASS_STATS counts what the scissor test rejects: the fragment stage tests it instead.
  if (ctx.fragment.scissorTest && !statistics_) {
    const ScissorBox& s = ctx.fragment.scissor;
    bounds.x0 = std::max(bounds.x0, s.x);
    bounds.y0 = std::max(bounds.y0, s.y);
    bounds.x1 = static_cast<int>(std::min<long long>(bounds.x1, static_cast<long long>(s.x) + s.width));
    bounds.y1 = static_cast<int>(std::min<long long>(bounds.y1, static_cast<long long>(s.y) + s.height));
  }

  const RasterState& r = ctx.raster;
  // Attributes are always interpolated perspective-correctly, whatever
  // GL_PERSPECTIVE_CORRECTION_HINT says (the hint allows it; Mesa does the same).
  const bool perspective = true;
  triangleSettings_ = raster::TriangleSettings{};
  triangleSettings_.bounds = bounds;
  triangleSettings_.varyingCount = vertex_.varyingCount;
  triangleSettings_.perspectiveCorrect = perspective;
  triangleSettings_.earlyDepth = earlyDepthTest(ctx);
  triangleSettings_.depthUsed = depthTestActive(ctx);  // only the depth test reads a fragment's depth
  teaching_ = teachingCanvasFor(ctx);
  // The overdraw view counts every fragment rasterized: none may be dropped before the count.
  // So does GLASS_STATS, whose depth test count is the fragment stage's.
  if ((teaching_ && teaching_->view == TeachingView::Overdraw) || statistics_) triangleSettings_.earlyDepth = {};

  lineSettings_ = raster::LineSettings{};
  lineSettings_.bounds = bounds;
  lineSettings_.framebufferHeight = ctx.framebuffer.height();  // rows as Mesa numbers them
  lineSettings_.varyingCount = vertex_.varyingCount;
  lineSettings_.width = std::min(r.lineWidth, kMaxLineWidth);  // GL_ALIASED_LINE_WIDTH_RANGE
  lineSettings_.perspectiveCorrect = perspective;
  lineSettings_.stippleFactor = r.lineStipple ? r.lineStippleFactor : 0;
  lineSettings_.stipplePattern = r.lineStipplePattern;
  lineSettings_.stippleCounter = &stippleCounter_;

  pointSettings_ = raster::PointSettings{};
  pointSettings_.bounds = bounds;
  pointSettings_.varyingCount = vertex_.varyingCount;
  pointSettings_.size = std::min(r.pointSize, kMaxPointSize);  // GL_ALIASED_POINT_SIZE_RANGE
  smoothLines_ = r.lineSmooth;
  smoothPoints_ = r.pointSmooth;
  pointSizeAttenuated_ = pointSizeAttenuated(r);
  const float* attenuation = r.pointDistanceAttenuation;
  pointDistanceAttenuated_ =
      attenuation[0] != 1.0f || attenuation[1] != 0.0f || attenuation[2] != 0.0f;
  if (pointDistanceAttenuated_ && !invert(ctx.transform.projection.top(), projectionInverse_)) {
    projectionInverse_ = Matrix4{};  // a singular projection: every distance taken as 0
  }

  flat_ = r.shadeModel == GL_FLAT;
  stippleCounter_ = 0;

  polygonSink_ = r.polygonStipple ? static_cast<raster::FragmentSink*>(&stage().polygonStipple) : &stage().processor;
  recording_ = ctx.renderMode.mode != GL_RENDER;
  lineReset_ = false;
  if (recording_) recorder_.prepare(ctx, vertex_.texturing);
}

void DrawPipeline::finishIfReadingContext() {
  if (drawReadsContext_) tiles_.finish();
}

void DrawPipeline::finishQueuedWork() { tiles_.finish(); }

void DrawPipeline::beforeColorMaterialChange() {
  if (stage().processor.readsLighting()) tiles_.waitForThreads();
}

void finishQueuedDrawing(Context& ctx) {
  if (ctx.draw) ctx.draw->finishQueuedWork();
}

bool queueClear(Context& ctx, const raster::ClearRequest& request) {
  if (!ctx.draw) return false;
  ctx.draw->queueClear(request);
  return true;
}

void finishDrawReadingContext(Context& ctx) {
  if (ctx.draw) ctx.draw->finishIfReadingContext();
}

void beforeColorMaterialChange(Context& ctx) {
  if (ctx.draw) ctx.draw->beforeColorMaterialChange();
}

}  // namespace glass::gl
