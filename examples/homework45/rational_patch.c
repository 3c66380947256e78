#include "rational_patch.h"

#include <math.h>
#include <stddef.h>
#include <string.h>
#include <GL/glut.h>

#include "rounded_upright.h"

void control_point(float out[4], double x, double y, double z, double w)
{
  out[0] = (float)(x * w);
  out[1] = (float)(y * w);
  out[2] = (float)(z * w);
  out[3] = (float)w;
}

/* Sets the maps of a patch's points and normals and the grid of its mesh, ARC_STEPS steps along u
 * and v_steps along v; end_patch_maps undoes it. */
static void begin_patch_maps(const float net[][3][4], const float normals[][3][3], int rows, int v_steps)
{
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 3, 0, 1, 12, rows, &net[0][0][0]);
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 3, 0, 1, 9, rows, &normals[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_NORMAL);
  glDisable(GL_AUTO_NORMAL);
  glMapGrid2f(ARC_STEPS, 0, 1, v_steps, 0, 1);
}

static void end_patch_maps(void)
{
  glEnable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_NORMAL);
  glDisable(GL_MAP2_VERTEX_4);
}

/* The net of a patch's normals about its centres, times w: side * w (P - centre), side 1 for a
 * rim (the solid inside its tube), -1 for a fillet (outside). */
static void normals_about_centres(const float net[][3][4], const double centre[][3][3], float side, int rows,
                                  float normals[3][3][3])
{
  for (int v = 0; v < rows; ++v)
    for (int u = 0; u < 3; ++u)
      for (int k = 0; k < 3; ++k) normals[v][u][k] = side * (net[v][u][k] - net[v][u][3] * (float)centre[v][u][k]);
}

void rational_patch_point(const float net[][3][4], int rows, double u, double v, double out[3])
{
  double h[4] = {0, 0, 0, 0};
  const double bu[3] = {(1 - u) * (1 - u), 2 * u * (1 - u), u * u};
  const double bv3[3] = {(1 - v) * (1 - v), 2 * v * (1 - v), v * v}, bv2[2] = {1 - v, v};
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 4; ++k) h[k] += (rows == 3 ? bv3[j] : bv2[j]) * bu[i] * net[j][i][k];
  for (int k = 0; k < 3; ++k) out[k] = h[k] / h[3];
}

/* draw_net_in_halves cuts an arc's grid at its middle step. */
_Static_assert(ARC_STEPS % 2 == 0, "ARC_STEPS must be even");

/* The patch begin_net_parts set up, for draw_part_mapped and draw_part_charted. */
static const float (*part_net)[3][4];
static int part_rows, part_v_steps;

void begin_net_parts(const float net[][3][4], const double centre[][3][3], float side, int rows, int v_steps)
{
  float normals[3][3][3];
  normals_about_centres(net, centre, side, rows, normals);
  begin_patch_maps(net, (const float (*)[3][3])normals, rows, v_steps);
  part_net = net;
  part_rows = rows;
  part_v_steps = v_steps;
}

void draw_part_mapped(const float tex[][3][2], struct grid_part part)
{
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 3, 0, 1, 6, part_rows, &tex[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glEvalMesh2(GL_FILL, part.i0, part.i1, part.j0, part.j1);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
}

/* The texture coordinates `texture` gives the points of row j of the grid part (columns i0 to i1). */
static void chart_row(point_texture texture, const void *chart, struct grid_part part, int j, float st[][2])
{
  for (int i = part.i0; i <= part.i1; ++i) {
    double point[3];
    rational_patch_point(part_net, part_rows, (double)i / ARC_STEPS, (double)j / part_v_steps, point);
    texture(point, chart, st[i - part.i0]);
  }
}

void draw_part_charted(point_texture texture, const void *chart, struct grid_part part)
{
  /* glEvalMesh2's rows, as the triangle strips it draws them in; the texture's map is off, so
   * glEvalPoint2 takes the current texture coordinates, charted once for each point of the grid. */
  float lower[ARC_STEPS + 1][2], upper[ARC_STEPS + 1][2];
  chart_row(texture, chart, part, part.j0, lower);
  for (int j = part.j0; j < part.j1; ++j) {
    chart_row(texture, chart, part, j + 1, upper);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = part.i0; i <= part.i1; ++i) {
      glTexCoord2fv(lower[i - part.i0]);
      glEvalPoint2(i, j);
      glTexCoord2fv(upper[i - part.i0]);
      glEvalPoint2(i, j + 1);
    }
    glEnd();
    memcpy(lower, upper, sizeof lower);
  }
}

void end_net_parts(void)
{
  end_patch_maps();
  part_net = NULL;
}

void draw_net_in_halves(const float net[][3][4], const float tex[][3][2], const double centre[][3][3], float side,
                        int rows, int v_steps, int arc_along_v, int top_first, const struct rim_chart *chart)
{
  begin_net_parts(net, centre, side, rows, v_steps);
  /* The halves across the arc: the wall's first, unless the arc starts at the top. */
  const int steps = arc_along_v ? v_steps : ARC_STEPS, middle = steps / 2;
  const int wall[2] = {top_first ? middle : 0, top_first ? steps : middle};
  const int top[2] = {top_first ? 0 : middle, top_first ? middle : steps};
  const struct grid_part wall_half = arc_along_v ? (struct grid_part){0, ARC_STEPS, wall[0], wall[1]}
                                                 : (struct grid_part){wall[0], wall[1], 0, v_steps};
  const struct grid_part top_half = arc_along_v ? (struct grid_part){0, ARC_STEPS, top[0], top[1]}
                                                : (struct grid_part){top[0], top[1], 0, v_steps};
  draw_part_mapped(tex, wall_half);
  draw_part_charted(rim_top_texture, chart, top_half);
  end_net_parts();
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

struct rim_chart strip_rim_chart(const double axis[2], const double across[2], double below, double out, double r)
{
  const struct rim_chart chart = {0, {axis[0], axis[1]}, {across[0], across[1]}, 0.0, below, out, r};
  return chart;
}

struct rim_chart corner_rim_chart(const double axis[2], double top_distance, double below, double out, double r)
{
  const struct rim_chart chart = {1, {axis[0], axis[1]}, {0.0, 0.0}, top_distance, below, out, r};
  return chart;
}

void rim_top_texture(const double p[3], const void *data, float st[2])
{
  const struct rim_chart *chart = data;
  const double from_axis[2] = {p[0] - chart->axis[0], p[2] - chart->axis[1]};
  const double height = chart->out * (p[1] - chart->below);
  if (!chart->corner) {
    /* phi (with its sign) from the point's offset across the axis: beyond the edge by R phi, the
     * point's own offset taken back. */
    const double offset = from_axis[0] * chart->across[0] + from_axis[1] * chart->across[1];
    const double beyond = chart->r * atan2(offset, height) - offset;
    st[0] = (float)(p[0] + beyond * chart->across[0]);
    st[1] = (float)(p[2] + beyond * chart->across[1]);
    return;
  }
  /* phi with its sign: positive away from the axis (a sphere's eighth, from its pole), negative
   * towards it (a torus piece, from its inner rim). */
  const double distance = hypot(from_axis[0], from_axis[1]);
  const double reach = chart->top_distance + chart->r * atan2(distance - chart->top_distance, height);
  const double scale = distance > 0 ? reach / distance : 0.0;
  st[0] = (float)(chart->axis[0] + scale * from_axis[0]);
  st[1] = (float)(chart->axis[1] + scale * from_axis[1]);
}
