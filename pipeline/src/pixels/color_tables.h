// Colour table lookup (OpenGL 1.4 specification, section 3.6.5, "Color Table Lookup", and the
// post-convolution and post-colour-matrix lookups that work the same way).
#pragma once

#include "pixels/imaging_state.h"

namespace glass::gl {

// Replaces the components of count RGBA groups that the table's format names (table 3.17):
//   GL_ALPHA            A = At
//   GL_LUMINANCE        R = Lt, G = Lt, B = Lt
//   GL_LUMINANCE_ALPHA  R = Lt, G = Lt, B = Lt, A = At
//   GL_INTENSITY        R = It, G = It, B = It, A = It
//   GL_RGB              R = Rt, G = Gt, B = Bt
//   GL_RGBA             R = Rt, G = Gt, B = Bt, A = At
// Each replaced component selects its own entry: it is clamped to [0, 1], multiplied by
// width - 1 and rounded to the nearest integer. A table of width 0 changes nothing.
void lookUpColorTable(const ColorTable& table, float* rgba, int count);

}  // namespace glass::gl
