/* A grey checkerboard of n x n quads filling the square (x0, y0) to (x0 + side, y0 + side), in
 * one glBegin(GL_QUADS): the background the texture-environment programs blend and modulate over.
 * Square (i, j) is `light` when i + j is odd, else `dark`. */
#ifndef GLASS_TOOLS_CHECKERBOARD_H
#define GLASS_TOOLS_CHECKERBOARD_H

#include <GL/gl.h>

static inline void draw_checkerboard(float x0, float y0, float side, int n, float dark, float light)
{
  const float size = side / n;
  glBegin(GL_QUADS);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float v = (i + j) % 2 ? light : dark;
      glColor3f(v, v, v);
      glVertex2f(x0 + i * size, y0 + j * size);
      glVertex2f(x0 + (i + 1) * size, y0 + j * size);
      glVertex2f(x0 + (i + 1) * size, y0 + (j + 1) * size);
      glVertex2f(x0 + i * size, y0 + (j + 1) * size);
    }
  }
  glEnd();
}

#endif /* GLASS_TOOLS_CHECKERBOARD_H */
