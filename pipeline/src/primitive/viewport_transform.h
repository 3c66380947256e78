// Perspective division and the viewport transformation (spec 2.11.1):
//   x_w = (p_x / 2) x_d + o_x,   y_w = (p_y / 2) y_d + o_y,   z_w = ((f - n) / 2) z_d + (n + f) / 2
// with (x_d, y_d, z_d) = (x_c, y_c, z_c) / w_c. Like Mesa, the division is a multiplication by
// 1 / w_c, which the rasterizer also needs for perspective-correct interpolation.
#pragma once

#include "glass/raster/vertex.h"

namespace glass::gl {

struct ViewportTransform {
  float scale[3] = {1.0f, 1.0f, 0.5f};
  float offset[3] = {0.0f, 0.0f, 0.5f};
};

struct Viewport;
ViewportTransform makeViewportTransform(const Viewport& viewport, double depthNear, double depthFar);

// False when the vertex has no window position: w_c = 0, or a result that is not finite. Clipping
// leaves w_c = 0 only at the clip-space origin (0, 0, 0, 0), which lies on every frustum plane:
// every other point of a segment or polygon through it has the window position of the other
// vertices' points (t v projects where v does), so such a primitive has no length or area and
// rasterizes to nothing, and a point there has no position at all. Callers draw nothing then.
// A clipped vertex whose w_c is only rounding away from 0 may overflow float in the division.
[[nodiscard]] bool toWindow(const ViewportTransform& transform, const raster::ClipVertex& in,
                            int varyingCount, raster::WindowVertex& out);

}  // namespace glass::gl
