// The evaluator entry points (spec 5.1): glMap1, glMap2, glGetMap, glMapGrid, glEvalCoord,
// glEvalPoint and glEvalMesh in all their forms. glMap copies the control points when it is
// called, also into a display list (spec 5.4); glGetMap is never compiled.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "lists/command_recording.h"

using glass::gl::compileOrExecute;
using glass::gl::Context;
using glass::gl::executeNow;

namespace {

// The control points of a glMap1 call, read with its stride and packed; empty when the call is
// invalid (so that nothing is read from a pointer the call does not describe).
template <class T>
std::vector<double> packMap1Points(GLenum target, GLint stride, GLint order, const T* points) {
  const int k = glass::gl::mapValuesPerPoint(target);
  std::vector<double> packed;
  if (k == 0 || !points || stride < k || order < 1 || order > glass::gl::kMaxEvalOrder) return packed;
  for (GLint i = 0; i < order; ++i)
    for (int c = 0; c < k; ++c) packed.push_back(static_cast<double>(points[i * stride + c]));
  return packed;
}

template <class T>
std::vector<double> packMap2Points(GLenum target, GLint ustride, GLint uorder, GLint vstride, GLint vorder,
                                   const T* points) {
  const int k = glass::gl::mapValuesPerPoint(target);
  std::vector<double> packed;
  if (k == 0 || !points || ustride < k || vstride < k || uorder < 1 || vorder < 1 ||
      uorder > glass::gl::kMaxEvalOrder || vorder > glass::gl::kMaxEvalOrder)
    return packed;
  for (GLint i = 0; i < uorder; ++i)
    for (GLint j = 0; j < vorder; ++j)
      for (int c = 0; c < k; ++c) packed.push_back(static_cast<double>(points[i * ustride + j * vstride + c]));
  return packed;
}

template <class T>
void map1(GLenum target, T u1, T u2, GLint stride, GLint order, const T* points) {
  std::vector<double> packed = packMap1Points(target, stride, order, points);
  compileOrExecute([=, packed = std::move(packed)](Context& ctx) {
    glass::gl::map1Command(ctx, target, u1, u2, stride, order, packed);
  });
}

template <class T>
void map2(GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2, GLint vstride, GLint vorder,
          const T* points) {
  std::vector<double> packed = packMap2Points(target, ustride, uorder, vstride, vorder, points);
  compileOrExecute([=, packed = std::move(packed)](Context& ctx) {
    glass::gl::map2Command(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, packed);
  });
}

template <class T, class Convert>
void getMap(GLenum target, GLenum query, T* v, Convert convert) {
  executeNow([=](Context& ctx) {
    std::vector<double> values;
    if (!glass::gl::getMapCommand(ctx, target, query, values) || !v) return;
    for (std::size_t i = 0; i < values.size(); ++i) v[i] = convert(values[i]);
  });
}

void evalCoord1(double u) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalCoord1Command(ctx, u); });
}

void evalCoord2(double u, double v) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalCoord2Command(ctx, u, v); });
}

void mapGrid1(GLint un, double u1, double u2) {
  compileOrExecute([=](Context& ctx) { glass::gl::mapGrid1Command(ctx, un, u1, u2); });
}

void mapGrid2(GLint un, double u1, double u2, GLint vn, double v1, double v2) {
  compileOrExecute([=](Context& ctx) { glass::gl::mapGrid2Command(ctx, un, u1, u2, vn, v1, v2); });
}

}  // namespace

extern "C" {

void glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order, const GLfloat* points) {
  map1(target, u1, u2, stride, order, points);
}
void glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order, const GLdouble* points) {
  map1(target, u1, u2, stride, order, points);
}
void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2,
             GLint vstride, GLint vorder, const GLfloat* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder, GLdouble v1, GLdouble v2,
             GLint vstride, GLint vorder, const GLdouble* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

void glGetMapfv(GLenum target, GLenum query, GLfloat* v) {
  getMap(target, query, v, [](double x) { return static_cast<GLfloat>(x); });
}
void glGetMapdv(GLenum target, GLenum query, GLdouble* v) {
  getMap(target, query, v, [](double x) { return x; });
}
// Integer queries round to the nearest integer (spec 6.1.2).
void glGetMapiv(GLenum target, GLenum query, GLint* v) {
  getMap(target, query, v, [](double x) { return static_cast<GLint>(std::lround(x)); });
}

void glEvalCoord1f(GLfloat u) { evalCoord1(u); }
void glEvalCoord1d(GLdouble u) { evalCoord1(u); }
void glEvalCoord1fv(const GLfloat* u) {
  if (u) evalCoord1(u[0]);
}
void glEvalCoord1dv(const GLdouble* u) {
  if (u) evalCoord1(u[0]);
}
void glEvalCoord2f(GLfloat u, GLfloat v) { evalCoord2(u, v); }
void glEvalCoord2d(GLdouble u, GLdouble v) { evalCoord2(u, v); }
void glEvalCoord2fv(const GLfloat* u) {
  if (u) evalCoord2(u[0], u[1]);
}
void glEvalCoord2dv(const GLdouble* u) {
  if (u) evalCoord2(u[0], u[1]);
}

void glMapGrid1f(GLint un, GLfloat u1, GLfloat u2) { mapGrid1(un, u1, u2); }
void glMapGrid1d(GLint un, GLdouble u1, GLdouble u2) { mapGrid1(un, u1, u2); }
void glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  mapGrid2(un, u1, u2, vn, v1, v2);
}
void glMapGrid2d(GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
  mapGrid2(un, u1, u2, vn, v1, v2);
}

void glEvalPoint1(GLint i) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalPoint1Command(ctx, i); });
}
void glEvalPoint2(GLint i, GLint j) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalPoint2Command(ctx, i, j); });
}
void glEvalMesh1(GLenum mode, GLint i1, GLint i2) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalMesh1Command(ctx, mode, i1, i2); });
}
void glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  compileOrExecute([=](Context& ctx) { glass::gl::evalMesh2Command(ctx, mode, i1, i2, j1, j2); });
}

}  // extern "C"
