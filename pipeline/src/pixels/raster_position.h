// The current raster position (OpenGL 1.5 specification, section 2.13; table 6.5): where
// glBitmap, glDrawPixels and glCopyPixels put their pixels, with the depth, colour, texture
// coordinates and distance their fragments take.
//
// glRasterPos treats its coordinates like a vertex: modelview and projection, clipping against
// the view volume and the user clip planes (a point outside makes the position invalid), the
// perspective division and the viewport. Its colour is lit as a vertex's is, its texture
// coordinates go through texture generation and the texture matrix, whether or not texturing is
// enabled. glWindowPos (GL 1.4, section 2.13) gives window coordinates directly.
#pragma once

#include "texture/texture_units.h"

namespace glass::gl {

struct Context;

struct RasterPositionState {
  float window[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // x_w, y_w, z_w and the clip w_c
  bool valid = true;
  float distance = 0.0f;                       // Euclidean distance from the eye (spec 2.13)
  float color[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float secondaryColor[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  // Per texture unit (spec 2.13: the current raster texture coordinates of each unit).
  float texCoord[kTextureUnitCount][4] = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 1.0f}};
  float index = 1.0f;                          // colour index mode only; reported as 1
};

// glRasterPos's work once its errors are checked: object coordinates (x, y, z, w).
void setRasterPosition(Context& ctx, const float object[4]);

// glWindowPos's work (GL 1.4, section 2.13): window x, y as given, z clamped to [0, 1] and mapped
// through the depth range, w_c = 1; colour and texture coordinates are the current ones, the
// distance is 0 (the fog coordinate source is always the fragment depth in glass).
void setWindowPosition(Context& ctx, float x, float y, float z);

}  // namespace glass::gl
