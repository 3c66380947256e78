// The array drawing commands later versions defined through glDrawElements and glDrawArrays:
// glDrawRangeElements (OpenGL 1.2, spec 2.8), glMultiDrawArrays and glMultiDrawElements
// (OpenGL 1.4, spec 2.8). Each checks its own arguments, then draws exactly as the commands it is
// defined by, which also read the array data at compile time inside a display list.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "vertex/primitive_assembly.h"

using glass::gl::Context;
using glass::gl::recordError;

namespace {

// The errors a call sets before drawing anything; false when it may go on.
bool argumentsAccepted(GLenum mode, GLsizei count) {
  return glass::gl::queryNow(false, [=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return false;
    if (!glass::gl::isPrimitiveMode(mode)) {
      recordError(ctx, GL_INVALID_ENUM);
      return false;
    }
    if (count < 0) {
      recordError(ctx, GL_INVALID_VALUE);
      return false;
    }
    return true;
  });
}

}  // namespace

extern "C" {

// Spec 2.8: like glDrawElements, with the promise that every index lies in [start, end]; end <
// start is GL_INVALID_VALUE. Indices outside the range are drawn all the same (the spec leaves
// them undefined; Mesa draws them too).
void glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                         const GLvoid* indices) {
  if (!argumentsAccepted(mode, count)) return;
  if (end < start) {
    glass::gl::executeNow([](Context& ctx) { recordError(ctx, GL_INVALID_VALUE); });
    return;
  }
  glDrawElements(mode, count, type, indices);
}

// Spec 2.8 (1.4): for each i with count[i] > 0, DrawArrays(mode, first[i], count[i]).
void glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count, GLsizei primcount) {
  if (!argumentsAccepted(mode, primcount) || !first || !count) return;
  for (GLsizei i = 0; i < primcount; ++i) {
    if (count[i] > 0) glDrawArrays(mode, first[i], count[i]);
  }
}

// Spec 2.8 (1.4): for each i with count[i] > 0, DrawElements(mode, count[i], type, indices[i]).
void glMultiDrawElements(GLenum mode, const GLsizei* count, GLenum type,
                         const GLvoid* const* indices, GLsizei primcount) {
  if (!argumentsAccepted(mode, primcount) || !count || !indices) return;
  for (GLsizei i = 0; i < primcount; ++i) {
    if (count[i] > 0) glDrawElements(mode, count[i], type, indices[i]);
  }
}

}  // extern "C"
