// glDrawBuffer and glReadBuffer (spec 4.2.1, 4.3.2): which colour buffer fragments go to and
// pixels are read from (fragment/buffer_selection.h). Both are compiled into display lists.
#include <GL/gl.h>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "lists/command_recording.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;

extern "C" {

void glDrawBuffer(GLenum buffer) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (const GLenum error = glass::gl::drawBufferError(buffer); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    ctx.fragment.drawBuffer = buffer;
    glass::gl::selectDrawBuffer(ctx);
  });
}

void glReadBuffer(GLenum buffer) {
  compileOrExecute([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (const GLenum error = glass::gl::readBufferError(buffer); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    ctx.pixelTransfer.readBuffer = buffer;
  });
}

}  // extern "C"
