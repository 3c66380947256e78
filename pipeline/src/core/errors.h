// The GL error flag (spec 2.5): the first error since the last glGetError is kept, later ones are
// dropped until it is read.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct ErrorState {
  GLenum error = GL_NO_ERROR;
};

struct Context;

// Sets the error flag unless an earlier error is still unread.
void recordError(Context& ctx, GLenum error);

// Between glBegin and glEnd only the commands listed in spec 2.6.3 are allowed; every other
// command sets GL_INVALID_OPERATION and does nothing. Returns true (after recording the error)
// when ctx is inside glBegin/glEnd. One line at the top of such a command:
//   if (rejectInsideBeginEnd(ctx)) return;
bool rejectInsideBeginEnd(Context& ctx);

}  // namespace glass::gl
