/* The quarter cylinder of a rounded upright edge (rounded_upright.h). The middle control point is
 * the corner itself weighted by sqrt(2)/2, which makes the quadratic an exact circle arc: around
 * an axis inside the solid at a convex corner, outside it (a fillet filling the corner) at a
 * concave one; the control points are the same. */
#include "rounded_upright.h"

#include <math.h>
#include <GL/glut.h>

void quarter_arc_point(const float from[2], const float corner[2], const float to[2], double u, double out[2])
{
  const double w = sqrt(2.0) / 2.0;
  const double b0 = (1 - u) * (1 - u), b1 = 2 * u * (1 - u) * w, b2 = u * u;
  const double sum = b0 + b1 + b2;
  out[0] = (b0 * from[0] + b1 * corner[0] + b2 * to[0]) / sum;
  out[1] = (b0 * from[1] + b1 * corner[1] + b2 * to[1]) / sum;
}

void quarter_cylinder(const float from[2], const float corner[2], const float to[2], float y0, float y1, float s0,
                      float arc, float t0, float t1, int v_steps)
{
  const float w = (float)(sqrt(2.0) / 2.0);
  float points[2][3][4]; /* [v][u][xyzw] */
  for (int v = 0; v < 2; ++v) {
    float y = v ? y1 : y0;
    const float *corners[3] = {from, corner, to};
    for (int u = 0; u < 3; ++u) {
      float weight = u == 1 ? w : 1.0f;
      points[v][u][0] = corners[u][0] * weight;
      points[v][u][1] = y * weight;
      points[v][u][2] = corners[u][1] * weight;
      points[v][u][3] = weight;
    }
  }
  float texture_points[2][3][2] = {{{s0, t0}, {s0 + arc / 2, t0}, {s0 + arc, t0}},
                                   {{s0, t1}, {s0 + arc / 2, t1}, {s0 + arc, t1}}};
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 3, 0, 1, 12, 2, &points[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 0, 1, 6, 2, &texture_points[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glMapGrid2f(ARC_STEPS, 0, 1, v_steps, 0, 1);
  glEvalMesh2(GL_FILL, 0, ARC_STEPS, 0, v_steps);
  glDisable(GL_MAP2_VERTEX_4);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
}
