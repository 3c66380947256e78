// <GL/osmesa.h>: creating OSMesa contexts, binding them to the caller's buffer, its layout and
// queries (Mesa's include/GL/osmesa.h, version 11.2, describes each function). osmesa_context.h
// says when the caller's buffer is read and written.
#include <GL/osmesa.h>

#include <cstdio>
#include <new>
#include <string>
#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "core/transform_state.h"
#include "osmesa/context_request.h"
#include "osmesa/osmesa_context.h"
#include "primitive/queued_drawing.h"

using glass::osmesa::storeBuffers;

namespace {

// The OSMesa context made current on this thread by OSMesaMakeCurrent.
thread_local OSMesaContext boundOnThisThread = nullptr;

// It, while GL calls still go to it (glassMakeCurrent may have made another context current).
OSMesaContext currentOSMesaContext() {
  OSMesaContext ctx = boundOnThisThread;
  return ctx && glass::gl::currentContext() == &ctx->gl ? ctx : nullptr;
}

OSMesaContext createContext(const int* attributes, OSMesaContext sharelist, const char* function) {
  glass::osmesa::ContextRequest request;
  std::string error;
  if (!glass::osmesa::readContextRequest(attributes, request, error)) {
    std::fprintf(stderr, "%s: %s\n", function, error.c_str());
    return nullptr;
  }
  try {
    auto* ctx = new osmesa_context(request.format);
    // Asking for 0 bits gives no such buffer (core/ancillary_buffers.h).
    ctx->gl.buffers.depth = request.depthBits > 0;
    ctx->gl.buffers.stencil = request.stencilBits > 0;
    ctx->gl.buffers.accumulation = request.accumBits > 0;
    // A format without alpha gives a colour buffer without alpha bitplanes, as in Mesa.
    glass::gl::setAlphaBitplanes(ctx->gl, glass::osmesa::formatHasAlpha(request.format));
    // Display lists and texture objects are shared (docs/osmesa.md).
    if (sharelist) {
      ctx->gl.lists.lists = sharelist->gl.lists.lists;
      ctx->gl.texture.names = sharelist->gl.texture.names;
    }
    return ctx;
  } catch (...) {  // no memory, or no threads for the rasterizer
    return nullptr;
  }
}

// The buffer's layout as the context's settings make it now.
glass::osmesa::BufferLayout layoutFor(const osmesa_context& ctx, GLenum type, int width, int height) {
  glass::osmesa::BufferLayout layout;
  layout.format = ctx.format;
  layout.type = type;
  layout.width = width;
  layout.height = height;
  layout.rowLength = ctx.rowLengthSetting != 0 ? ctx.rowLengthSetting : width;
  layout.yUp = ctx.yUp;
  return layout;
}

// The buffer is the colour buffer: read it again as the new layout lays it out. Programs set the
// layout right after OSMesaMakeCurrent, before drawing; the old layout's picture is not stored
// first, since it would write the new layout's row padding.
template <typename Change>
void changeLayout(osmesa_context& ctx, Change change) {
  change();
  if (!ctx.buffer) return;
  glass::gl::finishQueuedDrawing(ctx.gl);
  ctx.layout = layoutFor(ctx, ctx.layout.type, ctx.layout.width, ctx.layout.height);
  glass::osmesa::loadColorBuffer(ctx.buffer, ctx.layout, ctx.gl.framebuffer);
}

// Releases this thread's OSMesa context, leaving the picture in its buffer.
void releaseBoundContext() {
  OSMesaContext ctx = boundOnThisThread;
  if (!ctx) return;
  storeBuffers(*ctx);
  if (glass::gl::currentContext() == &ctx->gl) glass::gl::setCurrentContext(nullptr);
  boundOnThisThread = nullptr;
  ctx->current = false;
}

void clearOutputs(GLint* width, GLint* height, GLint* third, void** buffer) {
  if (width) *width = 0;
  if (height) *height = 0;
  if (third) *third = 0;
  if (buffer) *buffer = nullptr;
}

}  // namespace

extern "C" {

OSMesaContext OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

OSMesaContext OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                     GLint accumBits, OSMesaContext sharelist) {
  const int attributes[] = {OSMESA_FORMAT, static_cast<int>(format), OSMESA_DEPTH_BITS, depthBits,
                            OSMESA_STENCIL_BITS, stencilBits, OSMESA_ACCUM_BITS, accumBits, 0};
  return createContext(attributes, sharelist, "OSMesaCreateContextExt");
}

OSMesaContext OSMesaCreateContextAttribs(const int* attribList, OSMesaContext sharelist) {
  return createContext(attribList, sharelist, "OSMesaCreateContextAttribs");
}

void OSMesaDestroyContext(OSMesaContext ctx) {
  if (!ctx) return;
  // The caller's buffer is not written: programs often free it before destroying the context.
  if (boundOnThisThread == ctx) {
    if (glass::gl::currentContext() == &ctx->gl) glass::gl::setCurrentContext(nullptr);
    boundOnThisThread = nullptr;
  }
  delete ctx;
}

GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type, GLsizei width,
                            GLsizei height) {
  if (!ctx && !buffer) {
    releaseBoundContext();
    return GL_TRUE;
  }
  if (!ctx || !buffer || width < 1 || height < 1 || width > glass::gl::kMaxViewportSize ||
      height > glass::gl::kMaxViewportSize || !glass::osmesa::acceptsType(ctx->format, type)) {
    return GL_FALSE;
  }
  // Rows shorter than the width would overlap, and the last one would run past the buffer.
  if (ctx->rowLengthSetting != 0 && ctx->rowLengthSetting < width) return GL_FALSE;
  // A context is current on one thread at most.
  const bool claimed = ctx != boundOnThisThread;
  if (claimed) {
    bool wasCurrent = false;
    if (!ctx->current.compare_exchange_strong(wasCurrent, true)) return GL_FALSE;
  }

  // Leaving the previous buffer (of this or another context) holding its picture.
  if (boundOnThisThread) storeBuffers(*boundOnThisThread);

  glass::gl::Context& gl = ctx->gl;
  if (gl.framebuffer.width() != width || gl.framebuffer.height() != height) {
    try {
      glass::gl::resizeFramebuffer(gl, width, height);
    } catch (...) {
      if (claimed) ctx->current = false;
      return GL_FALSE;
    }
    std::vector<uint32_t>().swap(ctx->depthCopy);  // OSMesaGetDepthBuffer makes a new one
  }
  if (claimed && boundOnThisThread) boundOnThisThread->current = false;

  if (!ctx->buffer) {
    // The first binding sizes the viewport and the scissor box to the buffer (Mesa's
    // _mesa_make_current does so for a context whose viewport was never set).
    gl.transform.viewport = glass::gl::Viewport{0, 0, width, height};
    gl.fragment.scissor = glass::gl::ScissorBox{0, 0, width, height};
  }
  ctx->buffer = buffer;
  ctx->layout = layoutFor(*ctx, type, width, height);
  glass::gl::finishQueuedDrawing(gl);
  glass::osmesa::loadColorBuffer(buffer, ctx->layout, gl.framebuffer);

  boundOnThisThread = ctx;
  glass::gl::setCurrentContext(&gl);
  return GL_TRUE;
}

OSMesaContext OSMesaGetCurrentContext(void) { return currentOSMesaContext(); }

void OSMesaPixelStore(GLint pname, GLint value) {
  OSMesaContext ctx = currentOSMesaContext();
  if (!ctx) return;
  switch (pname) {
    case OSMESA_ROW_LENGTH:
      if (value < 0 || (value != 0 && ctx->buffer && value < ctx->layout.width)) {
        return glass::gl::recordError(ctx->gl, GL_INVALID_VALUE);
      }
      changeLayout(*ctx, [&] { ctx->rowLengthSetting = value; });
      return;
    case OSMESA_Y_UP:
      changeLayout(*ctx, [&] { ctx->yUp = value != 0; });
      return;
    default:
      return glass::gl::recordError(ctx->gl, GL_INVALID_ENUM);
  }
}

void OSMesaGetIntegerv(GLint pname, GLint* value) {
  if (!value) return;
  OSMesaContext ctx = currentOSMesaContext();
  const bool bound = ctx && ctx->buffer;
  switch (pname) {
    case OSMESA_WIDTH: *value = bound ? ctx->layout.width : 0; return;
    case OSMESA_HEIGHT: *value = bound ? ctx->layout.height : 0; return;
    case OSMESA_FORMAT: *value = ctx ? static_cast<GLint>(ctx->format) : 0; return;
    case OSMESA_TYPE: *value = bound ? static_cast<GLint>(ctx->layout.type) : 0; return;
    case OSMESA_ROW_LENGTH: *value = ctx ? ctx->rowLengthSetting : 0; return;
    case OSMESA_Y_UP: *value = ctx && ctx->yUp ? 1 : 0; return;
    case OSMESA_MAX_WIDTH:
    case OSMESA_MAX_HEIGHT: *value = glass::gl::kMaxViewportSize; return;
    default:
      if (ctx) glass::gl::recordError(ctx->gl, GL_INVALID_ENUM);
      return;
  }
}

GLboolean OSMesaGetDepthBuffer(OSMesaContext c, GLint* width, GLint* height, GLint* bytesPerValue,
                               void** buffer) {
  if (!c || !c->buffer || !c->gl.buffers.depth || !width || !height || !bytesPerValue || !buffer) {
    clearOutputs(width, height, bytesPerValue, buffer);
    return GL_FALSE;
  }
  const glass::raster::Framebuffer& fb = c->gl.framebuffer;
  try {
    c->depthCopy.resize(static_cast<size_t>(fb.width()) * static_cast<size_t>(fb.height()));
  } catch (const std::bad_alloc&) {
    clearOutputs(width, height, bytesPerValue, buffer);
    return GL_FALSE;
  }
  glass::osmesa::copyDepthBuffer(*c);
  *width = fb.width();
  *height = fb.height();
  *bytesPerValue = 4;
  *buffer = c->depthCopy.data();
  return GL_TRUE;
}

GLboolean OSMesaGetColorBuffer(OSMesaContext c, GLint* width, GLint* height, GLint* format,
                               void** buffer) {
  if (!c || !c->buffer || !width || !height || !format || !buffer) {
    clearOutputs(width, height, format, buffer);
    return GL_FALSE;
  }
  storeBuffers(*c);
  *width = c->layout.width;
  *height = c->layout.height;
  *format = static_cast<GLint>(c->format);
  *buffer = c->buffer;
  return GL_TRUE;
}

void OSMesaColorClamp(GLboolean) {
  // Colours are stored with 8 bits in [0, 1] (osmesa/buffer_layout.h): always clamped already.
}

void OSMesaPostprocess(OSMesaContext, const char* filter, unsigned) {
  std::fprintf(stderr, "OSMesaPostprocess: glass has no post-processing filters; \"%s\" ignored\n",
               filter ? filter : "(null)");
}

}  // extern "C"
