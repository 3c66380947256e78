// Vertices as the raster stage sees them: in homogeneous clip space (input to clipping) and in
// window space (input to triangle, line and point rasterization). The raster stage knows nothing
// of GL state; the pipeline decides what each varying slot means (see pipeline/src/varyings.h).
#pragma once

#include <cstdint>

namespace glass::raster {

// Attributes interpolated across a primitive: colours, texture coordinates (eight texture units),
// fog coordinate, ... Only the prefix a primitive uses is interpolated (varyingCount).
inline constexpr int kMaxVaryings = 48;
// User clip planes (GL_CLIP_PLANE0..5).
inline constexpr int kMaxUserClipPlanes = 6;

// A vertex in homogeneous clip coordinates, ready for clipping (OpenGL 1.5 spec, section 2.12).
struct ClipVertex {
  float clip[4];  // x_c, y_c, z_c, w_c
  // Signed distance to each user clip plane, p . (x_e, y_e, z_e, w_e) with p in eye space.
  // Distances are linear in the homogeneous coordinates, so clipping interpolates them like any
  // other attribute; a vertex is inside plane i when userClipDistance[i] >= 0.
  float userClipDistance[kMaxUserClipPlanes];
  float varyings[kMaxVaryings];
};

// A vertex after perspective division and the viewport transform (spec section 2.11.1).
struct WindowVertex {
  float x, y;  // window coordinates; pixel (i, j) has its centre at (i + 0.5, j + 0.5)
  float z;     // window depth in [0, 1], after glDepthRange
  float invW;  // 1 / w_c, used for perspective-correct interpolation
  float varyings[kMaxVaryings];
};

// Which part of the framebuffer may be written: the framebuffer intersected with the scissor box.
// Half-open: x0 <= x < x1, y0 <= y < y1.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

}  // namespace glass::raster
