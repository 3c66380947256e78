/* Homework 4-5 of the study guide, a model answer with GL, GLU and GLUT only: a room corner
 * (floor and two walls), an object made of cubes in the middle, read from a Wings3D file (by
 * default the L of three cubes l_block.wings; another file may be named on the command line),
 * whose edges marked hard in Wings3D are rounded by rational quadratic Bezier patches (glMap2f,
 * GL_MAP2_VERTEX_4, GL_AUTO_NORMAL): its upright edges into quarter cylinders at its convex
 * corners and concave fillets filling its inner corners; the rims of its top and its bottom
 * (each when all its edges are hard) into quarter cylinders along the sides, which meet an eighth
 * of a sphere at a rounded convex corner, a piece of a torus at a fillet, and each other in a
 * mitre at a sharp corner. The sphere and torus pieces are surfaces of revolution: the rim's quarter circle
 * turned around the upright's axis by the upright's quarter circle, a rational bi-quadratic
 * patch whose weights are products of the two arcs' weights, exact as both arcs are (study
 * guide, section 2.4). An object of several layers of cubes that is not one outline raised (a
 * cube on a slab) is drawn by layers (layered_block.c): its hard uprights rounded layer by layer,
 * the rims of a layer's piece (a rectangle, an L) with nothing above (below) it, or with only
 * rectangles standing on it whose feet are filleted, rounded as above, the feet of those
 * rectangles filled by fillets, its other rims left sharp. A texture runs on across the rounded strips, planar shadows
 * of the object fall on the floor and both walls (shadow matrices, kept on their surface by the
 * stencil buffer); walk mode with collisions, examine mode, three kinds of light, five
 * viewpoints, orthographic or perspective projection.
 *
 * Keys: arrows walk (up/down) and turn (left/right); R/r round more/less; 1-5 viewpoints;
 * w walk mode, e examine mode (drag with the left button); d/p/s directional/point/spot light;
 * o orthographic/perspective; +/- field of view; Esc quits. The right button opens the menu. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <GL/glut.h>

#include "layered_block.h"
#include "rational_patch.h"
#include "rounded_upright.h"
#include "wings_plan.h"

#define PI 3.14159265358979323846

/* The room: floor y = 0 and walls x = -ROOM, z = -ROOM, up to WALL_HEIGHT. */
#define ROOM 5.0f
#define WALL_HEIGHT 4.0f
/* The object: its floor plan from the Wings3D file when it is one layer of cubes or layers alike
 * (drawn with the rims of its top and its bottom rounded), else its layers (drawn by
 * layered_block.c, the uprights rounded layer by layer); its cells, which the walker may not
 * enter, and its bounding box. */
static struct floor_plan plan;
static struct cube_layers layers;
static int layered, has_cells;
static float block_min[3], block_max[3];
/* The height the texture's t runs from 0 to 1 over on the sides: the object's for one layer of
 * cubes, one unit for several (as s runs one unit along a side), as layered_block.c does. */
static float texture_height;
#define RADIUS_STEP 0.08f
/* How close the walker may come to a wall or to the block. */
#define WALKER_RADIUS 0.3f
/* The top of the walker's head, a little above his eyes: he walks under any part of the object
 * whose bottom is higher. */
#define HEAD_HEIGHT 1.8f
#define STEP 0.25f
#define TURN_DEGREES 5.0f
#define EYE_HEIGHT 1.6f

enum light_kind { DIRECTIONAL, POINT, SPOT };
enum menu_entry {
  MENU_WALK = 1, MENU_EXAMINE, MENU_DIRECTIONAL, MENU_POINT, MENU_SPOT, MENU_PROJECTION,
  MENU_WIDER, MENU_NARROWER, MENU_ROUNDER, MENU_SHARPER, MENU_VIEWPOINT_1
};

static float radius = 0.0f;
static int walking = 1;
static int perspective = 1;
static float field_of_view = 60.0f;
static enum light_kind light = POINT;
static float walker_x, walker_z, walker_yaw; /* yaw 0 looks along -z */
static float examine_azimuth = 30.0f, examine_elevation = 25.0f;
static int drag_x, drag_y, dragging;
static int window_width = 400, window_height = 300;
static GLuint texture;

/* Viewpoints 1-5: where the walker stands and where he looks. */
static const float viewpoints[5][3] = {
  {3.0f, 4.0f, 37.0f}, {2.0f, 2.0f, 0.0f}, {-3.5f, 3.5f, -45.0f}, {4.0f, -3.0f, 127.0f},
  {-2.0f, 4.5f, -24.0f},
};

static void set_viewpoint(int index)
{
  walker_x = viewpoints[index][0];
  walker_z = viewpoints[index][1];
  walker_yaw = viewpoints[index][2];
  walking = 1;
}

/* A checkerboard with a stripe, so that its run across the rounded edges can be seen. */
static void make_texture(void)
{
  static GLubyte texels[64][64][3];
  for (int row = 0; row < 64; ++row)
    for (int column = 0; column < 64; ++column) {
      int dark = ((row / 8) + (column / 8)) % 2;
      GLubyte value = dark ? 90 : 230;
      texels[row][column][0] = value;
      texels[row][column][1] = (GLubyte)(row < 8 ? 40 : value);
      texels[row][column][2] = (GLubyte)(dark ? 40 : 120);
    }
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
}

/* A flat rectangle corner + s*edge_s + t*edge_t cut into n x n quads, so that point and spot
 * lights (computed at vertices, GL 1.x section 2.14) show their fall-off across it. */
static void grid(const float corner[3], const float edge_s[3], const float edge_t[3],
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

/* The rims: the top's (TOP) and the bottom's (BOTTOM), each with its height and the direction
 * out of the solid through it (+1 up, -1 down). */
enum rim_level { BOTTOM, TOP };
static double rim_height(enum rim_level level) { return level == TOP ? block_max[1] : block_min[1]; }
static double rim_outward(enum rim_level level) { return level == TOP ? 1.0 : -1.0; }

/* Whether the rim along side i (from corner i to corner i + 1, any i taken round the outline)
 * at `level` is rounded: its edges there are marked hard and the radius is not 0. */
static int side_rounded(int i, enum rim_level level)
{
  const int n = plan.corners;
  i = (i % n + n) % n;
  return radius > 0 && (level == TOP ? plan.top_hard[i] : plan.bottom_hard[i]);
}

/* The radius the rim along side i at `level` is rounded with (0: sharp). */
static double side_radius(int i, enum rim_level level) { return side_rounded(i, level) ? radius : 0.0; }

/* Whether the rim is rounded on either side of corner k at `level`. */
static int corner_rounded(int k, enum rim_level level)
{
  return side_rounded(k - 1, level) || side_rounded(k, level);
}

/* The texture's t on the sides at height y: 0 at the bottom, 1 at texture_height above it (the
 * top, for one layer), the rims' arcs running on beyond the walls by their length. */
static float side_t(double y) { return (float)((y - block_min[1]) / texture_height); }

/* Turns the order of `rows` rows of `row_size` bytes each round. */
static void reverse_rows(void *data, int rows, size_t row_size)
{
  unsigned char *bytes = data;
  for (int j = 0; j < rows / 2; ++j)
    for (size_t k = 0; k < row_size; ++k) {
      const unsigned char swap = bytes[(size_t)j * row_size + k];
      bytes[(size_t)j * row_size + k] = bytes[(size_t)(rows - 1 - j) * row_size + k];
      bytes[(size_t)(rows - 1 - j) * row_size + k] = swap;
    }
}

/* Draws the rim's patch net[v][u] (rows = 2 or 3 rows of 3 homogeneous points) with its normals
 * from the centres centre[v][u], in its two halves (draw_net_in_halves): the wall's with the
 * texture net tex[v][u], the top's with `chart`; its rows turned round when dP/du x dP/dv points
 * into the solid at its middle (so every patch of the top's rim faces up and out, of the bottom's
 * down and out, for its winding). */
static void draw_rim_patch(float net[][3][4], float tex[][3][2], const double centre[][3][3], int rows,
                           enum rim_level level, const struct rim_chart *chart)
{
  double centres[3][3][3];
  memcpy(centres, centre, (size_t)rows * sizeof centres[0]);
  double a[3], b[3], c[3], d[3];
  rational_patch_point((const float (*)[3][4])net, rows, 0.4, 0.5, a);
  rational_patch_point((const float (*)[3][4])net, rows, 0.6, 0.5, b);
  rational_patch_point((const float (*)[3][4])net, rows, 0.5, 0.4, c);
  rational_patch_point((const float (*)[3][4])net, rows, 0.5, 0.6, d);
  const double du[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, dv[3] = {d[0] - c[0], d[1] - c[1], d[2] - c[2]};
  const int turned = (du[2] * dv[0] - du[0] * dv[2]) * rim_outward(level) < 0;
  if (turned) {
    reverse_rows(net, rows, sizeof net[0]);
    reverse_rows(tex, rows, sizeof tex[0]);
    reverse_rows(centres, rows, sizeof centres[0]);
  }
  /* A strip's arc runs along u (its rows run along the side); a corner piece's along v, from the
   * wall to the top unless its rows were turned round. */
  const int corner = rows == 3;
  draw_net_in_halves((const float (*)[3][4])net, (const float (*)[3][2])tex, (const double (*)[3][3])centres, 1.0f,
                     rows, corner ? ARC_STEPS : 4, corner, corner && turned, chart);
}

/* A quarter cylinder of the current radius around the upright edge at corner k, from the point
 * `from` on one side to `to` on the next, walked counter-clockwise seen from above so that
 * GL_AUTO_NORMAL's dP/du x dP/dv points out of the solid, between the rims (R in from a rounded
 * one). The texture s runs from s0 to s0 + the arc's length, so the checkerboard continues from
 * the face. */
static void rounded_edge(int k, const float from[2], const float corner[2], const float to[2], float s0)
{
  const float y0 = block_min[1] + (corner_rounded(k, BOTTOM) ? radius : 0.0f);
  const float y1 = block_max[1] - (corner_rounded(k, TOP) ? radius : 0.0f);
  quarter_cylinder(from, corner, to, y0, y1, s0, (float)(PI / 2.0) * radius, side_t(y0), side_t(y1), 4);
}

/* Where the outline leaves and reaches corner i: R along its sides from the corner when the
 * upright there is rounded, the corner itself otherwise. */
static void corner_ends(int i, float from[2], float to[2])
{
  const int n = plan.corners;
  const double *here = plan.xz[i], *before = plan.xz[(i + n - 1) % n], *after = plan.xz[(i + 1) % n];
  const double r = plan.rounded[i] ? radius : 0.0;
  const double to_before = hypot(before[0] - here[0], before[1] - here[1]);
  const double to_after = hypot(after[0] - here[0], after[1] - here[1]);
  for (int k = 0; k < 2; ++k) {
    from[k] = (float)(here[k] + r * (before[k] - here[k]) / to_before);
    to[k] = (float)(here[k] + r * (after[k] - here[k]) / to_after);
  }
}

/* The unit vector into the solid across side i (from corner i to corner i + 1): to the left of
 * the walk, the sides' outward normals being to its right. */
static void inward(int i, double out[2])
{
  const double *a = plan.xz[i], *b = plan.xz[(i + 1) % plan.corners];
  const double length = hypot(b[0] - a[0], b[1] - a[1]);
  out[0] = (b[1] - a[1]) / length;
  out[1] = -(b[0] - a[0]) / length;
}

/* The axis of the rounded upright at corner i (x, z): inside the solid at a convex corner,
 * outside it at a concave one; R from both sides' planes. */
static void upright_axis(int i, double out[2])
{
  float from[2], to[2];
  corner_ends(i, from, to);
  for (int k = 0; k < 2; ++k) out[k] = (double)from[k] + (double)to[k] - plan.xz[i][k];
}

/* Where the top (or the bottom) meets its rim at corner k, in (x, z): above a rounded upright,
 * its axis (a convex corner, where the sphere closes) or the arc twice as far from it (a concave
 * one, the torus's inner rim, drawn by the caller); above a sharp upright, R in from each side
 * whose rim is rounded: the mitre's top when both are, else where the one rounded strip ends, in
 * the plane of the sharp side. */
static void rim_top_corner(int k, enum rim_level level, double out[2])
{
  const int n = plan.corners;
  if (plan.rounded[k] && radius > 0) {
    upright_axis(k, out);
    return;
  }
  double before[2], after[2];
  inward((k + n - 1) % n, before);
  inward(k, after);
  const double r_before = side_radius(k - 1, level), r_after = side_radius(k, level);
  for (int c = 0; c < 2; ++c) out[c] = plan.xz[k][c] + r_before * before[c] + r_after * after[c];
}

/* The unit vector along side i, in the direction of the walk. */
static void along_side(int i, double out[2])
{
  double in[2];
  inward(i, in);
  out[0] = -in[1];
  out[1] = in[0];
}

static void piece_vertex(const double p[3], const double e[2], float s_e, const double s_direction[2])
{
  glTexCoord2f(s_e + (float)((p[0] - e[0]) * s_direction[0] + (p[2] - e[1]) * s_direction[1]), side_t(p[1]));
  glVertex3dv(p);
}

/* A flat piece where a rounded rim's strip ends against a sharp edge, in the vertical plane
 * through e and c (x, z, R apart): the strip's end is the rim's quarter circle around c at R in
 * from the rim's height, from e (R in) to c (at the rim's height), the same rational quadratic as
 * the strip's patch (control points e R in, e at the rim weighted sqrt(2)/2, c at the rim), so
 * they share their points. With `disk` the piece is the quarter disk inside the arc (fanned from
 * its centre), else the quarter moon between the arc and the square's corner e at the rim (fanned
 * from that corner). Its texture: t as on the sides, s from s_e at e along `s_direction`. */
static void rim_end_piece(const double e[2], const double c[2], enum rim_level level, const double normal[2],
                          float s_e, const double s_direction[2], int disk)
{
  const double rim = rim_height(level), inner = rim - rim_outward(level) * radius, w = sqrt(2.0) / 2.0;
  const double centre[3] = {disk ? c[0] : e[0], disk ? inner : rim, disk ? c[1] : e[1]};
  glNormal3d(normal[0], 0, normal[1]);
  glBegin(GL_TRIANGLE_FAN);
  piece_vertex(centre, e, s_e, s_direction);
  for (int step = 0; step <= ARC_STEPS; ++step) {
    const double u = (double)step / ARC_STEPS;
    const double b0 = (1 - u) * (1 - u), b1 = 2 * u * (1 - u) * w, b2 = u * u, sum = b0 + b1 + b2;
    const double p[3] = {((b0 + b1) * e[0] + b2 * c[0]) / sum, (b0 * inner + (b1 + b2) * rim) / sum,
                         ((b0 + b1) * e[1] + b2 * c[1]) / sum};
    piece_vertex(p, e, s_e, s_direction);
  }
  glEnd();
}

/* The rounded rim along side i: the rim's quarter circle (from the side at R below the top, over
 * the top edge weighted sqrt(2)/2, to the top R in from the side) swept from the side's start to
 * its end. Above a rounded upright it ends where the upright's strip does, R along the side from
 * the corner; above a sharp one it ends in the corner's bisecting plane (the mitre the
 * neighbouring side's strip ends in too), its top point moved along the side by R. It is drawn
 * in its two halves (draw_net_in_halves), each with the texture of the face it touches: the half next
 * to the wall with the wall's (s along the side, t on up from the wall's top by the arc's
 * length), the half next to the top with the top's (x, z) run on beyond the top's edge; the
 * checkerboard changes from one to the other along the arc's middle, as the scene language's
 * rounding does (glass/geometry/edge_rounding.h). */
static void rim_strip(int i, enum rim_level level, float s0, float s1)
{
  const int n = plan.corners;
  const double r = side_radius(i, level), w = sqrt(2.0) / 2.0;
  const double top = rim_height(level), out = rim_outward(level), height = texture_height;
  float net[2][3][4];
  double centre[2][3][3];
  /* The strip's axis: R in from side i and R below the top. */
  double in_i[2], along[2];
  inward(i, in_i);
  along[0] = -in_i[1];
  along[1] = in_i[0];
  const double axis[2] = {plan.xz[i][0] + r * in_i[0], plan.xz[i][1] + r * in_i[1]};
  for (int end = 0; end < 2; ++end) {
    const int k = (i + end) % n;
    float from[2], to[2];
    corner_ends(k, from, to);
    double edge[2], on_top[2];
    if (plan.rounded[k] && radius > 0) {
      const float *at = end ? from : to;
      for (int c = 0; c < 2; ++c) {
        edge[c] = at[c];
        on_top[c] = at[c] + r * in_i[c];
      }
    } else {
      for (int c = 0; c < 2; ++c) edge[c] = plan.xz[k][c];
      rim_top_corner(k, level, on_top);
    }
    control_point(net[end][0], edge[0], top - out * r, edge[1], 1.0);
    control_point(net[end][1], edge[0], top, edge[1], w);
    control_point(net[end][2], on_top[0], top, on_top[1], 1.0);
    for (int u = 0; u < 3; ++u) {
      const double x = net[end][u][0] / net[end][u][3], z = net[end][u][2] / net[end][u][3];
      const double on_axis = (x - axis[0]) * along[0] + (z - axis[1]) * along[1];
      centre[end][u][0] = axis[0] + on_axis * along[0];
      centre[end][u][1] = top - out * r;
      centre[end][u][2] = axis[1] + on_axis * along[1];
    }
  }
  const float t0 = side_t(top - out * r), t2 = (float)(t0 + out * PI / 2 * r / height);
  float tex[2][3][2];
  for (int end = 0; end < 2; ++end) strip_column_texture(tex[end], end ? s1 : s0, t0, t2);
  const double outward[2] = {-in_i[0], -in_i[1]};
  const struct rim_chart chart = strip_rim_chart(axis, outward, top - out * r, out, r);
  draw_rim_patch(net, tex, (const double (*)[3][3])centre, 2, level, &chart);
}

/* Above the rounded upright at corner i, where the rim's strips of its two sides end: the rim's
 * quarter circle turned around the upright's axis by the upright's quarter circle, an eighth of a
 * sphere at a convex corner and a quarter of a torus above a fillet (rim_corner_net). Like the
 * strips, it is drawn in the two halves of the rim's quarter circle: the half next to the walls
 * with their texture (s on round the upright's arc, t on up), the half next to the top with the
 * top's (x, z) run on beyond the top's edge by the rim's arc length, away from the axis at a convex
 * corner (where the top's edge is the sphere's pole, the axis) and towards it above a fillet
 * (where the top's edge is the torus's inner rim, 2 R from the axis). */
static void rim_corner(int i, enum rim_level level, float s0)
{
  const double r = radius;
  const double top = rim_height(level), out = rim_outward(level), height = texture_height;
  float from[2], to[2];
  corner_ends(i, from, to);
  double axis[2];
  upright_axis(i, axis);
  const double arc[3][2] = {{from[0], from[1]}, {plan.xz[i][0], plan.xz[i][1]}, {to[0], to[1]}};
  float net[3][3][4], tex[3][3][2];
  double centre[3][3][3];
  const float length = (float)(PI / 2) * radius;
  const float t0 = side_t(top - out * r), t2 = (float)(t0 + out * PI / 2 * r / height);
  rim_corner_net(arc, axis, plan.convex[i], top - out * r, top, s0, length, t0, t2, net, tex, centre);
  const struct rim_chart chart = corner_rim_chart(axis, plan.convex[i] ? 0.0 : 2 * r, top - out * r, out, r);
  draw_rim_patch(net, tex, (const double (*)[3][3])centre, 3, level, &chart);
}

static void GLAPIENTRY top_vertex(void *data)
{
  const GLdouble *p = data;
  glTexCoord2d(p[0], p[2]);
  glVertex3dv(p);
}

/* One point of the top's (or the bottom's) outline, at height y. */
static void outline_point(GLdouble (*outline)[3], int *count, double x, double y, double z)
{
  outline[*count][0] = x;
  outline[*count][1] = y;
  outline[*count][2] = z;
  ++*count;
}

/* The top or the bottom: the outline with its rounded corners, which may be concave, so GLU's
 * tessellator cuts it into triangles (facing up or down: the normal is given). Along a side whose
 * rim is rounded the outline runs R in from the side, along a sharp one on the side's edge. */
static void block_end(enum rim_level level)
{
  static GLUtesselator *tess;
  static GLdouble (*outline)[3];
  static int capacity;
  const double y = rim_height(level), out = rim_outward(level);
  const int needed = plan.corners * (ARC_STEPS + 3);
  if (!tess) {
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (void (GLAPIENTRY *)(void))glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (void (GLAPIENTRY *)(void))top_vertex);
    gluTessCallback(tess, GLU_TESS_END, (void (GLAPIENTRY *)(void))glEnd);
  }
  gluTessNormal(tess, 0, out, 0);
  if (capacity < needed) {
    free(outline);
    outline = malloc((size_t)needed * sizeof *outline);
    if (!outline) exit(1);
    capacity = needed;
  }
  int count = 0;
  for (int i = 0; i < plan.corners; ++i) {
    float from[2], to[2], corner[2] = {(float)plan.xz[i][0], (float)plan.xz[i][1]};
    corner_ends(i, from, to);
    const int before = side_rounded(i - 1, level), after = side_rounded(i, level);
    const int upright = plan.rounded[i] && radius > 0;
    double arc[2];
    if (!before && !after) {
      /* A sharp rim on both sides: the corner, or the upright's arc. */
      const int steps = upright ? ARC_STEPS : 0;
      for (int step = 0; step <= steps; ++step) {
        quarter_arc_point(from, corner, to, (double)step / ARC_STEPS, arc);
        outline_point(outline, &count, arc[0], y, arc[1]);
      }
      continue;
    }
    double at[2];
    rim_top_corner(i, level, at);
    if (!upright) {
      /* The mitre's top, or where the one rounded strip ends in the sharp side's plane; at a
       * concave corner that end's cap reaches from the corner to it. */
      if (!plan.convex[i] && after && !before) outline_point(outline, &count, corner[0], y, corner[1]);
      outline_point(outline, &count, at[0], y, at[1]);
      if (!plan.convex[i] && before && !after) outline_point(outline, &count, corner[0], y, corner[1]);
      continue;
    }
    /* Above a rounded upright: a sharp side's edge runs on to where the upright's arc begins (or
     * ends), and the cap of the sphere or torus piece's end from there. */
    if (!before) outline_point(outline, &count, from[0], y, from[1]);
    if (plan.convex[i]) {
      /* The sphere's pole. */
      outline_point(outline, &count, at[0], y, at[1]);
    } else {
      /* Above a fillet: the torus's inner rim, the fillet's arc scaled by 2 from its axis. */
      float far_from[2], far_corner[2], far_to[2];
      for (int c = 0; c < 2; ++c) {
        far_from[c] = (float)(at[c] + 2 * (from[c] - at[c]));
        far_corner[c] = (float)(at[c] + 2 * (corner[c] - at[c]));
        far_to[c] = (float)(at[c] + 2 * (to[c] - at[c]));
      }
      for (int step = 0; step <= ARC_STEPS; ++step) {
        quarter_arc_point(far_from, far_corner, far_to, (double)step / ARC_STEPS, arc);
        outline_point(outline, &count, arc[0], y, arc[1]);
      }
    }
    if (!after) outline_point(outline, &count, to[0], y, to[1]);
  }
  glNormal3f(0, (float)out, 0);
  gluTessBeginPolygon(tess, NULL);
  gluTessBeginContour(tess);
  for (int k = 0; k < count; ++k) gluTessVertex(tess, outline[k], outline[k]);
  gluTessEndContour(tess);
  gluTessEndPolygon(tess);
}

/* At corner k, where the rim at `level` is rounded on one side of it or on both: above a rounded
 * upright the sphere or torus piece, and where one side's rim is sharp a flat cap ending it, in
 * the plane normal to that side through the upright's arc's end (the torus or sphere is kept
 * whole and steps down to the sharp edge, as the library's rounding does); above a sharp concave
 * corner with one side rounded, the quarter moon that ends that side's strip, in the sharp side's
 * plane past the corner. (Above a sharp convex corner the sharp side's face is cut instead:
 * side_face.) s is the texture's s where the corner's arc begins. */
static void corner_pieces(int k, enum rim_level level, float s)
{
  const int n = plan.corners;
  const int before = side_rounded(k - 1, level), after = side_rounded(k, level);
  if (!before && !after) return;
  if (plan.rounded[k]) {
    rim_corner(k, level, s);
    if (before && after) return;
    float from[2], to[2];
    corner_ends(k, from, to);
    double axis[2], e[2], c[2], normal[2], direction[2];
    upright_axis(k, axis);
    const double scale = plan.convex[k] ? 0.0 : 2.0;
    for (int m = 0; m < 2; ++m) {
      e[m] = after ? from[m] : to[m];
      c[m] = axis[m] + scale * (e[m] - axis[m]);
      normal[m] = (plan.xz[k][m] - e[m]) / radius;
      direction[m] = (c[m] - e[m]) / radius;
    }
    rim_end_piece(e, c, level, normal, after ? s : s + (float)(PI / 2) * radius, direction, 0);
    return;
  }
  if (plan.convex[k] || (before && after)) return;
  const int sharp = after ? (k + n - 1) % n : k, rounded = after ? k : (k + n - 1) % n;
  double in_rounded[2], in_sharp[2], direction[2], c[2];
  inward(rounded, in_rounded);
  inward(sharp, in_sharp);
  along_side(sharp, direction);
  for (int m = 0; m < 2; ++m) c[m] = plan.xz[k][m] + radius * in_rounded[m];
  const double normal[2] = {-in_sharp[0], -in_sharp[1]};
  rim_end_piece(plan.xz[k], c, level, normal, s, direction, 0);
}

/* Whether the rim of side i at `level` is cut at its end `end` (0: corner i, 1: corner i + 1):
 * its own rim sharp there, the corner convex with a sharp upright and the next side's rim
 * rounded. That side's strip ends in this side's plane, and of the corner's R x R square below
 * the rim this side keeps only the quarter disk under the strip's arc. */
static int side_cut(int i, int end, enum rim_level level)
{
  const int k = (i + end) % plan.corners;
  return !side_rounded(i, level) && side_rounded(end ? i + 1 : i - 1, level) && plan.convex[k] &&
         !(plan.rounded[k] && radius > 0);
}

/* The flat face of side i from `start` to `end` (x, z), between its rims (R in from a rounded
 * one), with the texture's s from s0 to s1 along it; outwards is to the right of the walk. */
static void side_face(int i, const float start[2], const float end[2], float s0, float s1)
{
  const float along[3] = {end[0] - start[0], 0, end[1] - start[1]};
  const float length = sqrtf(along[0] * along[0] + along[2] * along[2]);
  if (length <= 0) return;
  const float normal[3] = {-along[2] / length, 0, along[0] / length};
  const double low = block_min[1] + side_radius(i, BOTTOM), high = block_max[1] - side_radius(i, TOP);
  const int cut[2][2] = {{side_cut(i, 0, BOTTOM), side_cut(i, 1, BOTTOM)}, {side_cut(i, 0, TOP), side_cut(i, 1, TOP)}};
  const double inner_low = low + (cut[BOTTOM][0] || cut[BOTTOM][1] ? radius : 0);
  const double inner_high = high - (cut[TOP][0] || cut[TOP][1] ? radius : 0);
  const float base[3] = {start[0], (float)inner_low, start[1]}, up[3] = {0, (float)(inner_high - inner_low), 0};
  grid(base, along, up, normal, 4, s0, s1, side_t(inner_low), side_t(inner_high));
  for (int level = BOTTOM; level <= TOP; ++level) {
    if (!cut[level][0] && !cut[level][1]) continue;
    /* The band between the rim and R in from it, short of the cut squares, then the quarter
     * disks in them. */
    const double y0 = level == TOP ? inner_high : low, y1 = level == TOP ? high : inner_low;
    const float r0 = cut[level][0] ? radius : 0.0f, r1 = cut[level][1] ? radius : 0.0f;
    const float band_base[3] = {start[0] + along[0] / length * r0, (float)y0, start[1] + along[2] / length * r0};
    const float band_along[3] = {along[0] / length * (length - r0 - r1), 0, along[2] / length * (length - r0 - r1)};
    const float band_up[3] = {0, (float)(y1 - y0), 0};
    grid(band_base, band_along, band_up, normal, 4, s0 + r0, s1 - r1, side_t(y0), side_t(y1));
    for (int at = 0; at < 2; ++at) {
      if (!cut[level][at]) continue;
      const int k = (i + at) % plan.corners;
      double in_other[2], c[2], direction[2];
      inward(at ? (i + 1) % plan.corners : (i + plan.corners - 1) % plan.corners, in_other);
      along_side(i, direction);
      for (int m = 0; m < 2; ++m) c[m] = plan.xz[k][m] + radius * in_other[m];
      const double face_normal[2] = {normal[0], normal[2]};
      rim_end_piece(plan.xz[k], c, (enum rim_level)level, face_normal, at ? s1 : s0, direction, 1);
    }
  }
}

/* The object: its sides and rounded edges, in order around it so that the texture's s is the
 * length walked around it; then the top. */
static void block(int textured)
{
  float s = 0;
  if (textured) {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  }
  if (layered) {
    draw_layered_block(&layers, radius);
    if (textured) glDisable(GL_TEXTURE_2D);
    return;
  }
  for (int i = 0; i < plan.corners; ++i) {
    const int next = (i + 1) % plan.corners;
    float from[2], to[2], next_from[2], unused[2];
    float corner[2] = {(float)plan.xz[i][0], (float)plan.xz[i][1]};
    corner_ends(i, from, to);
    corner_ends(next, next_from, unused);
    if (plan.rounded[i] && radius > 0) rounded_edge(i, from, corner, to, s);
    corner_pieces(i, TOP, s);
    corner_pieces(i, BOTTOM, s);
    if (plan.rounded[i] && radius > 0) s += (float)(PI / 2) * radius;
    /* The side from this corner to the next. */
    const float length = hypotf(next_from[0] - to[0], next_from[1] - to[1]);
    side_face(i, to, next_from, s, s + length);
    if (side_rounded(i, TOP)) rim_strip(i, TOP, s, s + length);
    if (side_rounded(i, BOTTOM)) rim_strip(i, BOTTOM, s, s + length);
    s += length;
  }
  block_end(TOP);
  block_end(BOTTOM);
  if (textured) glDisable(GL_TEXTURE_2D);
}

/* The three surfaces as planes a x + b y + c z + d = 0 facing into the room. */
static const float surfaces[3][4] = {{0, 1, 0, 0}, {0, 0, 1, ROOM}, {1, 0, 0, ROOM}};

static void surface(int index)
{
  static const float colors[3][3] = {{0.75f, 0.7f, 0.6f}, {0.6f, 0.7f, 0.8f}, {0.8f, 0.65f, 0.6f}};
  glColor3fv(colors[index]);
  const float size = 2 * ROOM;
  if (index == 0) {
    const float corner[3] = {-ROOM, 0, ROOM}, s[3] = {size, 0, 0}, t[3] = {0, 0, -size};
    grid(corner, s, t, surfaces[0], 20, 0, 1, 0, 1);
  } else if (index == 1) {
    const float corner[3] = {-ROOM, 0, -ROOM}, s[3] = {size, 0, 0}, t[3] = {0, WALL_HEIGHT, 0};
    grid(corner, s, t, surfaces[1], 20, 0, 1, 0, 1);
  } else {
    const float corner[3] = {-ROOM, 0, ROOM}, s[3] = {0, 0, -size}, t[3] = {0, WALL_HEIGHT, 0};
    grid(corner, s, t, surfaces[2], 20, 0, 1, 0, 1);
  }
}

static void light_position(float position[4])
{
  if (light == DIRECTIONAL) {
    position[0] = 1.0f; position[1] = 0.5f; position[2] = 0.7f; position[3] = 0.0f;
  } else {
    position[0] = 3.0f; position[1] = 1.6f; position[2] = 2.5f; position[3] = 1.0f;
  }
}

/* The matrix that flattens everything onto the plane along rays from the light (homogeneous, so
 * the directional light w = 0 is the same formula): M = (plane . light) I - light plane^T,
 * stored column-major for glMultMatrixf. */
static void shadow_matrix(const float plane[4], const float light_at[4], float matrix[16])
{
  float dot = plane[0] * light_at[0] + plane[1] * light_at[1] + plane[2] * light_at[2] +
              plane[3] * light_at[3];
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      matrix[column * 4 + row] = (row == column ? dot : 0.0f) - light_at[row] * plane[column];
}

static void set_light(void)
{
  float position[4];
  light_position(position);
  const float white[4] = {0.9f, 0.9f, 0.9f, 1}, ambient[4] = {0.25f, 0.25f, 0.25f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  if (light == SPOT) {
    float direction[3] = {-position[0], 0.5f - position[1], -position[2]};
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 8.0f);
  } else {
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
  }
  if (light == DIRECTIONAL) {
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.0f);
  } else {
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.08f);
  }
}

static void set_projection(void)
{
  float aspect = (float)window_width / (float)(window_height > 0 ? window_height : 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (perspective) {
    gluPerspective(field_of_view, aspect, 0.1, 60.0);
  } else {
    /* The orthographic box as wide as the perspective view is at the block's distance. */
    float half = 6.0f * (float)tan(field_of_view * PI / 360.0);
    glOrtho(-half * aspect, half * aspect, -half, half, 0.1, 60.0);
  }
  glMatrixMode(GL_MODELVIEW);
}

static void set_camera(void)
{
  glLoadIdentity();
  if (walking) {
    double yaw = walker_yaw * PI / 180.0;
    gluLookAt(walker_x, EYE_HEIGHT, walker_z, walker_x - sin(yaw), EYE_HEIGHT - 0.15,
              walker_z - cos(yaw), 0, 1, 0);
  } else {
    double azimuth = examine_azimuth * PI / 180.0, elevation = examine_elevation * PI / 180.0;
    double distance = 9.0;
    gluLookAt(distance * cos(elevation) * sin(azimuth), 0.5 + distance * sin(elevation),
              distance * cos(elevation) * cos(azimuth), 0, 0.5, 0, 0, 1, 0);
  }
}

static void display(void)
{
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  set_projection();
  set_camera();
  set_light();

  /* Each surface marks its pixels with its number in the stencil buffer ... */
  glEnable(GL_LIGHTING);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (int index = 0; index < 3; ++index) {
    glStencilFunc(GL_ALWAYS, index + 1, 0xff);
    surface(index);
  }
  /* ... and the block's shadow on it darkens only those pixels, once each (the stencil is
   * zeroed where it fell, so overlapping shadow polygons do not darken twice). */
  float position[4], matrix[16];
  light_position(position);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  glColor4f(0, 0, 0, 0.5f);
  for (int index = 0; index < 3; ++index) {
    glStencilFunc(GL_EQUAL, index + 1, 0xff);
    shadow_matrix(surfaces[index], position, matrix);
    glPushMatrix();
    glMultMatrixf(matrix);
    block(0);
    glPopMatrix();
  }
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);

  glEnable(GL_LIGHTING);
  glColor3f(1, 1, 1);
  block(1);
  glutSwapBuffers();
}

static void reshape(int width, int height)
{
  window_width = width;
  window_height = height;
  glViewport(0, 0, width, height);
}

/* Whether the walker at (x, z) keeps his distance from the walls, the floor's open edges and the
 * object: from each column of its cells that it fills anywhere between the floor and the top of
 * his head (so that he can walk into an inner corner, and under an overhang whose bottom is above
 * his head), or from its bounding box when it is not cut into cells. */
static int walker_fits(float x, float z)
{
  if (x < -ROOM + WALKER_RADIUS || z < -ROOM + WALKER_RADIUS) return 0;
  if (x > ROOM - WALKER_RADIUS || z > ROOM - WALKER_RADIUS) return 0;
  if (!has_cells)
    return !(x > block_min[0] - WALKER_RADIUS && x < block_max[0] + WALKER_RADIUS &&
             z > block_min[2] - WALKER_RADIUS && z < block_max[2] + WALKER_RADIUS);
  for (int j = 0; j + 1 < layers.z_count; ++j)
    for (int i = 0; i + 1 < layers.x_count; ++i) {
      int filled = 0;
      for (int layer = 0; layer < layers.layer_count && !filled; ++layer)
        filled = cube_layers_filled(&layers, layer, i, j) && layers.height[layer] < HEAD_HEIGHT &&
                 layers.height[layer + 1] > 0;
      if (filled && x > layers.x[i] - WALKER_RADIUS && x < layers.x[i + 1] + WALKER_RADIUS &&
          z > layers.z[j] - WALKER_RADIUS && z < layers.z[j + 1] + WALKER_RADIUS)
        return 0;
    }
  return 1;
}

/* A step that would collide keeps the free part of its motion (x and z tried apart), so the
 * walker slides along a wall or the block instead of stopping dead. */
static void walk(float distance)
{
  double yaw = walker_yaw * PI / 180.0;
  float x = walker_x - distance * (float)sin(yaw), z = walker_z - distance * (float)cos(yaw);
  if (walker_fits(x, walker_z)) walker_x = x;
  if (walker_fits(walker_x, z)) walker_z = z;
}

static void change_radius(float change)
{
  radius += change;
  if (radius < 0) radius = 0;
  const double largest = layered ? layers.max_radius : plan.max_radius;
  if (radius > (float)largest) radius = (float)largest;
}

static void change_field_of_view(float change)
{
  field_of_view += change;
  if (field_of_view < 10) field_of_view = 10;
  if (field_of_view > 120) field_of_view = 120;
}

static void choose(int entry)
{
  switch (entry) {
  case MENU_WALK: walking = 1; break;
  case MENU_EXAMINE: walking = 0; break;
  case MENU_DIRECTIONAL: light = DIRECTIONAL; break;
  case MENU_POINT: light = POINT; break;
  case MENU_SPOT: light = SPOT; break;
  case MENU_PROJECTION: perspective = !perspective; break;
  case MENU_WIDER: change_field_of_view(5); break;
  case MENU_NARROWER: change_field_of_view(-5); break;
  case MENU_ROUNDER: change_radius(RADIUS_STEP); break;
  case MENU_SHARPER: change_radius(-RADIUS_STEP); break;
  default:
    if (entry >= MENU_VIEWPOINT_1 && entry < MENU_VIEWPOINT_1 + 5) set_viewpoint(entry - MENU_VIEWPOINT_1);
    break;
  }
  glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
  (void)x; (void)y;
  switch (key) {
  case 27: exit(0);
  case 'R': choose(MENU_ROUNDER); break;
  case 'r': choose(MENU_SHARPER); break;
  case 'w': choose(MENU_WALK); break;
  case 'e': choose(MENU_EXAMINE); break;
  case 'd': choose(MENU_DIRECTIONAL); break;
  case 'p': choose(MENU_POINT); break;
  case 's': choose(MENU_SPOT); break;
  case 'o': choose(MENU_PROJECTION); break;
  case '+': choose(MENU_NARROWER); break;
  case '-': choose(MENU_WIDER); break;
  default:
    if (key >= '1' && key <= '5') choose(MENU_VIEWPOINT_1 + (key - '1'));
    break;
  }
}

static void special(int key, int x, int y)
{
  (void)x; (void)y;
  if (!walking) return;
  switch (key) {
  case GLUT_KEY_UP: walk(STEP); break;
  case GLUT_KEY_DOWN: walk(-STEP); break;
  case GLUT_KEY_LEFT: walker_yaw += TURN_DEGREES; break;
  case GLUT_KEY_RIGHT: walker_yaw -= TURN_DEGREES; break;
  }
  glutPostRedisplay();
}

static void mouse(int button, int state, int x, int y)
{
  if (button != GLUT_LEFT_BUTTON) return;
  dragging = state == GLUT_DOWN;
  drag_x = x;
  drag_y = y;
}

/* Examine mode: dragging turns the camera around the block. */
static void motion(int x, int y)
{
  if (!dragging || walking) return;
  examine_azimuth -= 0.5f * (float)(x - drag_x);
  examine_elevation += 0.5f * (float)(y - drag_y);
  if (examine_elevation < 2) examine_elevation = 2;
  if (examine_elevation > 85) examine_elevation = 85;
  drag_x = x;
  drag_y = y;
  glutPostRedisplay();
}

/* The object's file: the first argument GLUT leaves, or the L beside this program's source. An
 * object of one layer of cubes (or of layers alike) is drawn from its floor plan, any other closed
 * object of cubes by layers; both are cut into cells for the walker's collisions when they can
 * be. */
static void load_object(int argc, char **argv)
{
  const char *path = argc > 1 ? argv[1] : HOMEWORK45_MODEL;
  char error[300], plan_error[300];
  struct wings_mesh mesh;
  if (!wings_read_mesh(path, &mesh, error, sizeof error)) {
    fprintf(stderr, "homework45: %s: %s\n", path, error);
    exit(1);
  }
  has_cells = cube_layers_from_mesh(&mesh, &layers, error, sizeof error);
  layered = !floor_plan_from_mesh(&mesh, has_cells && cube_layers_alike(&layers), &plan, plan_error,
                                  sizeof plan_error);
  wings_mesh_free(&mesh);
  if (layered && !has_cells) {
    fprintf(stderr, "homework45: %s: %s\n", path, error);
    exit(1);
  }
  if (!layered && plan.sharp_hard_edges > 0)
    fprintf(stderr, "homework45: %s: %d hard edges stay sharp (this program rounds the upright edges, and "
            "the top's and the bottom's rims along each side whose edges there are all hard)\n", path,
            plan.sharp_hard_edges);
  if (layered && layers.sharp_hard_edges > 0)
    fprintf(stderr, "homework45: %s: %d hard edges stay sharp (of an object of more than one layer of cubes "
            "this program rounds the upright edges, layer by layer, and the top (bottom) rim of a piece of a "
            "layer (cubes joined side to side, outlined by one loop, such as a rectangle or an L, its concave "
            "corners' uprights rounded) with nothing above (below) it or, above it, only rectangles of cubes whose "
            "feet it fills with fillets (rectangles standing on the layer below, each side inside its top or flush "
            "with its side); it leaves the other edges along the layers' tops and bottoms sharp)\n",
            path, layers.sharp_hard_edges);
  if (layered && layers.radius_limited_by_fillet)
    fprintf(stderr, "homework45: %s: the radius goes up to %g only: the height of a layer whose foot is filleted "
            "or that filleted feet stand on, shared by its fillet and its rounded rims\n", path, layers.max_radius);
  if (layered) {
    block_min[0] = (float)layers.x[0], block_max[0] = (float)layers.x[layers.x_count - 1];
    block_min[1] = (float)layers.height[0], block_max[1] = (float)layers.height[layers.layer_count];
    block_min[2] = (float)layers.z[0], block_max[2] = (float)layers.z[layers.z_count - 1];
    return;
  }
  block_min[0] = (float)plan.min_x, block_max[0] = (float)plan.max_x;
  block_min[1] = (float)plan.bottom, block_max[1] = (float)plan.top;
  block_min[2] = (float)plan.min_z, block_max[2] = (float)plan.max_z;
  texture_height = has_cells && layers.layer_count > 1 ? 1.0f : block_max[1] - block_min[1];
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  load_object(argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(window_width, window_height);
  glutCreateWindow("Homework 4-5");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutSpecialFunc(special);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);

  glutCreateMenu(choose);
  glutAddMenuEntry("Walk mode (w)", MENU_WALK);
  glutAddMenuEntry("Examine mode (e)", MENU_EXAMINE);
  glutAddMenuEntry("Directional light (d)", MENU_DIRECTIONAL);
  glutAddMenuEntry("Point light (p)", MENU_POINT);
  glutAddMenuEntry("Spot light (s)", MENU_SPOT);
  glutAddMenuEntry("Orthographic/perspective (o)", MENU_PROJECTION);
  glutAddMenuEntry("Wider field of view (-)", MENU_WIDER);
  glutAddMenuEntry("Narrower field of view (+)", MENU_NARROWER);
  glutAddMenuEntry("Rounder edges (R)", MENU_ROUNDER);
  glutAddMenuEntry("Sharper edges (r)", MENU_SHARPER);
  glutAddMenuEntry("Viewpoint 1", MENU_VIEWPOINT_1);
  glutAddMenuEntry("Viewpoint 2", MENU_VIEWPOINT_1 + 1);
  glutAddMenuEntry("Viewpoint 3", MENU_VIEWPOINT_1 + 2);
  glutAddMenuEntry("Viewpoint 4", MENU_VIEWPOINT_1 + 3);
  glutAddMenuEntry("Viewpoint 5", MENU_VIEWPOINT_1 + 4);
  glutAttachMenu(GLUT_RIGHT_BUTTON);

  make_texture();
  set_viewpoint(0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_SMOOTH);
  glutMainLoop();
  return 0;
}
