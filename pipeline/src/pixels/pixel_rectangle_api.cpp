// glDrawPixels, glCopyPixels and glBitmap (OpenGL 1.5 specification, sections 3.6.4, 4.3.3 and
// 3.7). All three are compiled into display lists; glDrawPixels and glBitmap unpack their client
// data when compiled (spec 5.4). Errors are found when the command is given and recorded when it
// executes, as for every compiled command.
#include <GL/gl.h>

#include <memory>
#include <new>
#include <vector>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"
#include "pixels/pixel_fragments.h"
#include "pixels/pixel_image.h"
#include "texture/client_pixels.h"

using glass::gl::Context;
using glass::gl::recordError;

namespace {

// Compiles or runs a command that either fails with `error` or does `work`.
template <class Work>
void pixelCommand(Context& ctx, GLenum error, Work work) {
  glass::gl::compileOrExecuteOn(ctx, [=](Context& c) {
    if (glass::gl::rejectInsideBeginEnd(c)) return;
    if (error != GL_NO_ERROR) return recordError(c, error);
    glass::gl::finishQueuedDrawing(c);  // the pixels read and write the framebuffer
    work(c);
  });
}

// Between glBegin and glEnd (and not compiling a list) the command will be refused with
// GL_INVALID_OPERATION, so its client data is not read: the unpack state its caller meant for it
// may itself have been refused there (glPixelStore is an error between glBegin and glEnd), and
// reading by the state in force could run past the caller's data.
bool refusedBeforeReading(const Context& ctx) { return ctx.assembly.active && !ctx.lists.isCompiling(); }

}  // namespace

extern "C" {

void glDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type, const GLvoid* pixels) {
  glass::gl::executeNow([=](Context& ctx) {
    GLenum error = glass::gl::checkPixelFormatAndType(format, type);
    if (width < 0 || height < 0) error = GL_INVALID_VALUE;
    // Executed now, the common colour images may go into the colour buffer as they are.
    if (error == GL_NO_ERROR && pixels != nullptr && !ctx.assembly.active && !ctx.lists.isCompiling()) {
      glass::gl::finishQueuedDrawing(ctx);
      if (glass::gl::drawPixelBytes(ctx, pixels, width, height, format, type, ctx.pixelStore.unpack)) return;
    }
    std::shared_ptr<const glass::gl::UnpackedImage> image;
    if (error == GL_NO_ERROR && pixels != nullptr && !refusedBeforeReading(ctx)) {
      try {
        image = std::make_shared<const glass::gl::UnpackedImage>(
            glass::gl::unpackImage(pixels, width, height, format, type, ctx.pixelStore.unpack));
      } catch (const std::bad_alloc&) {
        error = GL_OUT_OF_MEMORY;
      }
    }
    pixelCommand(ctx, error, [image](Context& c) {
      if (image) glass::gl::drawPixels(c, *image);
    });
  });
}

void glCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  glass::gl::executeNow([=](Context& ctx) {
    GLenum error = GL_NO_ERROR;
    if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) error = GL_INVALID_ENUM;
    else if (width < 0 || height < 0) error = GL_INVALID_VALUE;
    pixelCommand(ctx, error, [=](Context& c) {
      // Copying colour needs a colour read buffer: none after glReadBuffer(GL_NONE).
      if (type == GL_COLOR && !glass::gl::readsColor(c.pixelTransfer.readBuffer)) {
        return recordError(c, GL_INVALID_OPERATION);
      }
      if (!glass::gl::hasBufferToRead(c, type)) return recordError(c, GL_INVALID_OPERATION);
      try {
        glass::gl::copyPixels(c, x, y, width, height, type);
      } catch (const std::bad_alloc&) {
        recordError(c, GL_OUT_OF_MEMORY);
      }
    });
  });
}

void glBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
              GLfloat ymove, const GLubyte* bitmap) {
  glass::gl::executeNow([=](Context& ctx) {
    GLenum error = (width < 0 || height < 0) ? GL_INVALID_VALUE : GL_NO_ERROR;
    auto bits = std::make_shared<std::vector<uint8_t>>();
    if (error == GL_NO_ERROR && bitmap != nullptr && width > 0 && height > 0 && !refusedBeforeReading(ctx)) {
      try {
        bits->resize(static_cast<size_t>(width) * static_cast<size_t>(height));
        std::vector<int32_t> row(static_cast<size_t>(width));
        for (int j = 0; j < height; ++j) {
          glass::gl::unpackIndexRow(bitmap, width, j, GL_BITMAP, ctx.pixelStore.unpack, row.data());
          for (int i = 0; i < width; ++i) (*bits)[static_cast<size_t>(j) * width + i] = static_cast<uint8_t>(row[i]);
        }
      } catch (const std::bad_alloc&) {
        error = GL_OUT_OF_MEMORY;
      }
    }
    std::shared_ptr<const std::vector<uint8_t>> unpacked = std::move(bits);
    pixelCommand(ctx, error, [=](Context& c) {
      glass::gl::drawBitmap(c, width, height, xorig, yorig, xmove, ymove, *unpacked);
    });
  });
}

}  // extern "C"
