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

// A value rounded to the nearest integer and kept inside the GLint range; NaN gives 0 (converting
// NaN or an out-of-range value to an integer is undefined behaviour in C++).
inline GLint roundedToInteger(double v) {
  if (std::isnan(v)) return 0;
  return static_cast<GLint>(std::clamp(std::nearbyint(v), -2147483648.0, 2147483647.0));
}

// The inverse mapping for queries, rounded and kept inside the GLint range.
inline GLint colorToInteger(double c) { return roundedToInteger((c * 4294967295.0 - 1.0) / 2.0); }

// What glGet*iv returns for a float state value (spec 6.1.2): a colour maps [-1, 1] onto the
// whole GLint range, any other value is rounded to the nearest integer.
inline GLint queriedInteger(double value, bool isColor) {
  return isColor ? colorToInteger(value) : roundedToInteger(value);
}

}  // namespace glass::gl
