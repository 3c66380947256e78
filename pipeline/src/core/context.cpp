#include "core/context.h"

#include "primitive/draw_pipeline.h"
#include "primitive/queued_drawing.h"
#include "teaching/frame_statistics.h"
#include "teaching/statistics_query.h"
#include "teaching/teaching_view.h"
#include "teaching/vertex_trace.h"

namespace glass::gl {

Context::Context(int width, int height)
    : framebuffer(width, height), draw(std::make_unique<DrawPipeline>(*this)) {
  // Spec 2.11.1 and 4.1.2: the viewport and the scissor box start as the whole window.
  transform.viewport = Viewport{0, 0, width, height};
  fragment.scissor = ScissorBox{0, 0, width, height};
  attachTeachingViewFromEnvironment(*this);
  attachFrameStatisticsFromEnvironment(*this);
  attachVertexTraceFromEnvironment(*this);
}

Context::~Context() {
  detachTeachingView(*this);
  detachFrameStatistics(*this);
  detachStatisticsQueries(*this);
  detachVertexTrace(*this);
}

void resizeFramebuffer(Context& ctx, int width, int height) {
  finishQueuedDrawing(ctx);
  // The draw pipeline's tiles cover the framebuffer it is made for: it is made again after.
  raster::Framebuffer resized(width, height);
  std::swap(ctx.framebuffer, resized);
  try {
    ctx.draw = std::make_unique<DrawPipeline>(ctx);
  } catch (...) {
    std::swap(ctx.framebuffer, resized);
    throw;
  }
  std::vector<int16_t>().swap(ctx.accumulation.buffer);
}

namespace {
thread_local Context* current = nullptr;
}

Context* currentContext() { return current; }
void setCurrentContext(Context* ctx) { current = ctx; }

}  // namespace glass::gl
