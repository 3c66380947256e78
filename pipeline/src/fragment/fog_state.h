// Fog state (OpenGL 1.5 specification, section 3.10 and table 6.14), with the GL defaults.
#pragma once

#include <GL/gl.h>

namespace glass::gl {

struct FogState {
  bool enabled = false;           // glEnable(GL_FOG)
  GLenum mode = GL_EXP;           // GL_LINEAR, GL_EXP or GL_EXP2
  float density = 1.0f;           // EXP and EXP2
  float start = 0.0f, end = 1.0f; // LINEAR
  float index = 0.0f;             // colour index mode only; kept for glGet
  float color[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // clamped to [0, 1] when given
  // OpenGL 1.4: where c comes from, the eye distance (GL_FRAGMENT_DEPTH) or glFogCoord
  // (GL_FOG_COORDINATE).
  GLenum coordinateSource = GL_FRAGMENT_DEPTH;
  // GL_COLOR_SUM (OpenGL 1.4, spec 3.9): adds the secondary colour without lighting too. Its
  // attribute group is the fog's (table 6.21).
  bool colorSum = false;

  bool operator==(const FogState&) const = default;
};

}  // namespace glass::gl
