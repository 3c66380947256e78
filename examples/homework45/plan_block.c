/* Drawing the object of one floor plan raised (wings_plan.h) with its marked edges rounded
 * (plan_block.h): quarter cylinders at the uprights, the rims' strips, the sphere and torus
 * pieces where they meet, mitres, caps and cut faces where a rounded rim meets a sharp one, the
 * flat walls, and the top and the bottom cut into triangles by GLU's tessellator. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <GL/glu.h>

#include "plan_block.h"
#include "rational_patch.h"
#include "rounded_upright.h"
#include "textured_grid.h"

#define PI 3.14159265358979323846
/* The steps a side's wall and its rim's strip are drawn in along the side; the outline of the top
 * and the bottom takes their points, so that no edge of theirs ends in the middle of one of its
 * (a T-junction, which leaves pixels uncovered along the seam). */
#define SIDE_STEPS 4

/* What draw_plan_block was given, for the functions below: the loop of the plan's outline being
 * drawn (its arrays are the caller's), the rounding radius, the height the sides' texture t runs
 * from 0 to 1 over, and the bottom's and the top's heights in single precision; and the texture's
 * s per unit of length walked round the loop (about 1, so that its length is whole repeats). */
static struct plan_loop plan;
static float radius, texture_height, block_bottom, block_top, s_per_length;

/* The rims: the top's (TOP) and the bottom's (BOTTOM), each with its height and the direction
 * out of the solid through it (+1 up, -1 down). */
enum rim_level { BOTTOM, TOP };
static double rim_height(enum rim_level level) { return level == TOP ? block_top : block_bottom; }
static double rim_outward(enum rim_level level) { return level == TOP ? 1.0 : -1.0; }

/* Whether the walls and uprights stop R short of the rim at `level` (index BOTTOM or TOP): some
 * side's rim there is rounded (its wall stops there). A sharp side's wall and a sharp corner's
 * upright then end in a band R high of their own, so that every wall's and upright's edges meet
 * at the same heights (and the caps, quarter moons and cut faces, R high, meet them without a
 * T-junction). */
static int level_split[2];

/* Where the walls' and uprights' grids end at `level`: R short of its rim, or at the rim. */
static double grid_end(enum rim_level level)
{
  return rim_height(level) - rim_outward(level) * (level_split[level] ? radius : 0.0);
}

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
static float side_t(double y) { return (float)((y - block_bottom) / texture_height); }

/* The texture's s along a rounded upright's quarter circle: its length, in s. */
static float upright_arc_s(void) { return (float)(PI / 2) * radius * s_per_length; }

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
                     rows, corner ? ARC_STEPS : SIDE_STEPS, corner, corner && turned, chart);
}

/* A quarter cylinder of the current radius around the upright edge at corner k, from the point
 * `from` on one side to `to` on the next, walked counter-clockwise seen from above so that
 * GL_AUTO_NORMAL's dP/du x dP/dv points out of the solid: between the grids' ends in SIDE_STEPS
 * steps, as the walls beside it, and on to a rim that is sharp on both sides of the corner where
 * the grids stop short of it, in one step, as the walls' bands (a rim rounded on either side has
 * its sphere or torus piece there). The texture s runs from s0 to s0 + the arc's length, so the
 * checkerboard continues from the face. */
static void rounded_edge(int k, const float from[2], const float corner[2], const float to[2], float s0)
{
  const float y0 = (float)grid_end(BOTTOM), y1 = (float)grid_end(TOP);
  quarter_cylinder(from, corner, to, y0, y1, s0, upright_arc_s(), side_t(y0), side_t(y1), SIDE_STEPS);
  for (int level = BOTTOM; level <= TOP; ++level) {
    if (!level_split[level] || corner_rounded(k, (enum rim_level)level)) continue;
    const float band_start = level == TOP ? y1 : block_bottom, band_end = level == TOP ? block_top : y0;
    quarter_cylinder(from, corner, to, band_start, band_end, s0, upright_arc_s(), side_t(band_start),
                     side_t(band_end), 1);
  }
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
 * the plane of the sharp side; where the outline goes straight on (plan.straight), R in from the
 * side when either side's rim is rounded, where the strips end, in the plane across the side. */
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
  double r_before = side_radius(k - 1, level), r_after = side_radius(k, level);
  if (plan.straight[k]) r_before = 0, r_after = fmax(r_after, side_radius(k - 1, level));
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

/* A vertex of a flat piece cut into triangles by GLU's tessellator: its point and its texture
 * coordinates. */
struct flat_vertex {
  GLdouble point[3], texture[2];
};

static int same_point(const GLdouble p[3], const GLdouble q[3]) { return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; }

static void GLAPIENTRY emit_flat_vertex(void *data)
{
  const struct flat_vertex *v = data;
  glTexCoord2d(v->texture[0], v->texture[1]);
  glVertex3dv(v->point);
}

/* A vertex of a flat piece of the sides at point p, with the sides' texture: s from s_origin at
 * `origin` (x, z) on along `s_direction` by the length walked (times s_per_length), t as on the
 * sides. */
static struct flat_vertex side_vertex(const double p[3], const double origin[2], float s_origin,
                                      const double s_direction[2])
{
  const float along = (float)((p[0] - origin[0]) * s_direction[0] + (p[2] - origin[1]) * s_direction[1]);
  const struct flat_vertex v = {{p[0], p[1], p[2]}, {s_origin + along * s_per_length, side_t(p[1])}};
  return v;
}

static void piece_vertex(const double p[3], const double e[2], float s_e, const double s_direction[2])
{
  struct flat_vertex v = side_vertex(p, e, s_e, s_direction);
  emit_flat_vertex(&v);
}

/* The point at u (0 to 1) of the quarter circle a rounded rim's strip ends in, in the vertical
 * plane through e and c (x, z, R apart): the rim's quarter circle around c R in from the rim's
 * height, from e R in (u = 0) to c at the rim (u = 1), the same rational quadratic as the strip's
 * patch (control points e R in, e at the rim weighted sqrt(2)/2, c at the rim), so that the flat
 * pieces along it share the strip's points. */
static void rim_end_arc_point(const double e[2], const double c[2], enum rim_level level, double u, double out[3])
{
  const double rim = rim_height(level), inner = rim - rim_outward(level) * radius, w = sqrt(2.0) / 2.0;
  const double b0 = (1 - u) * (1 - u), b1 = 2 * u * (1 - u) * w, b2 = u * u, sum = b0 + b1 + b2;
  out[0] = ((b0 + b1) * e[0] + b2 * c[0]) / sum;
  out[1] = (b0 * inner + (b1 + b2) * rim) / sum;
  out[2] = ((b0 + b1) * e[1] + b2 * c[1]) / sum;
}

/* A flat piece where a rounded rim's strip ends against a sharp edge, in the vertical plane
 * through e and c (rim_end_arc_point): the quarter moon between the strip's end and the square's
 * corner e at the rim, fanned from that corner. Its texture: t as on the sides, s from s_e at e
 * along `s_direction`. */
static void rim_end_piece(const double e[2], const double c[2], enum rim_level level, const double normal[2],
                          float s_e, const double s_direction[2])
{
  const double corner[3] = {e[0], rim_height(level), e[1]};
  glNormal3d(normal[0], 0, normal[1]);
  glBegin(GL_TRIANGLE_FAN);
  piece_vertex(corner, e, s_e, s_direction);
  for (int step = 0; step <= ARC_STEPS; ++step) {
    double p[3];
    rim_end_arc_point(e, c, level, (double)step / ARC_STEPS, p);
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
  const float length = upright_arc_s();
  const float t0 = side_t(top - out * r), t2 = (float)(t0 + out * PI / 2 * r / height);
  rim_corner_net(arc, axis, plan.convex[i], top - out * r, top, s0, length, t0, t2, net, tex, centre);
  const struct rim_chart chart = corner_rim_chart(axis, plan.convex[i] ? 0.0 : 2 * r, top - out * r, out, r);
  draw_rim_patch(net, tex, (const double (*)[3][3])centre, 3, level, &chart);
}

/* Whether contour `contour` of draw_flat_polygon's keeps its vertex k: not equal to the one
 * before it. */
static int keeps_vertex(const struct flat_vertex *contour, int count, int k)
{
  return !same_point(contour[k].point, contour[(k + count - 1) % count].point);
}

/* The flat polygon whose contours are the runs of counts[0], counts[1], ... vertices of
 * `vertices` (a point equal to the one before it left out; a contour with fewer than three
 * points left, such as a top shrunk to a point or a line, left out), which may be concave and
 * hold holes, cut into triangles by GLU's tessellator, facing along `normal`. */
static void draw_flat_polygon(struct flat_vertex *vertices, const int *counts, int contour_count, const float normal[3])
{
  static GLUtesselator *tess;
  if (!tess) {
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (void (GLAPIENTRY *)(void))glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (void (GLAPIENTRY *)(void))emit_flat_vertex);
    gluTessCallback(tess, GLU_TESS_END, (void (GLAPIENTRY *)(void))glEnd);
  }
  int drawn = 0;
  for (int c = 0, first = 0; c < contour_count; first += counts[c++]) {
    int distinct = 0;
    for (int k = 0; k < counts[c]; ++k) distinct += keeps_vertex(vertices + first, counts[c], k);
    if (distinct < 3) continue;
    if (!drawn) {
      gluTessNormal(tess, normal[0], normal[1], normal[2]);
      glNormal3fv(normal);
      gluTessBeginPolygon(tess, NULL);
      drawn = 1;
    }
    gluTessBeginContour(tess);
    for (int k = 0; k < counts[c]; ++k)
      if (keeps_vertex(vertices + first, counts[c], k)) gluTessVertex(tess, vertices[first + k].point, &vertices[first + k]);
    gluTessEndContour(tess);
  }
  if (drawn) gluTessEndPolygon(tess);
}

/* The outline of the top (or the bottom) at each level: with its rounded corners, R in from a
 * side whose rim is rounded and on the side's edge along a sharp one, SIDE_STEPS steps along
 * each side. Side i's points are point[side_first[i]] (where it leaves corner i) to
 * point[side_first[i] + SIDE_STEPS] (where it reaches corner i + 1; indices taken round). */
struct outline {
  double (*point)[2];
  int count, capacity, *side_first;
};
/* The outlines of every loop of the plan, at both levels, and those of the loop being drawn. */
static struct outline (*loop_outlines)[2];
static int loop_outline_capacity;
static struct outline *outlines;

/* Side i's point j (0 to SIDE_STEPS) of the outline at `level`. */
static const double *outline_side_point(enum rim_level level, int i, int j)
{
  const struct outline *o = &outlines[level];
  return o->point[(o->side_first[i] + j) % o->count];
}

/* The points trace_outline finds at the corners, before the sides' steps go in between. */
static double (*corner_points)[2];
static int corner_count, corner_capacity;

static void corner_point(double x, double z)
{
  if (corner_count == corner_capacity) exit(1);
  corner_points[corner_count][0] = x;
  corner_points[corner_count][1] = z;
  ++corner_count;
}

/* Traces the outline at `level` into outlines[level]: each corner's points (its upright's arc,
 * a mitre's top, a sphere's pole, a torus's inner rim, where a rounded strip ends), then the
 * side's steps to the next corner's first point. */
static void trace_outline(enum rim_level level)
{
  static int *first_of_corner;
  struct outline *o = &outlines[level];
  const int needed = plan.corners * (ARC_STEPS + 3 + SIDE_STEPS);
  if (corner_capacity < needed) {
    free(corner_points);
    free(first_of_corner);
    corner_points = malloc((size_t)needed * sizeof *corner_points);
    first_of_corner = malloc(((size_t)plan.corners + 1) * sizeof *first_of_corner);
    if (!corner_points || !first_of_corner) exit(1);
    corner_capacity = needed;
  }
  if (o->capacity < needed) {
    free(o->point);
    free(o->side_first);
    o->point = malloc((size_t)needed * sizeof *o->point);
    o->side_first = malloc((size_t)plan.corners * sizeof *o->side_first);
    if (!o->point || !o->side_first) exit(1);
    o->capacity = needed;
  }
  corner_count = 0;
  for (int i = 0; i < plan.corners; ++i) {
    first_of_corner[i] = corner_count;
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
        corner_point(arc[0], arc[1]);
      }
      continue;
    }
    double at[2];
    rim_top_corner(i, level, at);
    if (!upright) {
      /* The mitre's top, or where the one rounded strip ends in the sharp side's plane; at a
       * concave corner that end's cap reaches from the corner to it. */
      if (!plan.convex[i] && after && !before) corner_point(corner[0], corner[1]);
      corner_point(at[0], at[1]);
      if (!plan.convex[i] && before && !after) corner_point(corner[0], corner[1]);
      continue;
    }
    /* Above a rounded upright: a sharp side's edge runs on to where the upright's arc begins (or
     * ends), and the cap of the sphere or torus piece's end from there. */
    if (!before) corner_point(from[0], from[1]);
    if (plan.convex[i]) {
      /* The sphere's pole. */
      corner_point(at[0], at[1]);
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
        corner_point(arc[0], arc[1]);
      }
    }
    if (!after) corner_point(to[0], to[1]);
  }
  first_of_corner[plan.corners] = corner_count;
  o->count = 0;
  for (int i = 0; i < plan.corners; ++i) {
    for (int k = first_of_corner[i]; k < first_of_corner[i + 1]; ++k) {
      o->point[o->count][0] = corner_points[k][0];
      o->point[o->count][1] = corner_points[k][1];
      ++o->count;
    }
    o->side_first[i] = o->count - 1;
    const double *a = corner_points[first_of_corner[i + 1] - 1];
    const double *b = corner_points[first_of_corner[(i + 1) % plan.corners]];
    for (int step = 1; step < SIDE_STEPS; ++step) {
      const double f = (double)step / SIDE_STEPS;
      o->point[o->count][0] = a[0] + f * (b[0] - a[0]);
      o->point[o->count][1] = a[1] + f * (b[1] - a[1]);
      ++o->count;
    }
  }
}

/* The top or the bottom: the outlines of the plan's `loop_count` loops (trace_outline), which may
 * be concave and hold holes, cut into triangles, facing up or down, with the texture's (x, z). */
static void block_end(enum rim_level level, int loop_count)
{
  static struct flat_vertex *vertices;
  static int *counts;
  static int capacity, count_capacity;
  int total = 0;
  for (int l = 0; l < loop_count; ++l) total += loop_outlines[l][level].count;
  if (capacity < total) {
    free(vertices);
    vertices = malloc((size_t)total * sizeof *vertices);
    if (!vertices) exit(1);
    capacity = total;
  }
  if (count_capacity < loop_count) {
    free(counts);
    counts = malloc((size_t)loop_count * sizeof *counts);
    if (!counts) exit(1);
    count_capacity = loop_count;
  }
  int n = 0;
  for (int l = 0; l < loop_count; ++l) {
    const struct outline *o = &loop_outlines[l][level];
    counts[l] = o->count;
    for (int k = 0; k < o->count; ++k) {
      const struct flat_vertex v = {{o->point[k][0], rim_height(level), o->point[k][1]}, {o->point[k][0], o->point[k][1]}};
      vertices[n++] = v;
    }
  }
  const float normal[3] = {0, (float)rim_outward(level), 0};
  draw_flat_polygon(vertices, counts, loop_count, normal);
}

/* At corner k, where the rim at `level` is rounded on one side of it or on both: above a rounded
 * upright the sphere or torus piece, and where one side's rim is sharp a flat cap ending it, in
 * the plane normal to that side through the upright's arc's end (the torus or sphere is kept
 * whole and steps down to the sharp edge, as the library's rounding does); above a sharp concave
 * corner with one side rounded, the quarter moon that ends that side's strip, in the sharp side's
 * plane past the corner; where the outline goes straight on from a rounded stretch of the rim to
 * a sharp one, the quarter moon across the side that ends the strip, facing it. (Above a sharp
 * convex corner the sharp side's face is cut instead: side_face.) s is the texture's s where the
 * corner's arc begins. */
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
    rim_end_piece(e, c, level, normal, after ? s : s + upright_arc_s(), direction);
    return;
  }
  if (plan.convex[k] || (before && after)) return;
  const int sharp = after ? (k + n - 1) % n : k, rounded = after ? k : (k + n - 1) % n;
  double in_rounded[2], in_sharp[2], direction[2], c[2];
  inward(rounded, in_rounded);
  inward(sharp, in_sharp);
  along_side(sharp, direction);
  for (int m = 0; m < 2; ++m) c[m] = plan.xz[k][m] + radius * in_rounded[m];
  double normal[2] = {-in_sharp[0], -in_sharp[1]};
  if (plan.straight[k]) {
    /* Across the side: facing the rounded stretch, s running in from the side's edge. */
    along_side(rounded, normal);
    if (!after) normal[0] = -normal[0], normal[1] = -normal[1];
    direction[0] = in_rounded[0], direction[1] = in_rounded[1];
  }
  rim_end_piece(plan.xz[k], c, level, normal, s, direction);
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

/* The band of side i's face between its grid's end and its sharp rim at `level` (where the
 * grids stop R short of the rim): one flat polygon through the grid's points along its edge,
 * from `start` to `end`, up the quarter circle a rounded neighbour's strip ends in where the side
 * is cut at its end, back along the outline's points of the side at the rim, and down that
 * quarter circle where it is cut at its start, so that it shares every point with the grid
 * below, the strips, the uprights' bands and the top (bottom). */
static void wall_band(int i, enum rim_level level, const float start[2], const float end[2], float s0,
                      const float normal[3])
{
  struct flat_vertex v[2 * (SIDE_STEPS + 1) + 2 * ARC_STEPS];
  int n = 0;
  const double edge = grid_end(level), rim = rim_height(level), origin[2] = {start[0], start[1]};
  double direction[2];
  along_side(i, direction);
  for (int j = 0; j <= SIDE_STEPS; ++j) {
    const float f = (float)j / (float)SIDE_STEPS;
    const double p[3] = {start[0] + f * (end[0] - start[0]), edge, start[1] + f * (end[1] - start[1])};
    v[n++] = side_vertex(p, origin, s0, direction);
  }
  double cut_arc[2][2][2]; /* at each end: the arc's e and c (rim_end_arc_point) */
  for (int at = 0; at < 2; ++at) {
    const int k = (i + at) % plan.corners;
    double in_other[2];
    inward(at ? (i + 1) % plan.corners : (i + plan.corners - 1) % plan.corners, in_other);
    for (int m = 0; m < 2; ++m) {
      cut_arc[at][0][m] = plan.xz[k][m];
      cut_arc[at][1][m] = plan.xz[k][m] + radius * in_other[m];
    }
  }
  if (side_cut(i, 1, level))
    for (int step = 1; step < ARC_STEPS; ++step) {
      double p[3];
      rim_end_arc_point(cut_arc[1][0], cut_arc[1][1], level, (double)step / ARC_STEPS, p);
      v[n++] = side_vertex(p, origin, s0, direction);
    }
  for (int j = SIDE_STEPS; j >= 0; --j) {
    const double *q = outline_side_point(level, i, j);
    const double p[3] = {q[0], rim, q[1]};
    v[n++] = side_vertex(p, origin, s0, direction);
  }
  if (side_cut(i, 0, level))
    for (int step = ARC_STEPS - 1; step > 0; --step) {
      double p[3];
      rim_end_arc_point(cut_arc[0][0], cut_arc[0][1], level, (double)step / ARC_STEPS, p);
      v[n++] = side_vertex(p, origin, s0, direction);
    }
  draw_flat_polygon(v, &n, 1, normal);
}

/* The flat face of side i from `start` to `end` (x, z), with the texture's s from s0 to s1 along
 * it; outwards is to the right of the walk. A grid between the grids' ends (grid_end), and above
 * (below) it to a sharp rim where the grids stop short of the rim, a band (wall_band). */
static void side_face(int i, const float start[2], const float end[2], float s0, float s1)
{
  const float along[3] = {end[0] - start[0], 0, end[1] - start[1]};
  const float length = sqrtf(along[0] * along[0] + along[2] * along[2]);
  if (length <= 0) return;
  const float normal[3] = {-along[2] / length, 0, along[0] / length};
  const double low = grid_end(BOTTOM), high = grid_end(TOP);
  const float base[3] = {start[0], (float)low, start[1]}, up[3] = {0, (float)(high - low), 0};
  textured_grid(base, along, up, normal, SIDE_STEPS, s0, s1, side_t(low), side_t(high));
  for (int level = BOTTOM; level <= TOP; ++level)
    if (level_split[level] && !side_rounded(i, (enum rim_level)level))
      wall_band(i, (enum rim_level)level, start, end, s0, normal);
}

/* The length of side i's flat face: from where it leaves corner i to where it reaches corner
 * i + 1 (corner_ends). */
static float side_length(int i)
{
  float from[2], to[2], next_from[2], next_to[2];
  corner_ends(i, from, to);
  corner_ends((i + 1) % plan.corners, next_from, next_to);
  return hypotf(next_from[0] - to[0], next_from[1] - to[1]);
}

/* The length of the walk round the loop at the current radius: the sides between the uprights'
 * quarter circles, and those. */
static float outline_length(void)
{
  float length = 0;
  for (int i = 0; i < plan.corners; ++i) {
    if (plan.rounded[i] && radius > 0) length += (float)(PI / 2) * radius;
    length += side_length(i);
  }
  return length;
}

/* The walls, uprights, rims' strips and corner pieces of the loop `plan`, and its outlines for the
 * top and the bottom: in order round it, so that the texture's s is the length walked round it
 * (times s_per_length, which makes the walk whole repeats of s_repeat). */
static void draw_loop(float s_repeat)
{
  const float walked = outline_length();
  s_per_length = fmaxf(1.0f, roundf(walked / s_repeat)) * s_repeat / walked;
  for (int level = BOTTOM; level <= TOP; ++level) {
    level_split[level] = 0;
    for (int i = 0; i < plan.corners; ++i) level_split[level] |= side_rounded(i, (enum rim_level)level);
    trace_outline((enum rim_level)level);
  }
  float s = 0;
  for (int i = 0; i < plan.corners; ++i) {
    float from[2], to[2], next_from[2], next_to[2];
    float corner[2] = {(float)plan.xz[i][0], (float)plan.xz[i][1]};
    corner_ends(i, from, to);
    corner_ends((i + 1) % plan.corners, next_from, next_to);
    if (plan.rounded[i] && radius > 0) rounded_edge(i, from, corner, to, s);
    corner_pieces(i, TOP, s);
    corner_pieces(i, BOTTOM, s);
    if (plan.rounded[i] && radius > 0) s += upright_arc_s();
    /* The side from this corner to the next. */
    const float length = side_length(i) * s_per_length;
    side_face(i, to, next_from, s, s + length);
    if (side_rounded(i, TOP)) rim_strip(i, TOP, s, s + length);
    if (side_rounded(i, BOTTOM)) rim_strip(i, BOTTOM, s, s + length);
    s += length;
  }
}

void draw_plan_block(const struct floor_plan *object, float rounding_radius, float texture_rise, float s_repeat)
{
  radius = rounding_radius;
  texture_height = texture_rise;
  block_bottom = (float)object->bottom;
  block_top = (float)object->top;
  if (loop_outline_capacity < object->loop_count) {
    loop_outlines = realloc(loop_outlines, (size_t)object->loop_count * sizeof *loop_outlines);
    if (!loop_outlines) exit(1);
    memset(loop_outlines + loop_outline_capacity, 0,
           (size_t)(object->loop_count - loop_outline_capacity) * sizeof *loop_outlines);
    loop_outline_capacity = object->loop_count;
  }
  for (int l = 0; l < object->loop_count; ++l) {
    plan = object->loops[l];
    outlines = loop_outlines[l];
    draw_loop(s_repeat);
  }
  block_end(TOP, object->loop_count);
  block_end(BOTTOM, object->loop_count);
}
