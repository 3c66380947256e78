#include "fragment/buffer_selection.h"

#include <cstring>

#include "core/context.h"
#include "primitive/queued_drawing.h"

namespace glass::gl {

namespace {

// Table 4.4: the buffers a name denotes. glass's framebuffer has the front-left buffer, and the
// back-left one when double-buffered (a single-buffered one takes the back-left names as its one
// buffer, see the header).
bool namesAColorBuffer(GLenum buffer) {
  switch (buffer) {
    case GL_FRONT: case GL_BACK: case GL_LEFT: case GL_FRONT_LEFT: case GL_BACK_LEFT:
    case GL_FRONT_AND_BACK:
      return true;
    default: return false;
  }
}

// Names of buffers that exist in some framebuffer, but not in glass's: selecting them is
// GL_INVALID_OPERATION (spec 4.2.1), not GL_INVALID_ENUM.
bool namesAMissingBuffer(GLenum buffer) {
  switch (buffer) {
    case GL_RIGHT: case GL_FRONT_RIGHT: case GL_BACK_RIGHT:
      return true;
    default: return buffer >= GL_AUX0 && buffer <= GL_AUX3;
  }
}

bool namesFrontOnly(GLenum buffer) { return buffer == GL_FRONT || buffer == GL_FRONT_LEFT; }
bool namesBoth(GLenum buffer) { return buffer == GL_FRONT_AND_BACK || buffer == GL_LEFT; }

// The buffer a read of `buffer` reads: GL_FRONT_AND_BACK and GL_LEFT read the front one, as in
// Mesa (spec 4.3.2 leaves them out of glReadBuffer).
int readColorBuffer(GLenum buffer) {
  return namesFrontOnly(buffer) || namesBoth(buffer) ? kFrontColorBuffer : kBackColorBuffer;
}

int drawColorBuffer(GLenum buffer) { return namesFrontOnly(buffer) ? kFrontColorBuffer : kBackColorBuffer; }

}  // namespace

void selectColorBuffer(Context& ctx, int index) {
  if (ctx.framebuffer.selectedColorBuffer() == index) return;
  finishQueuedDrawing(ctx);  // the queued fragments go to the buffer selected when they came
  ctx.framebuffer.selectColorBuffer(index);
}

GLenum drawBufferError(GLenum buffer) {
  if (buffer == GL_NONE || namesAColorBuffer(buffer)) return GL_NO_ERROR;
  return namesAMissingBuffer(buffer) ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

// Spec 4.3.2 lists neither GL_FRONT_AND_BACK (two buffers) nor GL_NONE for glReadBuffer; Mesa
// accepts both, and so does glass.
GLenum readBufferError(GLenum buffer) { return drawBufferError(buffer); }

bool isDoubleBuffered(const Context& ctx) { return ctx.framebuffer.hasSecondColorBuffer(); }

GLenum initialColorBuffer(const Context& ctx) { return isDoubleBuffered(ctx) ? GL_BACK : GL_FRONT; }

void setDoubleBuffered(Context& ctx, bool doubleBuffered) {
  finishQueuedDrawing(ctx);
  if (doubleBuffered) {
    ctx.framebuffer.addSecondColorBuffer();
  } else {
    ctx.framebuffer.removeSecondColorBuffer();
  }
  ctx.fragment.drawBuffer = ctx.pixelTransfer.readBuffer = initialColorBuffer(ctx);
  selectDrawBuffer(ctx);
}

void selectDrawBuffer(Context& ctx) {
  selectColorBuffer(ctx, isDoubleBuffered(ctx) ? drawColorBuffer(ctx.fragment.drawBuffer) : kBackColorBuffer);
}

bool writesBothBuffers(const Context& ctx) { return isDoubleBuffered(ctx) && namesBoth(ctx.fragment.drawBuffer); }

ReadBufferSelection::ReadBufferSelection(Context& ctx) : ctx_(ctx) {
  if (isDoubleBuffered(ctx)) selectColorBuffer(ctx, readColorBuffer(ctx.pixelTransfer.readBuffer));
}

ReadBufferSelection::~ReadBufferSelection() { selectDrawBuffer(ctx_); }

void swapColorBuffers(Context& ctx) {
  if (!isDoubleBuffered(ctx)) return;
  finishQueuedDrawing(ctx);
  raster::Framebuffer& fb = ctx.framebuffer;
  const size_t bytes = static_cast<size_t>(fb.width()) * fb.height() * 4;
  std::memcpy(fb.colorBufferPixels(kFrontColorBuffer), fb.colorBufferPixels(kBackColorBuffer), bytes);
}

const uint8_t* frontBufferPixels(const Context& ctx) {
  return ctx.framebuffer.colorBufferPixels(isDoubleBuffered(ctx) ? kFrontColorBuffer : kBackColorBuffer);
}

const uint8_t* backBufferPixels(const Context& ctx) { return ctx.framebuffer.colorBufferPixels(kBackColorBuffer); }

}  // namespace glass::gl
