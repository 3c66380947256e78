// Polygon offset (spec 3.5.5): the depth of every fragment of a polygon is moved by
//   o = m * factor + r * units
// where m is the polygon's maximum depth slope, approximated as the spec allows by
// max(|dz_w/dx_w|, |dz_w/dy_w|) (as Mesa does), and r is "the smallest value that is guaranteed to
// produce a resolvable difference" in the 24-bit depth buffer, which the specification leaves to
// the implementation. glass takes Mesa's (llvmpipe and its draw module: offset_units * mrd * 2),
// r = 2 / (2^24 - 1): an offset of one step of 1 / (2^24 - 1) can be lost to the rounding of
// depth to 24 bits, two steps cannot. (Measured: a square drawn over itself with GL_LESS wins
// from units -0.3 in Mesa, -0.4 in glass; with one step per unit glass needed -1.0.)
#pragma once

#include "glass/raster/vertex.h"

namespace glass::gl {

inline constexpr double kMinimumResolvableDepth = 2.0 / 16777215.0;

// The maximum depth slope m of the plane through a, b and c (0 for a degenerate triangle).
double maxDepthSlope(const raster::WindowVertex& a, const raster::WindowVertex& b,
                     const raster::WindowVertex& c);

// The offset o of a polygon given by its window vertices (any convex polygon: the slope is taken
// from the fan triangle of largest area, all of them lying in one plane).
double polygonOffset(float factor, float units, const raster::WindowVertex* vertices, int count);

}  // namespace glass::gl
