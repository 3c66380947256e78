// glPixelStore and glReadPixels (spec 3.6.1, 4.3.2). Neither is compiled into display lists.
#include <GL/gl.h>

#include <cmath>
#include <new>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "fragment/read_pixels.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"

using glass::gl::Context;
using glass::gl::executeNow;
using glass::gl::PixelPacking;
using glass::gl::recordError;

namespace {

void pixelStore(GLenum pname, double value) {
  executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const bool pack = (pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT) ||
                      pname == GL_PACK_SKIP_IMAGES || pname == GL_PACK_IMAGE_HEIGHT;
    PixelPacking& p = pack ? ctx.pixelStore.pack : ctx.pixelStore.unpack;
    const int integer = static_cast<int>(std::lround(value));
    switch (pname) {
      case GL_PACK_SWAP_BYTES: case GL_UNPACK_SWAP_BYTES: p.swapBytes = value != 0.0; return;
      case GL_PACK_LSB_FIRST: case GL_UNPACK_LSB_FIRST: p.lsbFirst = value != 0.0; return;
      case GL_PACK_ALIGNMENT: case GL_UNPACK_ALIGNMENT:
        if (integer != 1 && integer != 2 && integer != 4 && integer != 8) {
          return recordError(ctx, GL_INVALID_VALUE);
        }
        p.alignment = integer;
        return;
      default: break;
    }
    int* field = nullptr;
    switch (pname) {
      case GL_PACK_ROW_LENGTH: case GL_UNPACK_ROW_LENGTH: field = &p.rowLength; break;
      case GL_PACK_SKIP_ROWS: case GL_UNPACK_SKIP_ROWS: field = &p.skipRows; break;
      case GL_PACK_SKIP_PIXELS: case GL_UNPACK_SKIP_PIXELS: field = &p.skipPixels; break;
      case GL_PACK_IMAGE_HEIGHT: case GL_UNPACK_IMAGE_HEIGHT: field = &p.imageHeight; break;
      case GL_PACK_SKIP_IMAGES: case GL_UNPACK_SKIP_IMAGES: field = &p.skipImages; break;
      default: return recordError(ctx, GL_INVALID_ENUM);
    }
    if (integer < 0) return recordError(ctx, GL_INVALID_VALUE);
    *field = integer;
  });
}

}  // namespace

extern "C" {

void glPixelStorei(GLenum pname, GLint param) { pixelStore(pname, param); }
void glPixelStoref(GLenum pname, GLfloat param) { pixelStore(pname, param); }

void glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                  GLvoid* pixels) {
  executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (width < 0 || height < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (const GLenum error = glass::gl::checkReadPixelsFormatAndType(format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    // Colour formats need a colour read buffer: none after glReadBuffer(GL_NONE).
    if (format != GL_DEPTH_COMPONENT && format != GL_STENCIL_INDEX &&
        !glass::gl::readsColor(ctx.pixelTransfer.readBuffer)) {
      return recordError(ctx, GL_INVALID_OPERATION);
    }
    if (!glass::gl::hasBufferToRead(ctx, format)) return recordError(ctx, GL_INVALID_OPERATION);
    if (!pixels) return;
    glass::gl::finishQueuedDrawing(ctx);
    const glass::gl::ReadBufferSelection read(ctx);
    try {
      glass::gl::readPixels(ctx, x, y, width, height, format, type, pixels);
    } catch (const std::bad_alloc&) {
      recordError(ctx, GL_OUT_OF_MEMORY);  // the imaging operations hold the whole block
    }
  });
}

}  // extern "C"
