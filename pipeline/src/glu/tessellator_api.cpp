// The GLU tessellator's entry points (GLU 1.3 specification, chapter 5): creating and deleting
// tessellators, callbacks and properties, and describing a polygon contour by contour. A polygon
// is tessellated at gluTessEndPolygon (tessellator_rendering.cpp).
#include <GL/glu.h>

#include <new>
#include <utility>

#include "glu/tessellator_object.h"
#include "core/float_to_int.h"

using State = GLUtesselator::State;

namespace {

void beginPolygon(GLUtesselator& tess, void* data);
void beginContour(GLUtesselator& tess);
void endContour(GLUtesselator& tess);

// Back to the dormant state, dropping the polygon.
void makeDormant(GLUtesselator& tess) {
  tess.contours.clear();
  tess.state = State::Dormant;
}

// Moves one state at a time towards `wanted`, reporting each call that is missing and making it
// (except gluTessEndPolygon, whose polygon is dropped instead, as in SGI's GLU).
void requireState(GLUtesselator& tess, State wanted) {
  while (tess.state != wanted) {
    if (tess.state < wanted) {
      if (tess.state == State::Dormant) {
        tess.reportError(GLU_TESS_MISSING_BEGIN_POLYGON);
        beginPolygon(tess, nullptr);
      } else {
        tess.reportError(GLU_TESS_MISSING_BEGIN_CONTOUR);
        beginContour(tess);
      }
    } else if (tess.state == State::InContour) {
      tess.reportError(GLU_TESS_MISSING_END_CONTOUR);
      endContour(tess);
    } else {
      tess.reportError(GLU_TESS_MISSING_END_POLYGON);
      makeDormant(tess);
    }
  }
}

void beginPolygon(GLUtesselator& tess, void* data) {
  requireState(tess, State::Dormant);
  tess.state = State::InPolygon;
  tess.contours.clear();
  tess.polygonData = data;
}

void beginContour(GLUtesselator& tess) {
  requireState(tess, State::InPolygon);
  tess.state = State::InContour;
  tess.contours.emplace_back();
}

void endContour(GLUtesselator& tess) {
  requireState(tess, State::InContour);
  tess.state = State::InPolygon;
}

template <class Function>
Function callbackAs(_GLUfuncptr f) {
  return reinterpret_cast<Function>(f);
}

}  // namespace

extern "C" {

GLUtesselator* gluNewTess(void) { return new (std::nothrow) GLUtesselator; }

void gluDeleteTess(GLUtesselator* tess) {
  if (!tess) return;
  requireState(*tess, State::Dormant);
  delete tess;
}

void gluTessCallback(GLUtesselator* tess, GLenum which, _GLUfuncptr f) {
  if (!tess) return;
  switch (which) {
    case GLU_TESS_BEGIN: tess->begin = callbackAs<void (*)(GLenum)>(f); return;
    case GLU_TESS_BEGIN_DATA: tess->beginData = callbackAs<void (*)(GLenum, void*)>(f); return;
    case GLU_TESS_VERTEX: tess->vertex = callbackAs<void (*)(void*)>(f); return;
    case GLU_TESS_VERTEX_DATA: tess->vertexData = callbackAs<void (*)(void*, void*)>(f); return;
    case GLU_TESS_END: tess->end = callbackAs<void (*)()>(f); return;
    case GLU_TESS_END_DATA: tess->endData = callbackAs<void (*)(void*)>(f); return;
    case GLU_TESS_ERROR: tess->error = callbackAs<void (*)(GLenum)>(f); return;
    case GLU_TESS_ERROR_DATA: tess->errorData = callbackAs<void (*)(GLenum, void*)>(f); return;
    case GLU_TESS_EDGE_FLAG: tess->edgeFlag = callbackAs<void (*)(GLboolean)>(f); return;
    case GLU_TESS_EDGE_FLAG_DATA:
      tess->edgeFlagData = callbackAs<void (*)(GLboolean, void*)>(f);
      return;
    case GLU_TESS_COMBINE:
      tess->combine = callbackAs<void (*)(GLdouble[3], void*[4], GLfloat[4], void**)>(f);
      return;
    case GLU_TESS_COMBINE_DATA:
      tess->combineData =
          callbackAs<void (*)(GLdouble[3], void*[4], GLfloat[4], void**, void*)>(f);
      return;
    default: tess->reportError(GLU_INVALID_ENUM); return;
  }
}

void gluTessProperty(GLUtesselator* tess, GLenum which, GLdouble value) {
  if (!tess) return;
  switch (which) {
    case GLU_TESS_WINDING_RULE: {
      const GLenum rule = static_cast<GLenum>(glass::gl::enumFromFloat(value));
      const bool known = rule >= GLU_TESS_WINDING_ODD && rule <= GLU_TESS_WINDING_ABS_GEQ_TWO;
      if (static_cast<GLdouble>(rule) != value || !known) break;
      tess->windingRule = rule;
      return;
    }
    case GLU_TESS_BOUNDARY_ONLY: tess->boundaryOnly = value != 0.0; return;
    case GLU_TESS_TOLERANCE:
      if (!(value >= 0.0 && value <= 1.0)) break;
      tess->tolerance = value;
      return;
    default: tess->reportError(GLU_INVALID_ENUM); return;
  }
  tess->reportError(GLU_INVALID_VALUE);
}

void gluGetTessProperty(GLUtesselator* tess, GLenum which, GLdouble* value) {
  if (!tess || !value) return;
  switch (which) {
    case GLU_TESS_WINDING_RULE: *value = tess->windingRule; return;
    case GLU_TESS_BOUNDARY_ONLY: *value = tess->boundaryOnly ? 1.0 : 0.0; return;
    case GLU_TESS_TOLERANCE: *value = tess->tolerance; return;
    default:
      *value = 0.0;
      tess->reportError(GLU_INVALID_ENUM);
      return;
  }
}

void gluTessNormal(GLUtesselator* tess, GLdouble x, GLdouble y, GLdouble z) {
  if (!tess) return;
  tess->normal[0] = x;
  tess->normal[1] = y;
  tess->normal[2] = z;
}

void gluTessBeginPolygon(GLUtesselator* tess, GLvoid* data) {
  if (tess) beginPolygon(*tess, data);
}

void gluTessBeginContour(GLUtesselator* tess) {
  if (tess) beginContour(*tess);
}

// Coordinates beyond +-GLU_TESS_MAX_COORD are clamped to it and reported; NaN counts as 0.
void gluTessVertex(GLUtesselator* tess, GLdouble* location, GLvoid* data) {
  if (!tess || !location) return;
  requireState(*tess, State::InContour);
  GLUtesselator::Vertex v{{location[0], location[1], location[2]}, data};
  bool tooLarge = false;
  for (double& c : v.coords) {
    if (c != c) c = 0.0;
    if (c < -GLU_TESS_MAX_COORD) {
      c = -GLU_TESS_MAX_COORD;
      tooLarge = true;
    } else if (c > GLU_TESS_MAX_COORD) {
      c = GLU_TESS_MAX_COORD;
      tooLarge = true;
    }
  }
  if (tooLarge) tess->reportError(GLU_TESS_COORD_TOO_LARGE);
  tess->contours.back().push_back(v);
}

void gluTessEndContour(GLUtesselator* tess) {
  if (tess) endContour(*tess);
}

void gluTessEndPolygon(GLUtesselator* tess) {
  if (!tess) return;
  requireState(*tess, State::InPolygon);
  // Dormant before the callbacks run, so that they may describe the next polygon.
  const auto contours = std::move(tess->contours);
  makeDormant(*tess);
  glass::gl::glu::renderTessellation(*tess, contours);
  tess->polygonData = nullptr;
}

// GLU 1.0's interface (GLU 1.3 specification, section 5.7): one polygon per begin/end, each
// gluNextContour starting a new contour; the contour type is not needed.
void gluBeginPolygon(GLUtesselator* tess) {
  gluTessBeginPolygon(tess, nullptr);
  gluTessBeginContour(tess);
}

void gluNextContour(GLUtesselator* tess, GLenum) {
  gluTessEndContour(tess);
  gluTessBeginContour(tess);
}

void gluEndPolygon(GLUtesselator* tess) {
  gluTessEndContour(tess);
  gluTessEndPolygon(tess);
}

}  // extern "C"
