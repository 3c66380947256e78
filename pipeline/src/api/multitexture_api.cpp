// OpenGL 1.3 multitexture commands (spec 2.7, 2.8) and their GL_ARB_multitexture names
// (texture/texture_units.h): glActiveTexture, glClientActiveTexture and glMultiTexCoord in all
// its forms.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "texture/texture_units.h"
#include "vertex/immediate_mode.h"

using glass::gl::Context;
using glass::gl::isTextureUnit;
using glass::gl::recordError;

namespace {

// glTexCoord's conversion: plain numbers; t = 0, r = 0, q = 1 where not given (spec 2.7).
void multiTexCoord(GLenum unit, float s, float t, float r, float q) {
  if (!isTextureUnit(unit)) return;
  const float coords[4] = {s, t, r, q};
  const int index = static_cast<int>(unit - GL_TEXTURE0);
  glass::gl::compileOrExecute(
      [=](Context& ctx) { glass::gl::texCoordCommand(ctx, index, coords); });
}

template <class T>
void multiTexCoordv(GLenum unit, const T* v, int n) {
  if (!v) return;
  multiTexCoord(unit, static_cast<float>(v[0]), n > 1 ? static_cast<float>(v[1]) : 0.0f,
                n > 2 ? static_cast<float>(v[2]) : 0.0f, n > 3 ? static_cast<float>(v[3]) : 1.0f);
}

}  // namespace

extern "C" {

// Compiled into display lists (it is server state); client state is not (spec 5.4).
void glActiveTexture(GLenum texture) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!isTextureUnit(texture)) return recordError(ctx, GL_INVALID_ENUM);
    ctx.texture.activeUnit = static_cast<int>(texture - GL_TEXTURE0);
  });
}

void glClientActiveTexture(GLenum texture) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!isTextureUnit(texture)) return recordError(ctx, GL_INVALID_ENUM);
    ctx.arrays.clientActiveUnit = static_cast<int>(texture - GL_TEXTURE0);
  });
}

void glActiveTextureARB(GLenum texture) { glActiveTexture(texture); }
void glClientActiveTextureARB(GLenum texture) { glClientActiveTexture(texture); }

void glMultiTexCoord1d(GLenum u, GLdouble s) { multiTexCoord(u, float(s), 0.0f, 0.0f, 1.0f); }
void glMultiTexCoord1f(GLenum u, GLfloat s) { multiTexCoord(u, s, 0.0f, 0.0f, 1.0f); }
void glMultiTexCoord1i(GLenum u, GLint s) { multiTexCoord(u, float(s), 0.0f, 0.0f, 1.0f); }
void glMultiTexCoord1s(GLenum u, GLshort s) { multiTexCoord(u, s, 0.0f, 0.0f, 1.0f); }
void glMultiTexCoord2d(GLenum u, GLdouble s, GLdouble t) {
  multiTexCoord(u, float(s), float(t), 0.0f, 1.0f);
}
void glMultiTexCoord2f(GLenum u, GLfloat s, GLfloat t) { multiTexCoord(u, s, t, 0.0f, 1.0f); }
void glMultiTexCoord2i(GLenum u, GLint s, GLint t) {
  multiTexCoord(u, float(s), float(t), 0.0f, 1.0f);
}
void glMultiTexCoord2s(GLenum u, GLshort s, GLshort t) { multiTexCoord(u, s, t, 0.0f, 1.0f); }
void glMultiTexCoord3d(GLenum u, GLdouble s, GLdouble t, GLdouble r) {
  multiTexCoord(u, float(s), float(t), float(r), 1.0f);
}
void glMultiTexCoord3f(GLenum u, GLfloat s, GLfloat t, GLfloat r) {
  multiTexCoord(u, s, t, r, 1.0f);
}
void glMultiTexCoord3i(GLenum u, GLint s, GLint t, GLint r) {
  multiTexCoord(u, float(s), float(t), float(r), 1.0f);
}
void glMultiTexCoord3s(GLenum u, GLshort s, GLshort t, GLshort r) {
  multiTexCoord(u, s, t, r, 1.0f);
}
void glMultiTexCoord4d(GLenum u, GLdouble s, GLdouble t, GLdouble r, GLdouble q) {
  multiTexCoord(u, float(s), float(t), float(r), float(q));
}
void glMultiTexCoord4f(GLenum u, GLfloat s, GLfloat t, GLfloat r, GLfloat q) {
  multiTexCoord(u, s, t, r, q);
}
void glMultiTexCoord4i(GLenum u, GLint s, GLint t, GLint r, GLint q) {
  multiTexCoord(u, float(s), float(t), float(r), float(q));
}
void glMultiTexCoord4s(GLenum u, GLshort s, GLshort t, GLshort r, GLshort q) {
  multiTexCoord(u, s, t, r, q);
}
void glMultiTexCoord1dv(GLenum u, const GLdouble* v) { multiTexCoordv(u, v, 1); }
void glMultiTexCoord1fv(GLenum u, const GLfloat* v) { multiTexCoordv(u, v, 1); }
void glMultiTexCoord1iv(GLenum u, const GLint* v) { multiTexCoordv(u, v, 1); }
void glMultiTexCoord1sv(GLenum u, const GLshort* v) { multiTexCoordv(u, v, 1); }
void glMultiTexCoord2dv(GLenum u, const GLdouble* v) { multiTexCoordv(u, v, 2); }
void glMultiTexCoord2fv(GLenum u, const GLfloat* v) { multiTexCoordv(u, v, 2); }
void glMultiTexCoord2iv(GLenum u, const GLint* v) { multiTexCoordv(u, v, 2); }
void glMultiTexCoord2sv(GLenum u, const GLshort* v) { multiTexCoordv(u, v, 2); }
void glMultiTexCoord3dv(GLenum u, const GLdouble* v) { multiTexCoordv(u, v, 3); }
void glMultiTexCoord3fv(GLenum u, const GLfloat* v) { multiTexCoordv(u, v, 3); }
void glMultiTexCoord3iv(GLenum u, const GLint* v) { multiTexCoordv(u, v, 3); }
void glMultiTexCoord3sv(GLenum u, const GLshort* v) { multiTexCoordv(u, v, 3); }
void glMultiTexCoord4dv(GLenum u, const GLdouble* v) { multiTexCoordv(u, v, 4); }
void glMultiTexCoord4fv(GLenum u, const GLfloat* v) { multiTexCoordv(u, v, 4); }
void glMultiTexCoord4iv(GLenum u, const GLint* v) { multiTexCoordv(u, v, 4); }
void glMultiTexCoord4sv(GLenum u, const GLshort* v) { multiTexCoordv(u, v, 4); }

// The GL_ARB_multitexture names (the same commands, spec's Appendix F.1).
void glMultiTexCoord1dARB(GLenum u, GLdouble s) { glMultiTexCoord1d(u, s); }
void glMultiTexCoord1fARB(GLenum u, GLfloat s) { glMultiTexCoord1f(u, s); }
void glMultiTexCoord1iARB(GLenum u, GLint s) { glMultiTexCoord1i(u, s); }
void glMultiTexCoord1sARB(GLenum u, GLshort s) { glMultiTexCoord1s(u, s); }
void glMultiTexCoord2dARB(GLenum u, GLdouble s, GLdouble t) { glMultiTexCoord2d(u, s, t); }
void glMultiTexCoord2fARB(GLenum u, GLfloat s, GLfloat t) { glMultiTexCoord2f(u, s, t); }
void glMultiTexCoord2iARB(GLenum u, GLint s, GLint t) { glMultiTexCoord2i(u, s, t); }
void glMultiTexCoord2sARB(GLenum u, GLshort s, GLshort t) { glMultiTexCoord2s(u, s, t); }
void glMultiTexCoord3dARB(GLenum u, GLdouble s, GLdouble t, GLdouble r) {
  glMultiTexCoord3d(u, s, t, r);
}
void glMultiTexCoord3fARB(GLenum u, GLfloat s, GLfloat t, GLfloat r) {
  glMultiTexCoord3f(u, s, t, r);
}
void glMultiTexCoord3iARB(GLenum u, GLint s, GLint t, GLint r) { glMultiTexCoord3i(u, s, t, r); }
void glMultiTexCoord3sARB(GLenum u, GLshort s, GLshort t, GLshort r) {
  glMultiTexCoord3s(u, s, t, r);
}
void glMultiTexCoord4dARB(GLenum u, GLdouble s, GLdouble t, GLdouble r, GLdouble q) {
  glMultiTexCoord4d(u, s, t, r, q);
}
void glMultiTexCoord4fARB(GLenum u, GLfloat s, GLfloat t, GLfloat r, GLfloat q) {
  glMultiTexCoord4f(u, s, t, r, q);
}
void glMultiTexCoord4iARB(GLenum u, GLint s, GLint t, GLint r, GLint q) {
  glMultiTexCoord4i(u, s, t, r, q);
}
void glMultiTexCoord4sARB(GLenum u, GLshort s, GLshort t, GLshort r, GLshort q) {
  glMultiTexCoord4s(u, s, t, r, q);
}
void glMultiTexCoord1dvARB(GLenum u, const GLdouble* v) { glMultiTexCoord1dv(u, v); }
void glMultiTexCoord1fvARB(GLenum u, const GLfloat* v) { glMultiTexCoord1fv(u, v); }
void glMultiTexCoord1ivARB(GLenum u, const GLint* v) { glMultiTexCoord1iv(u, v); }
void glMultiTexCoord1svARB(GLenum u, const GLshort* v) { glMultiTexCoord1sv(u, v); }
void glMultiTexCoord2dvARB(GLenum u, const GLdouble* v) { glMultiTexCoord2dv(u, v); }
void glMultiTexCoord2fvARB(GLenum u, const GLfloat* v) { glMultiTexCoord2fv(u, v); }
void glMultiTexCoord2ivARB(GLenum u, const GLint* v) { glMultiTexCoord2iv(u, v); }
void glMultiTexCoord2svARB(GLenum u, const GLshort* v) { glMultiTexCoord2sv(u, v); }
void glMultiTexCoord3dvARB(GLenum u, const GLdouble* v) { glMultiTexCoord3dv(u, v); }
void glMultiTexCoord3fvARB(GLenum u, const GLfloat* v) { glMultiTexCoord3fv(u, v); }
void glMultiTexCoord3ivARB(GLenum u, const GLint* v) { glMultiTexCoord3iv(u, v); }
void glMultiTexCoord3svARB(GLenum u, const GLshort* v) { glMultiTexCoord3sv(u, v); }
void glMultiTexCoord4dvARB(GLenum u, const GLdouble* v) { glMultiTexCoord4dv(u, v); }
void glMultiTexCoord4fvARB(GLenum u, const GLfloat* v) { glMultiTexCoord4fv(u, v); }
void glMultiTexCoord4ivARB(GLenum u, const GLint* v) { glMultiTexCoord4iv(u, v); }
void glMultiTexCoord4svARB(GLenum u, const GLshort* v) { glMultiTexCoord4sv(u, v); }

}  // extern "C"
