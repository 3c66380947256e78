// Colours given or returned as integers (glTexParameteriv(GL_TEXTURE_BORDER_COLOR),
// glTexEnviv(GL_TEXTURE_ENV_COLOR) and their glGet counterparts): the full GLint range maps
// linearly onto [-1, 1] (OpenGL 1.5 specification, table 2.9 and section 6.1.2).
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace glass::gl {

// Table 2.9: c = (2i + 1) / (2^32 - 1).
inline double integerToColor(GLint i) { return (2.0 * static_cast<double>(i) + 1.0) / 4294967295.0; }

// The inverse mapping for queries, rounded and kept inside the GLint range.
inline GLint colorToInteger(double c) {
  const double i = std::nearbyint((c * 4294967295.0 - 1.0) / 2.0);
  return static_cast<GLint>(std::clamp(i, -2147483648.0, 2147483647.0));
}

}  // namespace glass::gl
