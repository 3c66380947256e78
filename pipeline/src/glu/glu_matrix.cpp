// GLU's matrix functions (GLU 1.3 specification, chapter 4), computed as SGI's reference GLU
// computes them, so that the matrices agree with Mesa's libGLU to the last bit where the
// arithmetic is the same. They act through GL calls (glMultMatrixd, glTranslated, ...).
#include <GL/glu.h>

#include <cmath>
#include <numbers>
#include "glass/geometry/portable_math.h"

namespace {

// SGI GLU normalizes in float: r = sqrt(v . v), v /= r (a zero vector is left alone).
void normalize(float v[3]) {
  const float r = static_cast<float>(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  if (r == 0.0f) return;
  v[0] /= r;
  v[1] /= r;
  v[2] /= r;
}

void cross(const float a[3], const float b[3], float out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

extern "C" {

void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
  glOrtho(left, right, bottom, top, -1.0, 1.0);
}

void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) {
  const double radians = fovy / 2.0 * std::numbers::pi / 180.0;
  const double deltaZ = zFar - zNear;
  const double sine = glass::portable::sin(radians);
  // As GLU: a degenerate frustum leaves the matrix unchanged.
  if (deltaZ == 0.0 || sine == 0.0 || aspect == 0.0) return;
  const double cotangent = glass::portable::cos(radians) / sine;
  const GLdouble m[16] = {cotangent / aspect, 0.0, 0.0, 0.0,
                         0.0, cotangent, 0.0, 0.0,
                         0.0, 0.0, -(zFar + zNear) / deltaZ, -1.0,
                         0.0, 0.0, -2.0 * zNear * zFar / deltaZ, 0.0};
  glMultMatrixd(m);
}

void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY,
               GLdouble centerZ, GLdouble upX, GLdouble upY, GLdouble upZ) {
  float forward[3] = {static_cast<float>(centerX - eyeX), static_cast<float>(centerY - eyeY),
                      static_cast<float>(centerZ - eyeZ)};
  float up[3] = {static_cast<float>(upX), static_cast<float>(upY), static_cast<float>(upZ)};
  normalize(forward);
  float side[3];
  cross(forward, up, side);  // side = forward x up
  normalize(side);
  cross(side, forward, up);  // the true up = side x forward
  // Rows side, up, -forward: the rotation taking the view direction to -z.
  const GLfloat m[16] = {side[0], up[0], -forward[0], 0.0f,
                         side[1], up[1], -forward[1], 0.0f,
                         side[2], up[2], -forward[2], 0.0f,
                         0.0f,    0.0f,  0.0f,        1.0f};
  glMultMatrixf(m);
  glTranslated(-eyeX, -eyeY, -eyeZ);
}

void gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint* viewport) {
  if (!viewport || delX <= 0.0 || delY <= 0.0) return;
  // Translate the picking region to the centre of the viewport, then scale it to fill it.
  glTranslatef(static_cast<GLfloat>((viewport[2] - 2.0 * (x - viewport[0])) / delX),
               static_cast<GLfloat>((viewport[3] - 2.0 * (y - viewport[1])) / delY), 0.0f);
  glScalef(static_cast<GLfloat>(viewport[2] / delX), static_cast<GLfloat>(viewport[3] / delY),
           1.0f);
}

}  // extern "C"
