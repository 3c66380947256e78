// glRasterPos and glWindowPos in all their forms (OpenGL 1.5 specification, section 2.13). Both
// are compiled into display lists; neither is allowed between glBegin and glEnd.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "pixels/raster_position.h"

using glass::gl::Context;

namespace {

void rasterPos(float x, float y, float z, float w) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const float object[4] = {x, y, z, w};
    glass::gl::setRasterPosition(ctx, object);
  });
}

// glRasterPos2/3 leave z = 0 and w = 1 (spec 2.13, as glVertex does).
template <class T>
void rasterPosv(const T* v, int n) {
  if (!v) return;
  rasterPos(static_cast<float>(v[0]), static_cast<float>(v[1]),
            n > 2 ? static_cast<float>(v[2]) : 0.0f, n > 3 ? static_cast<float>(v[3]) : 1.0f);
}

void windowPos(float x, float y, float z) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    glass::gl::setWindowPosition(ctx, x, y, z);
  });
}

// glWindowPos2 leaves z = 0 (GL 1.4, section 2.13).
template <class T>
void windowPosv(const T* v, int n) {
  if (!v) return;
  windowPos(static_cast<float>(v[0]), static_cast<float>(v[1]), n > 2 ? static_cast<float>(v[2]) : 0.0f);
}

}  // namespace

extern "C" {

void glRasterPos2s(GLshort x, GLshort y) { rasterPos(x, y, 0.0f, 1.0f); }
void glRasterPos2i(GLint x, GLint y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
void glRasterPos2f(GLfloat x, GLfloat y) { rasterPos(x, y, 0.0f, 1.0f); }
void glRasterPos2d(GLdouble x, GLdouble y) { rasterPos(float(x), float(y), 0.0f, 1.0f); }
void glRasterPos3s(GLshort x, GLshort y, GLshort z) { rasterPos(x, y, z, 1.0f); }
void glRasterPos3i(GLint x, GLint y, GLint z) { rasterPos(float(x), float(y), float(z), 1.0f); }
void glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) { rasterPos(x, y, z, 1.0f); }
void glRasterPos3d(GLdouble x, GLdouble y, GLdouble z) { rasterPos(float(x), float(y), float(z), 1.0f); }
void glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { rasterPos(x, y, z, w); }
void glRasterPos4i(GLint x, GLint y, GLint z, GLint w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
void glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { rasterPos(x, y, z, w); }
void glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  rasterPos(float(x), float(y), float(z), float(w));
}
void glRasterPos2sv(const GLshort* v) { rasterPosv(v, 2); }
void glRasterPos2iv(const GLint* v) { rasterPosv(v, 2); }
void glRasterPos2fv(const GLfloat* v) { rasterPosv(v, 2); }
void glRasterPos2dv(const GLdouble* v) { rasterPosv(v, 2); }
void glRasterPos3sv(const GLshort* v) { rasterPosv(v, 3); }
void glRasterPos3iv(const GLint* v) { rasterPosv(v, 3); }
void glRasterPos3fv(const GLfloat* v) { rasterPosv(v, 3); }
void glRasterPos3dv(const GLdouble* v) { rasterPosv(v, 3); }
void glRasterPos4sv(const GLshort* v) { rasterPosv(v, 4); }
void glRasterPos4iv(const GLint* v) { rasterPosv(v, 4); }
void glRasterPos4fv(const GLfloat* v) { rasterPosv(v, 4); }
void glRasterPos4dv(const GLdouble* v) { rasterPosv(v, 4); }

void glWindowPos2s(GLshort x, GLshort y) { windowPos(x, y, 0.0f); }
void glWindowPos2i(GLint x, GLint y) { windowPos(float(x), float(y), 0.0f); }
void glWindowPos2f(GLfloat x, GLfloat y) { windowPos(x, y, 0.0f); }
void glWindowPos2d(GLdouble x, GLdouble y) { windowPos(float(x), float(y), 0.0f); }
void glWindowPos3s(GLshort x, GLshort y, GLshort z) { windowPos(x, y, z); }
void glWindowPos3i(GLint x, GLint y, GLint z) { windowPos(float(x), float(y), float(z)); }
void glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { windowPos(x, y, z); }
void glWindowPos3d(GLdouble x, GLdouble y, GLdouble z) { windowPos(float(x), float(y), float(z)); }
void glWindowPos2sv(const GLshort* v) { windowPosv(v, 2); }
void glWindowPos2iv(const GLint* v) { windowPosv(v, 2); }
void glWindowPos2fv(const GLfloat* v) { windowPosv(v, 2); }
void glWindowPos2dv(const GLdouble* v) { windowPosv(v, 2); }
void glWindowPos3sv(const GLshort* v) { windowPosv(v, 3); }
void glWindowPos3iv(const GLint* v) { windowPosv(v, 3); }
void glWindowPos3fv(const GLfloat* v) { windowPosv(v, 3); }
void glWindowPos3dv(const GLdouble* v) { windowPosv(v, 3); }

}  // extern "C"
