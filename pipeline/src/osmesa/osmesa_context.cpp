#include "osmesa/osmesa_context.h"

#include "primitive/queued_drawing.h"
#include "teaching/teaching_view.h"

osmesa_context::osmesa_context(GLenum bufferFormat) : gl(1, 1), format(bufferFormat) {
  layout.format = bufferFormat;
  // glFlush and glFinish: the caller reads the buffer after them (Mesa's OSMesa copies there too).
  gl.afterFlush = [this](glass::gl::Context&) { glass::osmesa::storeBuffers(*this); };
}

namespace glass::osmesa {

void storeBuffers(osmesa_context& ctx) {
  if (!ctx.buffer) return;
  gl::finishQueuedDrawing(ctx.gl);
  // With GLASS_VIEW the caller's buffer receives the view's picture, as glassGetColorBuffer
  // does (teaching/teaching_view.h); the colour buffer keeps the program's colours.
  const uint8_t* view = gl::presentTeachingView(ctx.gl);
  storeColorBuffer(view ? view : ctx.gl.framebuffer.colorAt(0, 0), ctx.layout, ctx.buffer);
  if (!ctx.depthCopy.empty()) copyDepthBuffer(ctx);
}

void copyDepthBuffer(osmesa_context& ctx) {
  gl::finishQueuedDrawing(ctx.gl);
  // Mesa's Z24_UNORM_S8_UINT layout: the depth in the low 24 bits, the stencil value above.
  const raster::Framebuffer& fb = ctx.gl.framebuffer;
  for (int y = 0; y < fb.height(); ++y) {
    const uint32_t* depth = fb.depthAt(0, y);
    const uint8_t* stencil = fb.stencilAt(0, y);
    uint32_t* out = &ctx.depthCopy[static_cast<std::size_t>(y) * static_cast<std::size_t>(fb.width())];
    for (int x = 0; x < fb.width(); ++x) out[x] = depth[x] | static_cast<uint32_t>(stencil[x]) << 24;
  }
}

}  // namespace glass::osmesa
