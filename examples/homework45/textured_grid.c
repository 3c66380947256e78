/* A flat rectangle drawn as a grid of quads (textured_grid.h). */
#include <GL/gl.h>

#include "textured_grid.h"

/* A flat rectangle corner + s*edge_s + t*edge_t cut into n x n quads, so that point and spot
 * lights (computed at vertices, GL 1.x section 2.14) show their fall-off across it. */
void textured_grid(const float corner[3], const float edge_s[3], const float edge_t[3],
                         const float normal[3], int n, float texture_s0, float texture_s1, float texture_t0,
                         float texture_t1)
{
  glNormal3fv(normal);
  for (int j = 0; j < n; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; ++i) {
      for (int k = 1; k >= 0; --k) {
        float s = (float)i / (float)n, t = (float)(j + k) / (float)n;
        glTexCoord2f(texture_s0 + s * (texture_s1 - texture_s0), texture_t0 + t * (texture_t1 - texture_t0));
        glVertex3f(corner[0] + s * edge_s[0] + t * edge_t[0],
                   corner[1] + s * edge_s[1] + t * edge_t[1],
                   corner[2] + s * edge_s[2] + t * edge_t[2]);
      }
    }
    glEnd();
  }
}
