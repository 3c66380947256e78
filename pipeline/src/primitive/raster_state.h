// Rasterization state (spec 3.3-3.5; tables 6.12 and 6.13): point size, line width and stipple,
// shade model, polygon mode, culling, front face, polygon offset and polygon stipple.
#pragma once

#include <GL/gl.h>

#include "primitive/polygon_stipple.h"

namespace glass::gl {

// The widths and sizes glass rasterizes (GL_ALIASED_*_RANGE); larger requests are clamped.
inline constexpr float kMaxPointSize = 255.0f;
inline constexpr float kMaxLineWidth = 255.0f;

struct RasterState {
  float pointSize = 1.0f;
  // glPointParameter (OpenGL 1.4, primitive/point_parameters.h).
  float pointSizeMin = 0.0f;
  float pointSizeMax = kMaxPointSize;
  float pointFadeThreshold = 1.0f;
  float pointDistanceAttenuation[3] = {1.0f, 0.0f, 0.0f};
  float lineWidth = 1.0f;
  bool lineStipple = false;          // GL_LINE_STIPPLE
  int lineStippleFactor = 1;         // [1, 256]
  unsigned short lineStipplePattern = 0xFFFF;

  GLenum shadeModel = GL_SMOOTH;     // GL_FLAT, GL_SMOOTH or GL_PHONG_WIN (glass extension)

  GLenum polygonModeFront = GL_FILL;
  GLenum polygonModeBack = GL_FILL;
  bool cullFace = false;             // GL_CULL_FACE
  GLenum cullFaceMode = GL_BACK;
  GLenum frontFace = GL_CCW;

  float polygonOffsetFactor = 0.0f;
  float polygonOffsetUnits = 0.0f;
  bool polygonOffsetFill = false;
  bool polygonOffsetLine = false;
  bool polygonOffsetPoint = false;

  bool polygonStipple = false;       // GL_POLYGON_STIPPLE
  PolygonStipplePattern polygonStipplePattern;  // glPolygonStipple

  // Accepted and reported, without effect: glass draws aliased primitives only.
  bool pointSmooth = false;
  bool lineSmooth = false;
  bool polygonSmooth = false;
};

}  // namespace glass::gl
