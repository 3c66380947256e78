// The GLU NURBS entry points (GLU 1.3 specification, chapter 7): NURBS objects, their properties
// and callbacks, and the description of curves, surfaces and trimming loops. Errors go to the
// GLU_NURBS_ERROR callback with the GLU_NURBS_ERRORn codes SGI's GLU uses for the same mistakes.
// What was described is drawn at gluEndCurve / gluEndSurface (nurbs_rendering.cpp).
#include <GL/glu.h>

#include <new>

#include "glass/geometry/nurbs.h"
#include "glu/nurbs_object.h"
#include "core/float_to_int.h"

using State = GLUnurbs::State;
using glass::geometry::KnotVectorError;

namespace {

// Coordinates per control point of each map type (GL's glMap1/glMap2 targets and GLU's
// trimming types), 0 for a type that is none of them.
int dimensionOf(GLenum type) {
  switch (type) {
    case GL_MAP1_INDEX: case GL_MAP2_INDEX:
    case GL_MAP1_TEXTURE_COORD_1: case GL_MAP2_TEXTURE_COORD_1:
      return 1;
    case GL_MAP1_TEXTURE_COORD_2: case GL_MAP2_TEXTURE_COORD_2: case GLU_MAP1_TRIM_2:
      return 2;
    case GL_MAP1_VERTEX_3: case GL_MAP2_VERTEX_3: case GL_MAP1_NORMAL: case GL_MAP2_NORMAL:
    case GL_MAP1_TEXTURE_COORD_3: case GL_MAP2_TEXTURE_COORD_3: case GLU_MAP1_TRIM_3:
      return 3;
    case GL_MAP1_VERTEX_4: case GL_MAP2_VERTEX_4: case GL_MAP1_COLOR_4: case GL_MAP2_COLOR_4:
    case GL_MAP1_TEXTURE_COORD_4: case GL_MAP2_TEXTURE_COORD_4:
      return 4;
    default: return 0;
  }
}

bool isCurveType(GLenum type) { return type >= GL_MAP1_COLOR_4 && type <= GL_MAP1_VERTEX_4; }
bool isSurfaceType(GLenum type) { return type >= GL_MAP2_COLOR_4 && type <= GL_MAP2_VERTEX_4; }

// GLU_NURBS_ERROR1 .. 5 for the knot vector's faults, 0 when it is fine.
GLenum knotError(int order, const float* knots, int count) {
  if (!knots || count < 0) return GLU_NURBS_ERROR2;
  switch (glass::geometry::checkKnotVector(order, {knots, static_cast<size_t>(count)})) {
    case KnotVectorError::None: return 0;
    case KnotVectorError::UnsupportedOrder: return GLU_NURBS_ERROR1;
    case KnotVectorError::TooFewKnots: return GLU_NURBS_ERROR2;
    case KnotVectorError::EmptyRange: return GLU_NURBS_ERROR3;
    case KnotVectorError::Decreasing: return GLU_NURBS_ERROR4;
    case KnotVectorError::MultiplicityTooHigh: return GLU_NURBS_ERROR5;
  }
  return GLU_NURBS_ERROR2;
}

// Copies a curve's control points (count of them, `stride` floats apart).
GLUnurbs::Map curveMap(GLenum type, int order, const float* knots, int knotCount, int stride,
                       const float* control) {
  GLUnurbs::Map map;
  map.type = type;
  map.uOrder = order;
  map.uKnots.assign(knots, knots + knotCount);
  map.dimension = dimensionOf(type);
  const int count = knotCount - order;
  for (int k = 0; k < count; ++k) {
    for (int c = 0; c < map.dimension; ++c) map.points.push_back(control[k * stride + c]);
  }
  return map;
}

}  // namespace

extern "C" {

GLUnurbs* gluNewNurbsRenderer(void) { return new (std::nothrow) GLUnurbs; }

void gluDeleteNurbsRenderer(GLUnurbs* nurb) { delete nurb; }

void gluNurbsProperty(GLUnurbs* nurb, GLenum property, GLfloat value) {
  if (!nurb) return;
  switch (property) {
    case GLU_SAMPLING_TOLERANCE:
      if (!(value > 0.0f)) break;
      nurb->samplingTolerance = value;
      return;
    case GLU_PARAMETRIC_TOLERANCE:
      if (!(value > 0.0f)) break;
      nurb->parametricTolerance = value;
      return;
    case GLU_SAMPLING_METHOD: {
      const GLenum method = static_cast<GLenum>(glass::gl::enumFromFloat(value));
      if (method != GLU_PATH_LENGTH && method != GLU_PARAMETRIC_ERROR &&
          method != GLU_DOMAIN_DISTANCE && method != GLU_OBJECT_PATH_LENGTH &&
          method != GLU_OBJECT_PARAMETRIC_ERROR) {
        break;
      }
      nurb->samplingMethod = method;
      return;
    }
    case GLU_U_STEP:
      if (!(value > 0.0f)) break;
      nurb->uStep = value;
      return;
    case GLU_V_STEP:
      if (!(value > 0.0f)) break;
      nurb->vStep = value;
      return;
    case GLU_DISPLAY_MODE: {
      const GLenum mode = static_cast<GLenum>(glass::gl::enumFromFloat(value));
      if (mode != GLU_FILL && mode != GLU_OUTLINE_POLYGON && mode != GLU_OUTLINE_PATCH) break;
      nurb->displayMode = mode;
      return;
    }
    case GLU_CULLING: nurb->culling = value != 0.0f; return;
    case GLU_AUTO_LOAD_MATRIX: nurb->autoLoadMatrix = value != 0.0f; return;
    case GLU_NURBS_MODE: {
      const GLenum mode = static_cast<GLenum>(glass::gl::enumFromFloat(value));
      if (mode != GLU_NURBS_RENDERER && mode != GLU_NURBS_TESSELLATOR) break;
      nurb->mode = mode;
      return;
    }
    default: nurb->reportError(GLU_INVALID_ENUM); return;
  }
  nurb->reportError(GLU_INVALID_VALUE);
}

void gluGetNurbsProperty(GLUnurbs* nurb, GLenum property, GLfloat* value) {
  if (!nurb || !value) return;
  switch (property) {
    case GLU_SAMPLING_TOLERANCE: *value = nurb->samplingTolerance; return;
    case GLU_PARAMETRIC_TOLERANCE: *value = nurb->parametricTolerance; return;
    case GLU_SAMPLING_METHOD: *value = static_cast<GLfloat>(nurb->samplingMethod); return;
    case GLU_U_STEP: *value = nurb->uStep; return;
    case GLU_V_STEP: *value = nurb->vStep; return;
    case GLU_DISPLAY_MODE: *value = static_cast<GLfloat>(nurb->displayMode); return;
    case GLU_CULLING: *value = nurb->culling ? 1.0f : 0.0f; return;
    case GLU_AUTO_LOAD_MATRIX: *value = nurb->autoLoadMatrix ? 1.0f : 0.0f; return;
    case GLU_NURBS_MODE: *value = static_cast<GLfloat>(nurb->mode); return;
    default: nurb->reportError(GLU_INVALID_ENUM); return;
  }
}

void gluLoadSamplingMatrices(GLUnurbs* nurb, const GLfloat* model, const GLfloat* perspective,
                             const GLint* view) {
  if (!nurb || !model || !perspective || !view) return;
  for (int i = 0; i < 16; ++i) {
    nurb->modelview[i] = model[i];
    nurb->projection[i] = perspective[i];
  }
  for (int i = 0; i < 4; ++i) nurb->viewport[i] = view[i];
}

void gluNurbsCallback(GLUnurbs* nurb, GLenum which, _GLUfuncptr f) {
  if (!nurb) return;
  switch (which) {
    case GLU_NURBS_ERROR: nurb->error = reinterpret_cast<void (*)(GLenum)>(f); return;
    case GLU_NURBS_BEGIN: nurb->begin = reinterpret_cast<void (*)(GLenum)>(f); return;
    case GLU_NURBS_BEGIN_DATA:
      nurb->beginData = reinterpret_cast<void (*)(GLenum, void*)>(f);
      return;
    case GLU_NURBS_VERTEX: nurb->vertex = reinterpret_cast<void (*)(GLfloat*)>(f); return;
    case GLU_NURBS_VERTEX_DATA:
      nurb->vertexData = reinterpret_cast<void (*)(GLfloat*, void*)>(f);
      return;
    case GLU_NURBS_NORMAL: nurb->normal = reinterpret_cast<void (*)(GLfloat*)>(f); return;
    case GLU_NURBS_NORMAL_DATA:
      nurb->normalData = reinterpret_cast<void (*)(GLfloat*, void*)>(f);
      return;
    case GLU_NURBS_COLOR: nurb->color = reinterpret_cast<void (*)(GLfloat*)>(f); return;
    case GLU_NURBS_COLOR_DATA:
      nurb->colorData = reinterpret_cast<void (*)(GLfloat*, void*)>(f);
      return;
    case GLU_NURBS_TEXTURE_COORD: nurb->texCoord = reinterpret_cast<void (*)(GLfloat*)>(f); return;
    case GLU_NURBS_TEXTURE_COORD_DATA:
      nurb->texCoordData = reinterpret_cast<void (*)(GLfloat*, void*)>(f);
      return;
    case GLU_NURBS_END: nurb->end = reinterpret_cast<void (*)()>(f); return;
    case GLU_NURBS_END_DATA: nurb->endData = reinterpret_cast<void (*)(void*)>(f); return;
    default: nurb->reportError(GLU_INVALID_ENUM); return;
  }
}

void gluNurbsCallbackData(GLUnurbs* nurb, GLvoid* userData) {
  if (nurb) nurb->userData = userData;
}

void gluNurbsCallbackDataEXT(GLUnurbs* nurb, GLvoid* userData) {
  gluNurbsCallbackData(nurb, userData);
}

void gluBeginCurve(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state != State::Idle) {
    nurb->reportError(GLU_NURBS_ERROR6);  // gluEndCurve() must follow gluBeginCurve()
    return;
  }
  nurb->state = State::InCurve;
  nurb->maps.clear();
  nurb->surfaceHasErrors = false;
}

void gluEndCurve(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state != State::InCurve) {
    nurb->reportError(GLU_NURBS_ERROR7);  // gluBeginCurve() must precede gluEndCurve()
    return;
  }
  nurb->state = State::Idle;
  if (!nurb->surfaceHasErrors) glass::gl::glu::renderNurbsCurve(*nurb);
  nurb->maps.clear();
}

void gluBeginSurface(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state != State::Idle) {
    nurb->reportError(GLU_NURBS_ERROR27);  // gluEndSurface() must follow gluBeginSurface()
    return;
  }
  nurb->state = State::InSurface;
  nurb->maps.clear();
  nurb->trims.clear();
  nurb->surfaceHasErrors = false;
}

void gluEndSurface(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state == State::InTrim) {
    nurb->reportError(GLU_NURBS_ERROR12);  // gluEndTrim() must precede gluEndSurface()
    nurb->state = State::InSurface;
  }
  if (nurb->state != State::InSurface) {
    nurb->reportError(GLU_NURBS_ERROR13);  // gluBeginSurface() must precede gluEndSurface()
    return;
  }
  nurb->state = State::Idle;
  if (!nurb->surfaceHasErrors) glass::gl::glu::renderNurbsSurface(*nurb);
  nurb->maps.clear();
  nurb->trims.clear();
}

void gluBeginTrim(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state != State::InSurface) {
    nurb->reportError(GLU_NURBS_ERROR15);  // gluBeginSurface() must precede gluBeginTrim()
    return;
  }
  nurb->state = State::InTrim;
  nurb->trims.emplace_back();
}

void gluEndTrim(GLUnurbs* nurb) {
  if (!nurb) return;
  if (nurb->state != State::InTrim) {
    nurb->reportError(GLU_NURBS_ERROR17);  // gluBeginTrim() must precede gluEndTrim()
    return;
  }
  nurb->state = State::InSurface;
}

void gluPwlCurve(GLUnurbs* nurb, GLint count, GLfloat* data, GLint stride, GLenum type) {
  if (!nurb) return;
  if (nurb->state != State::InTrim) {
    nurb->reportError(GLU_NURBS_ERROR19);  // gluBeginTrim() must precede gluPwlCurve()
    return;
  }
  if (type != GLU_MAP1_TRIM_2 && type != GLU_MAP1_TRIM_3) {
    nurb->reportError(GLU_NURBS_ERROR14);  // improper type for a trimming curve
    return;
  }
  if (count < 0) {
    nurb->reportError(GLU_NURBS_ERROR33);  // negative vertex count
    return;
  }
  if (!data) {
    nurb->reportError(GLU_NURBS_ERROR36);  // null control point reference
    return;
  }
  GLUnurbs::TrimCurve curve;
  for (int k = 0; k < count; ++k) {
    const float* p = data + static_cast<long>(k) * stride;
    const double w = type == GLU_MAP1_TRIM_3 && p[2] != 0.0f ? p[2] : 1.0;
    curve.points.push_back(p[0] / w);
    curve.points.push_back(p[1] / w);
  }
  nurb->trims.back().push_back(std::move(curve));
}

void gluNurbsCurve(GLUnurbs* nurb, GLint knotCount, GLfloat* knots, GLint stride,
                   GLfloat* control, GLint order, GLenum type) {
  if (!nurb) return;
  const bool trimming = nurb->state == State::InTrim;
  if (!trimming && nurb->state != State::InCurve) {
    nurb->reportError(GLU_NURBS_ERROR7);  // gluBeginCurve() must precede the curve
    return;
  }
  const bool typeFits = trimming ? (type == GLU_MAP1_TRIM_2 || type == GLU_MAP1_TRIM_3)
                                 : isCurveType(type);
  if (!typeFits) {
    nurb->reportError(trimming ? GLU_NURBS_ERROR14 : GLU_NURBS_ERROR35);
    nurb->surfaceHasErrors = true;
    return;
  }
  if (const GLenum error = knotError(order, knots, knotCount)) {
    nurb->reportError(error);
    nurb->surfaceHasErrors = true;
    return;
  }
  if (!control) {
    nurb->reportError(GLU_NURBS_ERROR36);
    nurb->surfaceHasErrors = true;
    return;
  }
  GLUnurbs::Map map = curveMap(type, order, knots, knotCount, stride, control);
  if (trimming) {
    GLUnurbs::TrimCurve curve;
    curve.piecewiseLinear = false;
    curve.nurbs = std::move(map);
    nurb->trims.back().push_back(std::move(curve));
  } else {
    nurb->maps.push_back(std::move(map));
  }
}

void gluNurbsSurface(GLUnurbs* nurb, GLint sKnotCount, GLfloat* sKnots, GLint tKnotCount,
                     GLfloat* tKnots, GLint sStride, GLint tStride, GLfloat* control,
                     GLint sOrder, GLint tOrder, GLenum type) {
  if (!nurb) return;
  if (nurb->state != State::InSurface) {
    nurb->reportError(nurb->state == State::InTrim ? GLU_NURBS_ERROR22 : GLU_NURBS_ERROR13);
    return;
  }
  if (!isSurfaceType(type)) {
    nurb->reportError(GLU_NURBS_ERROR35);  // unknown type descriptor
    nurb->surfaceHasErrors = true;
    return;
  }
  GLenum error = knotError(sOrder, sKnots, sKnotCount);
  if (!error) error = knotError(tOrder, tKnots, tKnotCount);
  if (!error && !control) error = GLU_NURBS_ERROR36;
  if (error) {
    nurb->reportError(error);
    nurb->surfaceHasErrors = true;
    return;
  }
  GLUnurbs::Map map;
  map.type = type;
  map.uOrder = sOrder;
  map.vOrder = tOrder;
  map.uKnots.assign(sKnots, sKnots + sKnotCount);
  map.vKnots.assign(tKnots, tKnots + tKnotCount);
  map.dimension = dimensionOf(type);
  const int sCount = sKnotCount - sOrder, tCount = tKnotCount - tOrder;
  for (int i = 0; i < sCount; ++i) {
    for (int j = 0; j < tCount; ++j) {
      const float* p = control + static_cast<long>(i) * sStride + static_cast<long>(j) * tStride;
      for (int c = 0; c < map.dimension; ++c) map.points.push_back(p[c]);
    }
  }
  nurb->maps.push_back(std::move(map));
}

}  // extern "C"
