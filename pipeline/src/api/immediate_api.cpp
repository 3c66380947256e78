// Immediate mode entry points (spec 2.6-2.7, 2.10): glBegin, glEnd, glVertex, glColor, glNormal,
// glTexCoord, glEdgeFlag and glRect in all their forms. Each converts its arguments to float
// (colours and normals by table 2.9, coordinates as plain numbers) and records or runs the
// command of vertex/immediate_mode.h.
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"
#include "vertex/attribute_conversion.h"
#include "vertex/immediate_mode.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::normalizedToFloat;

namespace {

void vertex(float x, float y, float z, float w) {
  compileOrExecute([=](Context& ctx) { glass::gl::vertexCommand(ctx, x, y, z, w); });
}

template <class T>
void vertexv(const T* v, int n) {
  if (!v) return;
  vertex(static_cast<float>(v[0]), static_cast<float>(v[1]),
         n > 2 ? static_cast<float>(v[2]) : 0.0f, n > 3 ? static_cast<float>(v[3]) : 1.0f);
}

void color(float r, float g, float b, float a) {
  compileOrExecute([=](Context& ctx) { glass::gl::colorCommand(ctx, r, g, b, a); });
}

// glColor3 sets alpha to 1 (spec 2.7).
template <class T>
void color3(T r, T g, T b) {
  color(normalizedToFloat(r), normalizedToFloat(g), normalizedToFloat(b), 1.0f);
}
template <class T>
void color4(T r, T g, T b, T a) {
  color(normalizedToFloat(r), normalizedToFloat(g), normalizedToFloat(b), normalizedToFloat(a));
}
template <class T>
void color3v(const T* v) {
  if (v) color3(v[0], v[1], v[2]);
}
template <class T>
void color4v(const T* v) {
  if (v) color4(v[0], v[1], v[2], v[3]);
}

template <class T>
void normal(T x, T y, T z) {
  const float nx = normalizedToFloat(x), ny = normalizedToFloat(y), nz = normalizedToFloat(z);
  compileOrExecute([=](Context& ctx) { glass::gl::normalCommand(ctx, nx, ny, nz); });
}
template <class T>
void normalv(const T* v) {
  if (v) normal(v[0], v[1], v[2]);
}

// glTexCoord1/2/3 leave t = 0, r = 0, q = 1 (spec 2.7).
void texCoord(float s, float t, float r, float q) {
  // glTexCoord is glMultiTexCoord for GL_TEXTURE0 (spec 2.7).
  const float coords[4] = {s, t, r, q};
  compileOrExecute([=](Context& ctx) { glass::gl::texCoordCommand(ctx, 0, coords); });
}
template <class T>
void texCoordv(const T* v, int n) {
  if (!v) return;
  texCoord(static_cast<float>(v[0]), n > 1 ? static_cast<float>(v[1]) : 0.0f,
           n > 2 ? static_cast<float>(v[2]) : 0.0f, n > 3 ? static_cast<float>(v[3]) : 1.0f);
}

template <class T>
void rect(T x1, T y1, T x2, T y2) {
  const float a = static_cast<float>(x1), b = static_cast<float>(y1);
  const float c = static_cast<float>(x2), d = static_cast<float>(y2);
  compileOrExecute([=](Context& ctx) { glass::gl::rectCommand(ctx, a, b, c, d); });
}
template <class T>
void rectv(const T* v1, const T* v2) {
  if (v1 && v2) rect(v1[0], v1[1], v2[0], v2[1]);
}

}  // namespace

extern "C" {

void glBegin(GLenum mode) {
  compileOrExecute([=](Context& ctx) { glass::gl::beginCommand(ctx, mode); });
}
void glEnd(void) {
  compileOrExecute([](Context& ctx) { glass::gl::endCommand(ctx); });
}

void glVertex2f(GLfloat x, GLfloat y) { vertex(x, y, 0.0f, 1.0f); }
void glVertex2d(GLdouble x, GLdouble y) { vertex(float(x), float(y), 0.0f, 1.0f); }
void glVertex2i(GLint x, GLint y) { vertex(float(x), float(y), 0.0f, 1.0f); }
void glVertex2s(GLshort x, GLshort y) { vertex(x, y, 0.0f, 1.0f); }
void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { vertex(x, y, z, 1.0f); }
void glVertex3d(GLdouble x, GLdouble y, GLdouble z) { vertex(float(x), float(y), float(z), 1.0f); }
void glVertex3i(GLint x, GLint y, GLint z) { vertex(float(x), float(y), float(z), 1.0f); }
void glVertex3s(GLshort x, GLshort y, GLshort z) { vertex(x, y, z, 1.0f); }
void glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex(x, y, z, w); }
void glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  vertex(float(x), float(y), float(z), float(w));
}
void glVertex4i(GLint x, GLint y, GLint z, GLint w) { vertex(float(x), float(y), float(z), float(w)); }
void glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w) { vertex(x, y, z, w); }
void glVertex2fv(const GLfloat* v) { vertexv(v, 2); }
void glVertex2dv(const GLdouble* v) { vertexv(v, 2); }
void glVertex2iv(const GLint* v) { vertexv(v, 2); }
void glVertex2sv(const GLshort* v) { vertexv(v, 2); }
void glVertex3fv(const GLfloat* v) { vertexv(v, 3); }
void glVertex3dv(const GLdouble* v) { vertexv(v, 3); }
void glVertex3iv(const GLint* v) { vertexv(v, 3); }
void glVertex3sv(const GLshort* v) { vertexv(v, 3); }
void glVertex4fv(const GLfloat* v) { vertexv(v, 4); }
void glVertex4dv(const GLdouble* v) { vertexv(v, 4); }
void glVertex4iv(const GLint* v) { vertexv(v, 4); }
void glVertex4sv(const GLshort* v) { vertexv(v, 4); }

void glColor3f(GLfloat r, GLfloat g, GLfloat b) { color3(r, g, b); }
void glColor3d(GLdouble r, GLdouble g, GLdouble b) { color3(r, g, b); }
void glColor3ub(GLubyte r, GLubyte g, GLubyte b) { color3(r, g, b); }
void glColor3b(GLbyte r, GLbyte g, GLbyte b) { color3(r, g, b); }
void glColor3s(GLshort r, GLshort g, GLshort b) { color3(r, g, b); }
void glColor3i(GLint r, GLint g, GLint b) { color3(r, g, b); }
void glColor3us(GLushort r, GLushort g, GLushort b) { color3(r, g, b); }
void glColor3ui(GLuint r, GLuint g, GLuint b) { color3(r, g, b); }
void glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color4(r, g, b, a); }
void glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) { color4(r, g, b, a); }
void glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { color4(r, g, b, a); }
void glColor4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { color4(r, g, b, a); }
void glColor4s(GLshort r, GLshort g, GLshort b, GLshort a) { color4(r, g, b, a); }
void glColor4i(GLint r, GLint g, GLint b, GLint a) { color4(r, g, b, a); }
void glColor4us(GLushort r, GLushort g, GLushort b, GLushort a) { color4(r, g, b, a); }
void glColor4ui(GLuint r, GLuint g, GLuint b, GLuint a) { color4(r, g, b, a); }
void glColor3fv(const GLfloat* v) { color3v(v); }
void glColor3dv(const GLdouble* v) { color3v(v); }
void glColor3ubv(const GLubyte* v) { color3v(v); }
void glColor3bv(const GLbyte* v) { color3v(v); }
void glColor3sv(const GLshort* v) { color3v(v); }
void glColor3iv(const GLint* v) { color3v(v); }
void glColor3usv(const GLushort* v) { color3v(v); }
void glColor3uiv(const GLuint* v) { color3v(v); }
void glColor4fv(const GLfloat* v) { color4v(v); }
void glColor4dv(const GLdouble* v) { color4v(v); }
void glColor4ubv(const GLubyte* v) { color4v(v); }
void glColor4bv(const GLbyte* v) { color4v(v); }
void glColor4sv(const GLshort* v) { color4v(v); }
void glColor4iv(const GLint* v) { color4v(v); }
void glColor4usv(const GLushort* v) { color4v(v); }
void glColor4uiv(const GLuint* v) { color4v(v); }

void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { normal(x, y, z); }
void glNormal3d(GLdouble x, GLdouble y, GLdouble z) { normal(x, y, z); }
void glNormal3b(GLbyte x, GLbyte y, GLbyte z) { normal(x, y, z); }
void glNormal3s(GLshort x, GLshort y, GLshort z) { normal(x, y, z); }
void glNormal3i(GLint x, GLint y, GLint z) { normal(x, y, z); }
void glNormal3fv(const GLfloat* v) { normalv(v); }
void glNormal3dv(const GLdouble* v) { normalv(v); }
void glNormal3bv(const GLbyte* v) { normalv(v); }
void glNormal3sv(const GLshort* v) { normalv(v); }
void glNormal3iv(const GLint* v) { normalv(v); }

void glTexCoord1f(GLfloat s) { texCoord(s, 0.0f, 0.0f, 1.0f); }
void glTexCoord1d(GLdouble s) { texCoord(float(s), 0.0f, 0.0f, 1.0f); }
void glTexCoord1i(GLint s) { texCoord(float(s), 0.0f, 0.0f, 1.0f); }
void glTexCoord1s(GLshort s) { texCoord(s, 0.0f, 0.0f, 1.0f); }
void glTexCoord2f(GLfloat s, GLfloat t) { texCoord(s, t, 0.0f, 1.0f); }
void glTexCoord2d(GLdouble s, GLdouble t) { texCoord(float(s), float(t), 0.0f, 1.0f); }
void glTexCoord2i(GLint s, GLint t) { texCoord(float(s), float(t), 0.0f, 1.0f); }
void glTexCoord2s(GLshort s, GLshort t) { texCoord(s, t, 0.0f, 1.0f); }
void glTexCoord3f(GLfloat s, GLfloat t, GLfloat r) { texCoord(s, t, r, 1.0f); }
void glTexCoord3d(GLdouble s, GLdouble t, GLdouble r) { texCoord(float(s), float(t), float(r), 1.0f); }
void glTexCoord3i(GLint s, GLint t, GLint r) { texCoord(float(s), float(t), float(r), 1.0f); }
void glTexCoord3s(GLshort s, GLshort t, GLshort r) { texCoord(s, t, r, 1.0f); }
void glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q) { texCoord(s, t, r, q); }
void glTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q) {
  texCoord(float(s), float(t), float(r), float(q));
}
void glTexCoord4i(GLint s, GLint t, GLint r, GLint q) {
  texCoord(float(s), float(t), float(r), float(q));
}
void glTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q) { texCoord(s, t, r, q); }
void glTexCoord1fv(const GLfloat* v) { texCoordv(v, 1); }
void glTexCoord2fv(const GLfloat* v) { texCoordv(v, 2); }
void glTexCoord3fv(const GLfloat* v) { texCoordv(v, 3); }
void glTexCoord4fv(const GLfloat* v) { texCoordv(v, 4); }
void glTexCoord1dv(const GLdouble* v) { texCoordv(v, 1); }
void glTexCoord2dv(const GLdouble* v) { texCoordv(v, 2); }
void glTexCoord3dv(const GLdouble* v) { texCoordv(v, 3); }
void glTexCoord4dv(const GLdouble* v) { texCoordv(v, 4); }
void glTexCoord1iv(const GLint* v) { texCoordv(v, 1); }
void glTexCoord2iv(const GLint* v) { texCoordv(v, 2); }
void glTexCoord3iv(const GLint* v) { texCoordv(v, 3); }
void glTexCoord4iv(const GLint* v) { texCoordv(v, 4); }
void glTexCoord1sv(const GLshort* v) { texCoordv(v, 1); }
void glTexCoord2sv(const GLshort* v) { texCoordv(v, 2); }
void glTexCoord3sv(const GLshort* v) { texCoordv(v, 3); }
void glTexCoord4sv(const GLshort* v) { texCoordv(v, 4); }

void glEdgeFlag(GLboolean flag) {
  const bool f = flag != GL_FALSE;
  compileOrExecute([=](Context& ctx) { glass::gl::edgeFlagCommand(ctx, f); });
}
void glEdgeFlagv(const GLboolean* flag) {
  if (flag) glEdgeFlag(*flag);
}

void glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { rect(x1, y1, x2, y2); }
void glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { rect(x1, y1, x2, y2); }
void glRecti(GLint x1, GLint y1, GLint x2, GLint y2) { rect(x1, y1, x2, y2); }
void glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { rect(x1, y1, x2, y2); }
void glRectfv(const GLfloat* v1, const GLfloat* v2) { rectv(v1, v2); }
void glRectdv(const GLdouble* v1, const GLdouble* v2) { rectv(v1, v2); }
void glRectiv(const GLint* v1, const GLint* v2) { rectv(v1, v2); }
void glRectsv(const GLshort* v1, const GLshort* v2) { rectv(v1, v2); }

}  // extern "C"
