// Polygon facing (spec 2.14.1 and 3.5.1): a polygon is front facing when its window-space signed
// area has the sign glFrontFace asks for (positive for GL_CCW).
//
// glass decides facing before clipping, from clip coordinates: with window x, y obtained from
// x_c / w_c, y_c / w_c by a scale of positive factors, the signed area of a triangle has the
// sign of det[x_c y_c w_c] (rows: the three vertices) whenever its visible part has w_c > 0.
// Clipping keeps vertex order and produces convex combinations of the vertices, so the visible
// part of a triangle that crosses w_c = 0 has that same sign too. Deciding early lets culling
// skip clipping, and two-sided lighting pick the back colours before clipping interpolates them.
#pragma once

#include <GL/gl.h>

#include "glass/raster/vertex.h"

namespace glass::gl {

// True when the window-space signed area of (a, b, c) is positive (counter-clockwise).
bool isCounterClockwise(const raster::ClipVertex& a, const raster::ClipVertex& b,
                        const raster::ClipVertex& c);

inline bool isFrontFacing(bool counterClockwise, GLenum frontFace) {
  return counterClockwise == (frontFace == GL_CCW);
}

}  // namespace glass::gl
