#include "core/context.h"

#include "fragment/buffer_selection.h"
#include "primitive/draw_pipeline.h"
#include "primitive/queued_drawing.h"
#include "teaching/frame_statistics.h"
#include "teaching/statistics_query.h"
#include "teaching/teaching_view.h"
#include "teaching/vertex_trace.h"

namespace glass::gl {

namespace {

// Swaps `other` in as ctx's framebuffer and makes the draw pipeline over it (its tiles cover the
// framebuffer it is made for); if that throws, swaps back, and ctx keeps what it had.
void drawIntoFramebuffer(Context& ctx, raster::Framebuffer& other) {
  std::swap(ctx.framebuffer, other);
  try {
    ctx.draw = std::make_unique<DrawPipeline>(ctx);
  } catch (...) {
    std::swap(ctx.framebuffer, other);
    throw;
  }
}

}  // namespace

Context::Context(int width, int height)
    : framebuffer(width, height), draw(std::make_unique<DrawPipeline>(*this)) {
  startInInitialState();
}

Context::Context(raster::Framebuffer& taken) : framebuffer(1, 1) {
  drawIntoFramebuffer(*this, taken);
  try {
    startInInitialState();
  } catch (...) {
    std::swap(framebuffer, taken);
    throw;
  }
}

void Context::startInInitialState() {
  // Spec 2.11.1 and 4.1.2: the viewport and the scissor box start as the whole window.
  const int width = framebuffer.width(), height = framebuffer.height();
  transform.viewport = Viewport{0, 0, width, height};
  fragment.scissor = ScissorBox{0, 0, width, height};
  // Spec 4.2.1, 4.3.2: drawing and reading start on the back buffer of a double-buffered
  // framebuffer (one taken over from another context may be).
  fragment.drawBuffer = pixelTransfer.readBuffer = initialColorBuffer(*this);
  selectDrawBuffer(*this);
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
  raster::Framebuffer resized(width, height);
  if (isDoubleBuffered(ctx)) resized.addSecondColorBuffer();
  drawIntoFramebuffer(ctx, resized);
  if (!ctx.buffers.colorAlpha) fillColorAlpha(ctx.framebuffer);
  selectDrawBuffer(ctx);
  std::vector<int16_t>().swap(ctx.accumulation.buffer);
}

std::unique_ptr<Context> contextInInitialState(Context& previous) {
  finishQueuedDrawing(previous);
  // Everything that can throw comes first, while previous is untouched but for its framebuffer,
  // which the fresh context gives back if it throws: the fresh context over that framebuffer
  // (one draw pipeline, made once), then its view.
  auto fresh = std::make_unique<Context>(previous.framebuffer);
  try {
    setTeachingView(*fresh, teachingViewOf(previous));
  } catch (...) {
    std::swap(fresh->framebuffer, previous.framebuffer);
    throw;
  }
  fresh->buffers = previous.buffers;
  fresh->lists.lists = previous.lists.lists;
  fresh->texture.names = previous.texture.names;
  fresh->accumulation.buffer = std::move(previous.accumulation.buffer);
  fresh->afterFlush = std::move(previous.afterFlush);
  return fresh;
}

namespace {
// Every GL call reads this. In a shared library the default (general-dynamic) model asks
// __tls_get_addr for it each time; the initial-exec model is one load from the thread pointer.
// It takes 8 bytes of the static TLS block, which the C library keeps a reserve of for libraries
// loaded later with dlopen (as Python's OpenGL package loads libOSMesa), as other GL libraries
// rely on for their current context too.
#if defined(__GNUC__)
__attribute__((tls_model("initial-exec")))
#endif
thread_local Context* current = nullptr;
}  // namespace

Context* currentContext() { return current; }
void setCurrentContext(Context* ctx) { current = ctx; }

}  // namespace glass::gl
