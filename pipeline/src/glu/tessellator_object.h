// The GLU tessellator object (GLU 1.3 specification, chapter 5): its properties, callbacks and the
// polygon being described. tessellator_api.cpp holds the entry points and their state machine,
// tessellator_rendering.cpp turns a finished polygon into callbacks.
#pragma once

#include <GL/gl.h>
#include <GL/glu.h>

#include <vector>

struct GLUtesselator {
  // Where in the description of a polygon the tessellator is. A call made in the wrong state
  // first moves one step at a time to the state it needs, reporting each missing call through
  // the error callback (GLU_TESS_MISSING_*), as SGI's GLU does.
  enum class State { Dormant, InPolygon, InContour };
  State state = State::Dormant;

  GLenum windingRule = GLU_TESS_WINDING_ODD;
  bool boundaryOnly = false;
  double tolerance = 0.0;  // kept and reported; only exactly coincident vertices are merged
  double normal[3] = {0.0, 0.0, 0.0};  // gluTessNormal; all zero: computed from the polygon

  // Callbacks; the _DATA form, when set, is called instead of the plain one.
  void (*begin)(GLenum) = nullptr;
  void (*beginData)(GLenum, void*) = nullptr;
  void (*vertex)(void*) = nullptr;
  void (*vertexData)(void*, void*) = nullptr;
  void (*end)() = nullptr;
  void (*endData)(void*) = nullptr;
  void (*error)(GLenum) = nullptr;
  void (*errorData)(GLenum, void*) = nullptr;
  void (*edgeFlag)(GLboolean) = nullptr;
  void (*edgeFlagData)(GLboolean, void*) = nullptr;
  void (*combine)(GLdouble[3], void*[4], GLfloat[4], void**) = nullptr;
  void (*combineData)(GLdouble[3], void*[4], GLfloat[4], void**, void*) = nullptr;

  struct Vertex {
    double coords[3];
    void* data;
  };
  void* polygonData = nullptr;  // gluTessBeginPolygon's argument, passed to _DATA callbacks
  std::vector<std::vector<Vertex>> contours;

  void reportError(GLenum code) {
    if (errorData) {
      errorData(code, polygonData);
    } else if (error) {
      error(code);
    }
  }
  void callBegin(GLenum type) {
    if (beginData) {
      beginData(type, polygonData);
    } else if (begin) {
      begin(type);
    }
  }
  void callVertex(void* data) {
    if (vertexData) {
      vertexData(data, polygonData);
    } else if (vertex) {
      vertex(data);
    }
  }
  void callEnd() {
    if (endData) {
      endData(polygonData);
    } else if (end) {
      end();
    }
  }
  void callEdgeFlag(bool flag) {
    const GLboolean value = flag ? GL_TRUE : GL_FALSE;
    if (edgeFlagData) {
      edgeFlagData(value, polygonData);
    } else if (edgeFlag) {
      edgeFlag(value);
    }
  }
  bool hasEdgeFlagCallback() const { return edgeFlag || edgeFlagData; }
  void callCombine(GLdouble coords[3], void* data[4], GLfloat weights[4], void** out) {
    if (combineData) {
      combineData(coords, data, weights, out, polygonData);
    } else if (combine) {
      combine(coords, data, weights, out);
    }
  }
};

namespace glass::gl::glu {

// gluTessEndPolygon's work: tessellates the polygon and reports the result through tess's
// callbacks.
void renderTessellation(GLUtesselator& tess,
                        const std::vector<std::vector<GLUtesselator::Vertex>>& contours);

}  // namespace glass::gl::glu
