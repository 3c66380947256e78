// glass/context.h: creating offscreen contexts, making them current, writing PNGs, the hooks
// of window systems (resizing, the flush callback), and switching the teaching view.
#include <glass/context.h>

#include <memory>
#include <new>
#include <optional>

#include "core/context.h"
#include "core/png_writer.h"
#include "core/transform_state.h"
#include "fragment/buffer_selection.h"
#include "primitive/queued_drawing.h"
#include "teaching/teaching_view.h"

struct GlassContext {
  // Held by pointer: glassResetContext puts a context in its initial state in its place.
  std::unique_ptr<glass::gl::Context> gl;
  GlassContext(int width, int height) : gl(std::make_unique<glass::gl::Context>(width, height)) {}
};

namespace {
thread_local GlassContext* currentGlassContext = nullptr;
}

GlassContext* glassCreateContext(int width, int height) {
  if (width <= 0 || height <= 0 || width > glass::gl::kMaxViewportSize ||
      height > glass::gl::kMaxViewportSize) {
    return nullptr;
  }
  try {
    return new GlassContext(width, height);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

int glassMakeCurrent(GlassContext* ctx) {
  currentGlassContext = ctx;
  glass::gl::setCurrentContext(ctx ? ctx->gl.get() : nullptr);
  return 1;
}

void glassDestroyContext(GlassContext* ctx) {
  if (!ctx) return;
  if (currentGlassContext == ctx) glassMakeCurrent(nullptr);
  delete ctx;
}

int glassWritePNG(GlassContext* ctx, const char* path) {
  if (!ctx) return 0;
  glass::gl::finishQueuedDrawing(*ctx->gl);
  if (const unsigned char* view = glass::gl::presentTeachingView(*ctx->gl)) {
    return glass::gl::writeRGBAPixelsPNG(view, ctx->gl->framebuffer.width(),
                                         ctx->gl->framebuffer.height(), path) ? 1 : 0;
  }
  const glass::raster::Framebuffer& fb = ctx->gl->framebuffer;
  return glass::gl::writeRGBAPixelsPNG(glass::gl::backBufferPixels(*ctx->gl), fb.width(), fb.height(), path) ? 1 : 0;
}

GlassContext* glassGetCurrentContext(void) { return currentGlassContext; }

int glassGetWidth(const GlassContext* ctx) { return ctx ? ctx->gl->framebuffer.width() : 0; }
int glassGetHeight(const GlassContext* ctx) { return ctx ? ctx->gl->framebuffer.height() : 0; }

namespace {

// The pixels a caller of glassGetColorBuffer or glassGetFrontBuffer reads: queued draws must be
// in them (finishing queued work changes no GL state, so the context stays logically const),
// and with GLASS_VIEW it sees the view's picture (teaching/teaching_view.h), else `buffer`'s.
const unsigned char* pixelsToRead(const GlassContext* ctx, const uint8_t* (*buffer)(const glass::gl::Context&)) {
  if (!ctx) return nullptr;
  glass::gl::Context& gl = *const_cast<GlassContext*>(ctx)->gl;
  glass::gl::finishQueuedDrawing(gl);
  if (const unsigned char* view = glass::gl::presentTeachingView(gl)) return view;
  return buffer(gl);
}

}  // namespace

const unsigned char* glassGetColorBuffer(const GlassContext* ctx) {
  return pixelsToRead(ctx, glass::gl::backBufferPixels);
}

const unsigned char* glassGetFrontBuffer(const GlassContext* ctx) {
  return pixelsToRead(ctx, glass::gl::frontBufferPixels);
}

int glassSetDoubleBuffered(GlassContext* ctx, int doubleBuffered) {
  // Between glBegin and glEnd the draw under way may be writing into both buffers.
  if (!ctx || ctx->gl->assembly.active) return 0;
  try {
    glass::gl::setDoubleBuffered(*ctx->gl, doubleBuffered != 0);
  } catch (const std::bad_alloc&) {
    return 0;
  }
  return 1;
}

int glassSwapBuffers(GlassContext* ctx) {
  if (!ctx) return 0;
  glass::gl::swapColorBuffers(*ctx->gl);
  return 1;
}

int glassSetAncillaryBuffers(GlassContext* ctx, int depth, int stencil, int accumulation) {
  if (!ctx) return 0;
  glass::gl::finishQueuedDrawing(*ctx->gl);  // what is queued was drawn with the buffers it had
  glass::gl::AncillaryBuffers& buffers = ctx->gl->buffers;
  buffers.depth = depth != 0;
  buffers.stencil = stencil != 0;
  buffers.accumulation = accumulation != 0;
  return 1;
}

int glassSetAlphaBitplanes(GlassContext* ctx, int alpha) {
  if (!ctx) return 0;
  glass::gl::setAlphaBitplanes(*ctx->gl, alpha != 0);
  return 1;
}

int glassResizeContext(GlassContext* ctx, int width, int height) {
  if (!ctx || width <= 0 || height <= 0 || width > glass::gl::kMaxViewportSize ||
      height > glass::gl::kMaxViewportSize) {
    return 0;
  }
  try {
    glass::gl::resizeFramebuffer(*ctx->gl, width, height);
  } catch (...) {  // no memory, or no threads for the rasterizer: the context is as it was
    return 0;
  }
  return 1;
}

int glassResetContext(GlassContext* ctx) {
  if (!ctx) return 0;
  try {
    std::unique_ptr<glass::gl::Context> fresh = glass::gl::contextInInitialState(*ctx->gl);
    const bool current = glass::gl::currentContext() == ctx->gl.get();
    ctx->gl = std::move(fresh);
    if (current) glass::gl::setCurrentContext(ctx->gl.get());
  } catch (...) {  // no memory, or no threads for the rasterizer: the context is as it was
    return 0;
  }
  return 1;
}

void glassSetFlushCallback(GlassContext* ctx, GlassFlushCallback callback, void* userData) {
  if (!ctx) return;
  if (!callback) {
    ctx->gl->afterFlush = nullptr;
    return;
  }
  ctx->gl->afterFlush = [ctx, callback, userData](glass::gl::Context&) { callback(ctx, userData); };
}

int glassWritePixelsPNG(const char* path, int width, int height, const unsigned char* rgba) {
  return glass::gl::writeRGBAPixelsPNG(rgba, width, height, path) ? 1 : 0;
}

int glassSetView(GlassContext* ctx, const char* name) {
  if (!ctx) return 0;
  std::optional<glass::gl::TeachingView> view;
  if (name) {
    view = glass::gl::parseTeachingView(name);
    if (!view) return 0;
  }
  // Between glBegin and glEnd the draw under way holds the view's canvas.
  if (ctx->gl->assembly.active) return 0;
  // The rasterizer's threads write into the canvas a queued draw holds: they must be done.
  glass::gl::finishQueuedDrawing(*ctx->gl);
  glass::gl::setTeachingView(*ctx->gl, view);
  return 1;
}

const char* glassGetView(const GlassContext* ctx) {
  if (!ctx) return nullptr;
  const std::optional<glass::gl::TeachingView> view = glass::gl::teachingViewOf(*ctx->gl);
  return view ? glass::gl::teachingViewName(*view) : nullptr;
}
