// The region a GL line segment covers, as a quadrilateral in 24.8 fixed point.
#pragma once

#include <cstdint>

namespace glass::raster {

// Vertices in 24.8 fixed point with pixel centres at multiples of 256 (window coordinates minus
// one half, times 256). The quadrilateral is a parallelogram: for an x-major segment its two ends
// are vertical and its long sides are the segment moved up and down by width / 2; for a y-major
// segment the ends are horizontal and the long sides are moved left and right.
struct LineQuad {
  int64_t x[4], y[4];
  bool xMajor;
};

// Builds the quadrilateral of the segment from (xa, ya) to (xb, yb) (window coordinates) with the
// width rounded to an integer (at least 1). framebufferHeight is the height of the framebuffer
// drawn into: the construction follows Mesa's, which numbers rows downwards from the top of the
// framebuffer and whose float arithmetic rounds according to the size of those numbers (0 numbers
// them downwards from y = 0). Returns false for a zero-length segment.
bool makeLineQuad(float xa, float ya, float xb, float yb, float width, int framebufferHeight,
                  LineQuad& quad);

}  // namespace glass::raster
