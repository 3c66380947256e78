// Colour index commands (spec 2.7, 2.8, 4.2.2, 4.2.3): glIndex in all its forms, glClearIndex,
// glIndexMask and glIndexPointer. glass renders in RGBA mode only, where these set state that
// nothing draws with (core/color_index.h), exactly as in Mesa's RGBA contexts.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::recordError;
using glass::gl::rejectInsideBeginEnd;

namespace {

// glIndex is allowed between glBegin and glEnd (spec 2.6.3) and compiled into lists. Integer
// indices convert as plain numbers, not normalized (spec 2.7).
void setIndex(float index) {
  compileOrExecute([=](Context& ctx) { ctx.current.index = index; });
}

template <class T>
void setIndexv(const T* c) {
  if (c) setIndex(static_cast<float>(c[0]));
}

}  // namespace

extern "C" {

void glIndexd(GLdouble c) { setIndex(static_cast<float>(c)); }
void glIndexf(GLfloat c) { setIndex(c); }
void glIndexi(GLint c) { setIndex(static_cast<float>(c)); }
void glIndexs(GLshort c) { setIndex(c); }
void glIndexub(GLubyte c) { setIndex(c); }
void glIndexdv(const GLdouble* c) { setIndexv(c); }
void glIndexfv(const GLfloat* c) { setIndexv(c); }
void glIndexiv(const GLint* c) { setIndexv(c); }
void glIndexsv(const GLshort* c) { setIndexv(c); }
void glIndexubv(const GLubyte* c) { setIndexv(c); }

void glClearIndex(GLfloat c) {
  compileOrExecute([=](Context& ctx) {
    if (!rejectInsideBeginEnd(ctx)) ctx.fragment.clearIndex = c;
  });
}

void glIndexMask(GLuint mask) {
  compileOrExecute([=](Context& ctx) {
    if (!rejectInsideBeginEnd(ctx)) ctx.fragment.indexMask = mask;
  });
}

// Client state, never compiled (spec 5.4). Table 2.4: the index array takes GL_UNSIGNED_BYTE,
// GL_SHORT, GL_INT, GL_FLOAT and GL_DOUBLE.
void glIndexPointer(GLenum type, GLsizei stride, const GLvoid* pointer) {
  glass::gl::executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    if (stride < 0) return recordError(ctx, GL_INVALID_VALUE);
    switch (type) {
      case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_INT: case GL_FLOAT: case GL_DOUBLE: break;
      default: return recordError(ctx, GL_INVALID_ENUM);
    }
    glass::gl::ClientArray& a = ctx.arrays.index;
    a.type = type;
    a.stride = stride;
    a.pointer = pointer;
  });
}

}  // extern "C"
