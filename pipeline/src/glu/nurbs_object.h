// The GLU NURBS object (GLU 1.3 specification, chapter 7): properties, callbacks, the sampling
// matrices, and the curve or surface being described between gluBegin* and gluEnd*.
// nurbs_api.cpp holds the entry points; nurbs_rendering.cpp draws what was described.
#pragma once

#include <GL/gl.h>
#include <GL/glu.h>

#include <vector>

struct GLUnurbs {
  // Properties (gluNurbsProperty), with GLU's defaults.
  float samplingTolerance = 50.0f;    // GLU_SAMPLING_TOLERANCE, pixels (or object units)
  float parametricTolerance = 0.5f;   // GLU_PARAMETRIC_TOLERANCE
  GLenum samplingMethod = GLU_PATH_LENGTH;
  float uStep = 100.0f, vStep = 100.0f;  // GLU_U_STEP, GLU_V_STEP: samples per unit parameter
  GLenum displayMode = GLU_FILL;      // GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH
  bool culling = false;               // GLU_CULLING
  bool autoLoadMatrix = true;         // GLU_AUTO_LOAD_MATRIX
  GLenum mode = GLU_NURBS_RENDERER;   // GLU_NURBS_MODE

  // gluLoadSamplingMatrices, used when autoLoadMatrix is false.
  float modelview[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  int viewport[4] = {0, 0, 1, 1};

  // Callbacks. The _DATA forms get `userData` (gluNurbsCallbackData) and win over the others.
  void (*error)(GLenum) = nullptr;
  void (*begin)(GLenum) = nullptr;
  void (*beginData)(GLenum, void*) = nullptr;
  void (*vertex)(GLfloat*) = nullptr;
  void (*vertexData)(GLfloat*, void*) = nullptr;
  void (*normal)(GLfloat*) = nullptr;
  void (*normalData)(GLfloat*, void*) = nullptr;
  void (*color)(GLfloat*) = nullptr;
  void (*colorData)(GLfloat*, void*) = nullptr;
  void (*texCoord)(GLfloat*) = nullptr;
  void (*texCoordData)(GLfloat*, void*) = nullptr;
  void (*end)() = nullptr;
  void (*endData)(void*) = nullptr;
  void* userData = nullptr;

  // A gluNurbsCurve or gluNurbsSurface call, its data copied (GLU reads it at the gluEnd* that
  // closes it, but the caller's arrays may be gone by then).
  struct Map {
    GLenum type = 0;
    int uOrder = 0, vOrder = 0;      // vOrder 0 for curves
    std::vector<float> uKnots, vKnots;
    int dimension = 0;               // coordinates per control point
    std::vector<double> points;      // (i, j) at (i * vCount + j) * dimension
  };
  // A trimming curve: a piecewise linear one (gluPwlCurve) or a NURBS one (GLU_MAP1_TRIM_*).
  struct TrimCurve {
    bool piecewiseLinear = true;
    std::vector<double> points;      // u, v (or u, v, w) per point, for piecewise linear curves
    Map nurbs;                       // for NURBS trimming curves
  };

  enum class State { Idle, InCurve, InSurface, InTrim };
  State state = State::Idle;
  std::vector<Map> maps;                        // the curve's or surface's maps
  std::vector<std::vector<TrimCurve>> trims;    // each gluBeginTrim / gluEndTrim: one loop
  bool surfaceHasErrors = false;                // a map was refused: the surface is not drawn

  void reportError(GLenum code) const {
    if (error) error(code);
  }
};

namespace glass::gl::glu {

// gluEndCurve's and gluEndSurface's work: draws (or, in GLU_NURBS_TESSELLATOR mode, reports
// through the callbacks) the curve or surface described by nurb.maps and nurb.trims.
void renderNurbsCurve(GLUnurbs& nurb);
void renderNurbsSurface(GLUnurbs& nurb);

}  // namespace glass::gl::glu
