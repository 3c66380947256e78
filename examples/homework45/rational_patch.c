#include "rational_patch.h"

#include <math.h>
#include <stddef.h>
#include <GL/glut.h>

#include "rounded_upright.h"

void control_point(float out[4], double x, double y, double z, double w)
{
  out[0] = (float)(x * w);
  out[1] = (float)(y * w);
  out[2] = (float)(z * w);
  out[3] = (float)w;
}

void draw_rational_patch(const float net[][3][4], const float tex[][3][2], const float normals[][3][3], int rows,
                         int v_steps)
{
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 3, 0, 1, 12, rows, &net[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 0, 1, 6, rows, &tex[0][0][0]);
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 3, 0, 1, 9, rows, &normals[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glEnable(GL_MAP2_NORMAL);
  glDisable(GL_AUTO_NORMAL);
  glMapGrid2f(ARC_STEPS, 0, 1, v_steps, 0, 1);
  glEvalMesh2(GL_FILL, 0, ARC_STEPS, 0, v_steps);
  glEnable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_NORMAL);
  glDisable(GL_MAP2_VERTEX_4);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
}

/* Draws a patch whose normals, times w, are `side` (1 or -1) times w (P - centre), a
 * polynomial net: side 1 for a rim (the solid inside its tube), -1 for a fillet (outside). */
static void draw_net_about_centres(const float net[][3][4], const float tex[][3][2], const double centre[][3][3],
                                   float side, int rows, int v_steps)
{
  float normals[3][3][3];
  for (int v = 0; v < rows; ++v)
    for (int u = 0; u < 3; ++u)
      for (int k = 0; k < 3; ++k) normals[v][u][k] = side * (net[v][u][k] - net[v][u][3] * (float)centre[v][u][k]);
  draw_rational_patch(net, tex, (const float (*)[3][3])normals, rows, v_steps);
}

void draw_rim_net(const float net[][3][4], const float tex[][3][2], const double centre[][3][3], int rows,
                  int v_steps)
{
  draw_net_about_centres(net, tex, centre, 1.0f, rows, v_steps);
}

void draw_fillet_net(const float net[][3][4], const float tex[][3][2], const double centre[][3][3], int rows,
                     int v_steps)
{
  draw_net_about_centres(net, tex, centre, -1.0f, rows, v_steps);
}

/* The point (x, y, z) of `frame` (NULL: the object's own axes) into out. */
static void frame_point(const double frame[4][3], double x, double y, double z, double out[3])
{
  for (int k = 0; k < 3; ++k)
    out[k] = frame ? frame[0][k] + x * frame[1][k] + y * frame[2][k] + z * frame[3][k] : k == 0 ? x : k == 1 ? y : z;
}

void turned_profile_net_in_frame(const double arc[3][2], const double axis[2], const double scale[3],
                                 const double y[3], const double frame[4][3], float s0, float s_length, float t0,
                                 float t2, float net[3][3][4], float tex[3][3][2], double centre[3][3][3])
{
  const double w = sqrt(2.0) / 2.0;
  const double arc_weight[3] = {1.0, w, 1.0};
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 3; ++u) {
      double p[3];
      frame_point(frame, axis[0] + scale[v] * (arc[u][0] - axis[0]), y[v], axis[1] + scale[v] * (arc[u][1] - axis[1]), p);
      control_point(net[v][u], p[0], p[1], p[2], arc_weight[u] * arc_weight[v]);
      tex[v][u][0] = s0 + s_length * (float)u / 2;
      tex[v][u][1] = t0 + (t2 - t0) * (float)v / 2;
      frame_point(frame, axis[0] + scale[2] * (arc[u][0] - axis[0]), y[0], axis[1] + scale[2] * (arc[u][1] - axis[1]),
                  centre[v][u]);
    }
}

void turned_profile_net(const double arc[3][2], const double axis[2], const double scale[3], const double y[3],
                        float s0, float s_length, float t0, float t2, float net[3][3][4], float tex[3][3][2],
                        double centre[3][3][3])
{
  turned_profile_net_in_frame(arc, axis, scale, y, NULL, s0, s_length, t0, t2, net, tex, centre);
}

void rim_corner_net(const double arc[3][2], const double axis[2], int convex, double below, double rim, float s0,
                    float s_length, float t0, float t2, float net[3][3][4], float tex[3][3][2],
                    double centre[3][3][3])
{
  const double scale[3] = {1.0, 1.0, convex ? 0.0 : 2.0}, y[3] = {below, rim, rim};
  turned_profile_net(arc, axis, scale, y, s0, s_length, t0, t2, net, tex, centre);
}

void strip_column_texture(float tex[3][2], float s, float t0, float t2)
{
  const float ts[3] = {t0, (t0 + t2) / 2, t2};
  for (int u = 0; u < 3; ++u) {
    tex[u][0] = s;
    tex[u][1] = ts[u];
  }
}
