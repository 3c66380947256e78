// glAccum and glClearAccum (OpenGL 1.5 specification, sections 4.2.4 and 4.2.3). Both are
// compiled into display lists; neither is allowed between glBegin and glEnd.
#include <GL/gl.h>

#include <algorithm>

#include "accum/accumulation.h"
#include "core/context.h"
#include "lists/command_recording.h"
#include "primitive/queued_drawing.h"

using glass::gl::Context;

extern "C" {

void glAccum(GLenum op, GLfloat value) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!glass::gl::isAccumOperation(op)) return glass::gl::recordError(ctx, GL_INVALID_ENUM);
    if (!ctx.buffers.accumulation) return glass::gl::recordError(ctx, GL_INVALID_OPERATION);
    glass::gl::finishQueuedDrawing(ctx);
    glass::gl::accumulate(ctx, op, value);
  });
}

void glClearAccum(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    // Spec 4.2.3: the values are clamped to [-1, 1].
    const float values[4] = {red, green, blue, alpha};
    for (int k = 0; k < 4; ++k) ctx.accumulation.clearValue[k] = std::clamp(values[k], -1.0f, 1.0f);
  });
}

}  // extern "C"
