// OpenGL 1.4's fog coordinate and secondary colour commands (spec 2.7, 2.8): glFogCoord and
// glSecondaryColor in all their forms, and their array pointers (vertex/secondary_attributes.h).
// Like glColor, both are allowed between glBegin and glEnd and compiled into display lists;
// secondary colour components convert by table 2.9, fog coordinates as plain numbers.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "vertex/attribute_conversion.h"
#include "vertex/immediate_mode.h"

using glass::gl::Context;
using glass::gl::normalizedToFloat;
using glass::gl::recordError;

namespace {

void fogCoord(float c) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::fogCoordCommand(ctx, c); });
}

template <class T>
void secondaryColor(T r, T g, T b) {
  const float fr = normalizedToFloat(r), fg = normalizedToFloat(g), fb = normalizedToFloat(b);
  glass::gl::compileOrExecute(
      [=](Context& ctx) { glass::gl::secondaryColorCommand(ctx, fr, fg, fb); });
}

template <class T>
void secondaryColorv(const T* v) {
  if (v) secondaryColor(v[0], v[1], v[2]);
}

// Client state, never compiled (spec 5.4). Fog coordinates are GL_FLOAT or GL_DOUBLE; secondary
// colours have size 3 and any of glColorPointer's types.
void setPointer(bool fog, int size, GLenum type, GLsizei stride, const GLvoid* pointer) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    bool typeValid = false;
    if (fog) {
      typeValid = type == GL_FLOAT || type == GL_DOUBLE;
    } else {
      switch (type) {
        case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_INT:
        case GL_UNSIGNED_INT: case GL_FLOAT: case GL_DOUBLE:
          typeValid = true;
          break;
        default: break;
      }
    }
    if (!fog && size != 3) return recordError(ctx, GL_INVALID_VALUE);
    if (stride < 0) return recordError(ctx, GL_INVALID_VALUE);
    if (!typeValid) return recordError(ctx, GL_INVALID_ENUM);
    glass::gl::ClientArray& a = fog ? ctx.arrays.fogCoord : ctx.arrays.secondaryColor;
    a.size = size;
    a.type = type;
    a.stride = stride;
    a.pointer = pointer;
  });
}

}  // namespace

extern "C" {

void glFogCoordf(GLfloat c) { fogCoord(c); }
void glFogCoordd(GLdouble c) { fogCoord(static_cast<float>(c)); }
void glFogCoordfv(const GLfloat* c) {
  if (c) fogCoord(c[0]);
}
void glFogCoorddv(const GLdouble* c) {
  if (c) fogCoord(static_cast<float>(c[0]));
}

void glSecondaryColor3b(GLbyte r, GLbyte g, GLbyte b) { secondaryColor(r, g, b); }
void glSecondaryColor3d(GLdouble r, GLdouble g, GLdouble b) { secondaryColor(r, g, b); }
void glSecondaryColor3f(GLfloat r, GLfloat g, GLfloat b) { secondaryColor(r, g, b); }
void glSecondaryColor3i(GLint r, GLint g, GLint b) { secondaryColor(r, g, b); }
void glSecondaryColor3s(GLshort r, GLshort g, GLshort b) { secondaryColor(r, g, b); }
void glSecondaryColor3ub(GLubyte r, GLubyte g, GLubyte b) { secondaryColor(r, g, b); }
void glSecondaryColor3ui(GLuint r, GLuint g, GLuint b) { secondaryColor(r, g, b); }
void glSecondaryColor3us(GLushort r, GLushort g, GLushort b) { secondaryColor(r, g, b); }
void glSecondaryColor3bv(const GLbyte* v) { secondaryColorv(v); }
void glSecondaryColor3dv(const GLdouble* v) { secondaryColorv(v); }
void glSecondaryColor3fv(const GLfloat* v) { secondaryColorv(v); }
void glSecondaryColor3iv(const GLint* v) { secondaryColorv(v); }
void glSecondaryColor3sv(const GLshort* v) { secondaryColorv(v); }
void glSecondaryColor3ubv(const GLubyte* v) { secondaryColorv(v); }
void glSecondaryColor3uiv(const GLuint* v) { secondaryColorv(v); }
void glSecondaryColor3usv(const GLushort* v) { secondaryColorv(v); }

void glFogCoordPointer(GLenum type, GLsizei stride, const GLvoid* pointer) {
  setPointer(true, 1, type, stride, pointer);
}

void glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* pointer) {
  setPointer(false, size, type, stride, pointer);
}

}  // extern "C"
