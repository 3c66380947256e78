#include "primitive/draw_pipeline.h"

#include <algorithm>

#include "core/context.h"
#include "primitive/point_parameters.h"

namespace glass::gl {

void DrawPipeline::prepare() {
  Context& ctx = ctx_;
  prepareVertexStage(ctx, vertex_);
  fragments_.prepare(ctx, vertex_.phong);

  clip_.userPlaneMask = vertex_.clipPlaneMask;
  clip_.varyingCount = vertex_.varyingCount;
  viewport_ = makeViewportTransform(ctx.transform.viewport, ctx.transform.depthNear,
                                    ctx.transform.depthFar);

  // The scissor test as rasterization bounds (spec 4.1.2).
  raster::PixelRect bounds{0, 0, ctx.framebuffer.width(), ctx.framebuffer.height()};
  if (ctx.fragment.scissorTest) {
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

  polygonStipple_.prepare(r.polygonStipplePattern, fragments_);
  polygonSink_ = r.polygonStipple ? static_cast<raster::FragmentSink*>(&polygonStipple_) : &fragments_;
  recording_ = ctx.renderMode.mode != GL_RENDER;
  lineReset_ = false;
  if (recording_) recorder_.prepare(ctx, vertex_.texturing);
}

}  // namespace glass::gl
