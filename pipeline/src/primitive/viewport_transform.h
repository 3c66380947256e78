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

void toWindow(const ViewportTransform& transform, const raster::ClipVertex& in, int varyingCount,
              raster::WindowVertex& out);

}  // namespace glass::gl
