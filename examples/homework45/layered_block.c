/* The object of several layers of cubes, drawn as the solid each layer makes with its rounded
 * uprights: over its footprint with every rounded corner's quarter square cut by the quarter arc
 * (the arc's convex side in at a convex corner; a fillet, the arc's concave side, filling the
 * empty quarter at a concave one), straight up from one height to the next. Stacked, the layers
 * make a closed solid: its walls are the layers' walls and quarter cylinders, and at each height
 * the flat face is what the layer below covers and the layer above does not (facing up), or the
 * other way round (facing down).
 *
 * Every flat face is cut along the grid lines and R in from them into rectangles, and a corner's
 * R x R square is either whole, the quarter disk inside its arc, the piece between the arc and
 * the corner, or nothing: on every line every piece, wall and cylinder has its vertices at the
 * same points (the grid lines, R in from them, the arcs' ARC_STEPS points, four rows per layer up
 * the walls and the cylinders), so the surface has no T-junctions and no cracks. The arcs' squares
 * keep apart, as R is at most half the closest spacing of the grid lines.
 *
 * The top (bottom) rim of a capped piece (cube_layers.h) is rounded: its walls and uprights stop
 * R below the top (above the bottom), a rim strip runs along each wall cut at the wall's columns,
 * an eighth of a sphere joins two strips and the upright at each rounded convex corner, a quarter
 * of a torus at each concave one, the strips meet in a mitre at a sharp convex corner, and the
 * flat face loses its bands along the rim and, round each torus piece, what the torus covers; so
 * the pieces still share their vertices. In the same way a filleted foot (cube_layers.h) has its
 * walls and uprights start R above the foot, a fillet along each wall inside the top below, a
 * torus or horn piece at each corner between two of them, and the top below loses what they
 * cover; where a fillet ends at a side flush with the layer below (a standing corner), a quarter
 * of a torus joins it to the upright above and to the lower layer's top rim, which runs on along
 * the flush side, and the flush plane keeps what lies outside it. Walls and uprights have their
 * rows at the same heights in each layer (layer_rows), so that they meet those flat pieces and
 * one another vertex for vertex whichever of them stop R short of the top or the bottom. */
#include "layered_block.h"

#include "rational_patch.h"
#include "rounded_upright.h"

#include <math.h>
#include <GL/glut.h>

#define PI 3.14159265358979323846
/* Rows up each layer's walls and cylinders, as on the one-layer object. */
#define ROWS 4
/* The length of s in which homework45.c's checkerboard repeats: two squares of 8 of its 64
 * texels. */
#define CHECKER_PERIOD 0.25

/* The parts of a corner's R x R square a layer covers: the piece between the arc and the corner,
 * the quarter disk inside the arc, both (the whole square) or neither. */
enum { CORNER_PIECE = 1, QUARTER_DISK = 2, WHOLE_SQUARE = 3 };

/* The texture's t on the walls: the height above the object's bottom, in the units of s (a
 * one-layer object's sides run t from 0 to 1 over their height: the same for cubes of unit
 * size), so the checkerboard stays square however the object is cut into layers. */
static float texture_t(const struct cube_layers *layers, double y) { return (float)(y - layers->height[0]); }

/* The texture's s on a wall facing (normal_x, normal_z): the length along it in the direction of
 * a walk that keeps the solid on the left, as on the one-layer object's sides. */
static float wall_s(double x, double z, int normal_x, int normal_z) { return (float)(x * normal_z - z * normal_x); }

/* Whether the upright at grid point (i, j) of `layer` is rounded at this radius. */
static int upright_rounded(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  return radius > 0 && cube_layers_rounded(layers, layer, i, j);
}

/* Whether cell (i, j) of `layer` has its top (rim CAPPED_TOP) or bottom rim (CAPPED_BOTTOM)
 * rounded, or its foot filleted (FILLETED_FOOT), at this radius: a capped piece's (cube_layers.h),
 * when the radius leaves room for its rims in the layer's height (R for each, compared in single
 * precision, in which the radius is kept): the rims may take the whole height (cube_layers.c
 * bounds the radius by it; at the largest radius the walls between them are left out), so that
 * a rim that a fillet ends against is rounded whenever the fillet is. */
static int rim_rounded(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  const int capped = cube_layers_capped(layers, layer, i, j);
  if (radius <= 0 || !(capped & rim)) return 0;
  const int rims = !!(capped & CAPPED_TOP) + !!(capped & CAPPED_BOTTOM) + !!(capped & FILLETED_FOOT);
  return radius * (float)rims <= (float)(layers->height[layer + 1] - layers->height[layer]);
}

/* Whether the rim `rim` of cell (i, j) of `layer` is rounded along the cell's open sides: as
 * rim_rounded, but a top rim under a cell of the layer above is no rim (the wall above runs on
 * down there). */
static int rim_shown(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  return rim_rounded(layers, layer, i, j, radius, rim) &&
         !(rim == CAPPED_TOP && cube_layers_filled(layers, layer + 1, i, j));
}

/* How many of the four cells around grid point (i, j) `layer` fills. */
static int cells_around(const struct cube_layers *layers, int layer, int i, int j)
{
  int around = 0;
  for (int di = -1; di <= 0; ++di)
    for (int dj = -1; dj <= 0; ++dj) around += cube_layers_filled(layers, layer, i + di, j + dj);
  return around;
}

/* Whether the top (rim CAPPED_TOP) or bottom rim of `layer` is rounded at the corner at grid point
 * (i, j) (or its foot filleted, FILLETED_FOOT): the rim of the piece of the footprint that the
 * cells around it in the solid belong to (one piece, since cubes meeting only along an upright
 * line are refused), where no cell of the layer above stands on them (for a top rim). */
static int corner_rim_rounded(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  for (int di = -1; di <= 0; ++di)
    for (int dj = -1; dj <= 0; ++dj)
      if (cube_layers_filled(layers, layer, i + di, j + dj)) return rim_shown(layers, layer, i + di, j + dj, radius, rim);
  return 0;
}

/* Whether the foot of `layer`'s convex corner at grid point (i, j) is filleted and stands on the
 * layer below with one side flush with that layer's side (the layer below fills two of the cells
 * around the point): the fillet along the other side ends there against the lower layer's
 * rounded top rim, in a piece of torus (standing_corner). */
static int standing_corner_at(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  return cells_around(layers, layer, i, j) == 1 && cells_around(layers, layer - 1, i, j) == 2 &&
         upright_rounded(layers, layer, i, j, radius) && corner_rim_rounded(layers, layer, i, j, radius, FILLETED_FOOT);
}

/* The heights of the rows of `layer`'s walls and upright cylinders from y0 to y1 (each the
 * layer's bottom or R above it, its top or R below it): R above the bottom, four rows between
 * that and R below the top, and R below the top, so that walls and cylinders of one layer,
 * whichever of them stop short of the top or the bottom, have their vertices at the same heights
 * where they meet, also round a standing corner's flat pieces. Returns how many. */
static int layer_rows(const struct cube_layers *layers, int layer, float radius, double y0, double y1, float rows[ROWS + 3])
{
  const double bottom = layers->height[layer], top = layers->height[layer + 1];
  const double low = radius > 0 ? (double)((float)bottom + radius) : bottom;
  const double high = radius > 0 ? (double)((float)top - radius) : top;
  const double a = fmin(low, high), b = fmax(low, high);
  double heights[ROWS + 3];
  heights[0] = bottom;
  for (int row = 0; row <= ROWS; ++row) heights[1 + row] = a + (b - a) * row / ROWS;
  heights[ROWS + 2] = top;
  int count = 0;
  for (int h = 0; h < ROWS + 3; ++h)
    if (heights[h] >= y0 && heights[h] <= y1 && (count == 0 || (float)heights[h] > rows[count - 1]))
      rows[count++] = (float)heights[h];
  return count;
}

/* How far above the bottom of cell (i, j) of `layer` its wall towards cell (oi, oj) starts: R over
 * a rounded bottom rim or a fillet (which runs where the layer below fills the cell across the
 * wall; a wall flush with the layer below runs on down). */
static float foot_rise(const struct cube_layers *layers, int layer, int i, int j, int oi, int oj, float radius)
{
  return rim_rounded(layers, layer, i, j, radius, CAPPED_BOTTOM) ||
                 (rim_rounded(layers, layer, i, j, radius, FILLETED_FOOT) && cube_layers_filled(layers, layer - 1, oi, oj))
             ? radius
             : 0;
}

/* The columns of a wall from grid value a to b, and of the strips along it: a and b where `keep_a`
 * (`keep_b`) and, for a radius, a + R and b - R. Returns how many. */
static int wall_columns(float a, float b, int keep_a, int keep_b, float radius, float columns[4])
{
  int count = 0;
  const float candidates[4] = {a, a + radius, b - radius, b};
  const int wanted[4] = {keep_a, radius > 0, radius > 0, keep_b};
  for (int c = 0; c < 4; ++c)
    if (wanted[c] && (count == 0 || candidates[c] > columns[count - 1])) columns[count++] = candidates[c];
  return count;
}

/* The wall of `layer` along grid line `fixed` (x = fixed for along_x 0, else z = fixed), from
 * grid value a to b > a, facing (normal_x, normal_z): R shorter at an end where the upright is
 * rounded, with columns at a, a + R, b - R and b, rows by layer_rows. Its top R x R square at an
 * end `cut_a` (`cut_b`) is left out: there the flat pieces round a standing corner's torus
 * piece take over. */
static void wall(const struct cube_layers *layers, int layer, int along_x, float fixed, float a, float b,
                 int rounded_a, int rounded_b, int cut_a, int cut_b, int normal_x, int normal_z, float radius,
                 float drop, float rise)
{
  float columns[4], rows[ROWS + 3];
  const int count = wall_columns(a, b, !rounded_a, !rounded_b, radius, columns);
  const double y0 = rise > 0 ? (double)((float)layers->height[layer] + rise) : layers->height[layer];
  const double y1 = drop > 0 ? (double)((float)layers->height[layer + 1] - drop) : layers->height[layer + 1];
  const int row_count = layer_rows(layers, layer, radius, y0, y1, rows);
  const float cut_from = (float)layers->height[layer + 1] - radius;
  glNormal3f((float)normal_x, 0, (float)normal_z);
  for (int row = 0; row + 1 < row_count; ++row) {
    const int first = cut_a && rows[row] >= cut_from ? 1 : 0, last = cut_b && rows[row] >= cut_from ? count - 2 : count - 1;
    glBegin(GL_QUAD_STRIP);
    for (int c = first; c <= last; ++c)
      for (int k = 1; k >= 0; --k) {
        const float y = rows[row + k];
        const float x = along_x ? columns[c] : fixed, z = along_x ? fixed : columns[c];
        glTexCoord2f(wall_s(x, z, normal_x, normal_z), texture_t(layers, y));
        glVertex3f(x, y, z);
      }
    glEnd();
  }
}

/* The walls of `layer`: along every grid segment with the solid on one side only (the cell
 * (ci, cj) inside, (oi, oj) outside), from grid point (i, j) to (i + along_x, j + !along_x). Under a
 * cell of the layer above, the wall runs on up into that layer's flush wall and gives up its top
 * square at a standing corner of that layer. */
static void wall_of_segment(const struct cube_layers *layers, int layer, int along_x, int i, int j, int ci, int cj,
                            int oi, int oj, float radius)
{
  const int i1 = i + along_x, j1 = j + !along_x, under = cube_layers_filled(layers, layer + 1, ci, cj);
  wall(layers, layer, along_x, (float)(along_x ? layers->z[j] : layers->x[i]),
       (float)(along_x ? layers->x[i] : layers->z[j]), (float)(along_x ? layers->x[i1] : layers->z[j1]),
       upright_rounded(layers, layer, i, j, radius), upright_rounded(layers, layer, i1, j1, radius),
       under && standing_corner_at(layers, layer + 1, i, j, radius),
       under && standing_corner_at(layers, layer + 1, i1, j1, radius), along_x ? 0 : ci < oi ? 1 : -1,
       along_x ? (cj < oj ? 1 : -1) : 0, radius, rim_shown(layers, layer, ci, cj, radius, CAPPED_TOP) ? radius : 0,
       foot_rise(layers, layer, ci, cj, oi, oj, radius));
}

static void walls(const struct cube_layers *layers, int layer, float radius)
{
  for (int i = 0; i < layers->x_count; ++i)
    for (int j = 0; j + 1 < layers->z_count; ++j) {
      const int before = cube_layers_filled(layers, layer, i - 1, j), after = cube_layers_filled(layers, layer, i, j);
      if (before != after)
        wall_of_segment(layers, layer, 0, i, j, before ? i - 1 : i, j, before ? i : i - 1, j, radius);
    }
  for (int j = 0; j < layers->z_count; ++j)
    for (int i = 0; i + 1 < layers->x_count; ++i) {
      const int before = cube_layers_filled(layers, layer, i, j - 1), after = cube_layers_filled(layers, layer, i, j);
      if (before != after)
        wall_of_segment(layers, layer, 1, i, j, i, before ? j - 1 : j, i, before ? j : j - 1, radius);
    }
}

/* The length over which the texture's s runs across a corner piece of length `arc` from s0 to
 * reach s1 but for whole repeats of the checkerboard: arc stretched by less than a repeat. */
static float s_across(float s0, float s1, float arc)
{
  const double short_of = (double)s1 - s0 - arc;
  return arc + (float)(short_of - CHECKER_PERIOD * floor(short_of / CHECKER_PERIOD));
}

/* The arc of the rounded upright at grid point (i, j) of `layer`. Of the four cells around it one
 * differs from the others (the only one in the solid at a convex corner, the only one out of it
 * at a concave one), in direction (qx, qz) from the point; the walls run from the point along x
 * and along z on its sides. The arc goes from R along the wall the walk arrives by to R along the
 * wall it leaves by, the solid on the walk's left. Its texture's s runs from *s0 over *s_length.
 * Returns whether the corner is convex. */
static int upright_arc(const struct cube_layers *layers, int layer, int i, int j, float radius, float from[2],
                       float corner[2], float to[2], float *s0, float *s_length)
{
  int filled = 0, qx = 0, qz = 0;
  for (int di = -1; di <= 0; ++di)
    for (int dj = -1; dj <= 0; ++dj) filled += cube_layers_filled(layers, layer, i + di, j + dj);
  const int convex = filled == 1;
  for (int di = -1; di <= 0; ++di)
    for (int dj = -1; dj <= 0; ++dj)
      if (cube_layers_filled(layers, layer, i + di, j + dj) == convex)
        qx = di ? -1 : 1, qz = dj ? -1 : 1;
  const int sign = convex ? 1 : -1;
  /* The wall along x faces (0, -qz sign) and the walk runs along it by (-qz sign, 0): away from
   * the point, it leaves by that wall, when that is (qx, 0). The wall along z faces (-qx sign, 0). */
  const int leaves_along_x = -qz * sign == qx;
  corner[0] = (float)layers->x[i];
  corner[1] = (float)layers->z[j];
  const float along_x[2] = {corner[0] + (float)qx * radius, corner[1]};
  const float along_z[2] = {corner[0], corner[1] + (float)qz * radius};
  for (int k = 0; k < 2; ++k) {
    from[k] = leaves_along_x ? along_z[k] : along_x[k];
    to[k] = leaves_along_x ? along_x[k] : along_z[k];
  }
  /* The texture's s runs on from the wall the walk arrives by and, stretched by less than a
   * quarter of the texture, reaches the next wall's s but for whole quarters: the checkerboard
   * (squares of 8 of its 64 texels) repeats every quarter, so it runs on across both seams. */
  *s0 = leaves_along_x ? wall_s(from[0], from[1], -qx * sign, 0) : wall_s(from[0], from[1], 0, -qz * sign);
  const float s1 = leaves_along_x ? wall_s(to[0], to[1], 0, -qz * sign) : wall_s(to[0], to[1], -qx * sign, 0);
  *s_length = s_across(*s0, s1, (float)(PI / 2.0) * radius);
  return convex;
}

/* The quarter cylinder of the rounded upright at grid point (i, j) of `layer`, R short of the
 * layer's top and bottom where they are rounded rims. */
static void upright_cylinder(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  float from[2], corner[2], to[2], s0, s_length;
  upright_arc(layers, layer, i, j, radius, from, corner, to, &s0, &s_length);
  const float drop = corner_rim_rounded(layers, layer, i, j, radius, CAPPED_TOP) ? radius : 0;
  /* A fillet ends at the upright's foot unless both its walls are flush with the layer below. */
  const float rise = corner_rim_rounded(layers, layer, i, j, radius, CAPPED_BOTTOM) ||
                             (corner_rim_rounded(layers, layer, i, j, radius, FILLETED_FOOT) &&
                              cells_around(layers, layer - 1, i, j) >= 2)
                         ? radius
                         : 0;
  const double y0 = rise > 0 ? (double)((float)layers->height[layer] + rise) : layers->height[layer];
  const double y1 = drop > 0 ? (double)((float)layers->height[layer + 1] - drop) : layers->height[layer + 1];
  float rows[ROWS + 3];
  const int row_count = layer_rows(layers, layer, radius, y0, y1, rows);
  for (int row = 0; row + 1 < row_count; ++row)
    quarter_cylinder(from, corner, to, rows[row], rows[row + 1], s0, s_length, texture_t(layers, rows[row]),
                     texture_t(layers, rows[row + 1]), 1);
}

/* How a rim's strip or a fillet ends at a grid point along its wall: at a rounded upright, where
 * the corner's piece of sphere or torus takes over R before the point; at a standing corner
 * (standing_corner_at), where the torus piece between a fillet and the rim it ends against takes
 * over R before the point; at a sharp convex corner, in the corner's diagonal plane, where the
 * next wall's strip ends too (a mitre, as on the one-layer object); or running on along the wall. */
enum strip_end { ENDS_AT_CORNER_PIECE, ENDS_AT_STANDING_CORNER, ENDS_IN_MITRE, RUNS_ON };

static enum strip_end strip_end_at(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  if ((rim == CAPPED_TOP && standing_corner_at(layers, layer + 1, i, j, radius)) ||
      (rim == FILLETED_FOOT && standing_corner_at(layers, layer, i, j, radius)))
    return ENDS_AT_STANDING_CORNER;
  if (upright_rounded(layers, layer, i, j, radius)) return ENDS_AT_CORNER_PIECE;
  /* A rim's strips meet in a mitre at a sharp convex corner, a fillet's at a sharp concave one
   * (round a sharp convex one the horn piece takes over at the corner). */
  return cells_around(layers, layer, i, j) == (rim == FILLETED_FOOT ? 3 : 1) ? ENDS_IN_MITRE : RUNS_ON;
}

/* Draws a rim's or a fillet's patch (a strip, rows 2, or a corner's piece, rows 3, as
 * begin_net_parts takes it, its quarter circle from the wall to the top) in its two halves
 * (draw_net_in_halves): the wall's with the texture net tex, whose t runs on from the wall over
 * the whole quarter circle, the top's (the top below, for a fillet) with `chart`, so that the
 * checkerboard crosses from either face onto the piece without a jump. */
static void draw_rim_piece(const float net[][3][4], const float tex[][3][2], const double centre[][3][3], int rows,
                           int fillet, const struct rim_chart *chart)
{
  draw_net_in_halves(net, tex, centre, fillet ? -1.0f : 1.0f, rows, rows == 3 ? ARC_STEPS : 1, rows == 3, 0, chart);
}

/* Whether a strip keeps the column at its end (not where a corner's piece takes over). */
static int keeps_end_column(enum strip_end end) { return end != ENDS_AT_CORNER_PIECE && end != ENDS_AT_STANDING_CORNER; }

/* The outward normals (x, z) of the walls meeting at the standing corner at grid point (i, j) of
 * `layer`: n_w of the one with the fillet at its foot, n_f of the one flush with the layer below. */
static void standing_corner_walls(const struct cube_layers *layers, int layer, int i, int j, int n_w[2], int n_f[2])
{
  int qx = 0, qz = 0;
  for (int di = -1; di <= 0; ++di)
    for (int dj = -1; dj <= 0; ++dj)
      if (cube_layers_filled(layers, layer, i + di, j + dj)) qx = di ? -1 : 1, qz = dj ? -1 : 1;
  /* The layer below runs on past the wall x = corner (facing -qx) or past z = corner (facing -qz). */
  const int past_x = cube_layers_filled(layers, layer - 1, qx > 0 ? i - 1 : i, qz > 0 ? j : j - 1);
  n_w[0] = past_x ? -qx : 0, n_w[1] = past_x ? 0 : -qz;
  n_f[0] = past_x ? 0 : -qx, n_f[1] = past_x ? -qz : 0;
}

/* The rounded top (rim CAPPED_TOP) or bottom rim of `layer` along its wall on grid line `fixed`
 * (x = fixed for along_x 0, else z = fixed) from a to b, facing (normal_x, normal_z): a quarter
 * cylinder along the wall, its axis R in from the wall and R below the top (above the bottom),
 * cut at the wall's columns (a, a + R, b - R, b, the ends at a rounded upright left out, where the
 * sphere's eighth takes over), so that it meets the wall's top (bottom) row and the flat face's
 * bands at their vertices. At a mitred end the end's profile keeps its points on the wall and
 * the rim's edge, and its inner end moves R along the wall, onto the corner's diagonal plane, so
 * that the strip ends in the ellipse the next wall's strip ends in; its normals stay the
 * cylinder's (each control point's centre is its own projection onto the strip's axis). The
 * texture's s is the wall's; t runs on from the wall's top (bottom) by the arc's length. */
static void rim_strip(const struct cube_layers *layers, int layer, int along_x, float fixed, float a, float b,
                      enum strip_end end_a, enum strip_end end_b, int normal_x, int normal_z, float radius, int rim)
{
  const double w = sqrt(2.0) / 2.0;
  float columns[4];
  const int count = wall_columns(a, b, keeps_end_column(end_a), keeps_end_column(end_b), radius, columns);
  const float out = rim == CAPPED_TOP ? 1.0f : -1.0f;
  const float top = (float)layers->height[rim == CAPPED_TOP ? layer + 1 : layer], below = top - out * radius;
  const float t0 = texture_t(layers, below), t2 = t0 + out * (float)((PI / 2.0) * radius);
  const int in_x = -normal_x, in_z = -normal_z;
  const double axis[2] = {along_x ? a : fixed + (float)in_x * radius, along_x ? fixed + (float)in_z * radius : a};
  const double outward[2] = {normal_x, normal_z};
  const struct rim_chart chart = strip_rim_chart(axis, outward, below, out, radius);
  for (int c = 0; c + 1 < count; ++c) {
    float net[2][3][4], tex[2][3][2];
    double centre[2][3][3];
    for (int v = 0; v < 2; ++v) {
      const float x = along_x ? columns[c + v] : fixed, z = along_x ? fixed : columns[c + v];
      const float mitre = c + v == 0 && end_a == ENDS_IN_MITRE            ? radius
                          : c + v == count - 1 && end_b == ENDS_IN_MITRE ? -radius
                                                                          : 0.0f;
      const float inner_x = x + (float)in_x * radius + (along_x ? mitre : 0.0f);
      const float inner_z = z + (float)in_z * radius + (along_x ? 0.0f : mitre);
      control_point(net[v][0], x, below, z, 1.0);
      control_point(net[v][1], x, top, z, w);
      control_point(net[v][2], inner_x, top, inner_z, 1.0);
      strip_column_texture(tex[v], wall_s(x, z, normal_x, normal_z), t0, t2);
      for (int u = 0; u < 3; ++u) {
        centre[v][u][0] = along_x && u == 2 ? inner_x : x + (float)in_x * radius;
        centre[v][u][1] = below;
        centre[v][u][2] = !along_x && u == 2 ? inner_z : z + (float)in_z * radius;
      }
    }
    draw_rim_piece((const float (*)[3][4])net, (const float (*)[3][2])tex, (const double (*)[3][3])centre, 2, 0,
                   &chart);
  }
}

/* The fillet along the foot of `layer`'s wall on grid line `fixed` (x = fixed for along_x 0, else
 * z = fixed) from a to b, facing (normal_x, normal_z), standing on the layer below: a quarter
 * cylinder whose axis lies R out from the wall and R above the foot, from the wall R up to the
 * top below R out, cut at the wall's columns (the ends at a rounded upright left out, where the
 * corner's piece takes over) so that it meets the wall's bottom row and the bands of the top
 * below at their vertices. At a mitred end (a sharp concave corner) the end's profile keeps its
 * points on the wall and its end on the top below moves R along the wall, onto the corner's
 * diagonal plane, where the other wall's fillet ends in the same curve (its normals stay the
 * cylinder's, as at a rim's mitre). The texture's s is the wall's; t runs on down from the wall's
 * bottom by the arc's length. */
static void fillet_strip(const struct cube_layers *layers, int layer, int along_x, float fixed, float a, float b,
                         enum strip_end end_a, enum strip_end end_b, int normal_x, int normal_z, float radius)
{
  const double w = sqrt(2.0) / 2.0;
  float columns[4];
  const int count = wall_columns(a, b, keeps_end_column(end_a), keeps_end_column(end_b), radius, columns);
  const float foot = (float)layers->height[layer], above = foot + radius;
  const float t0 = texture_t(layers, above), t2 = t0 - (float)((PI / 2.0) * radius);
  const double axis[2] = {along_x ? a : fixed + (float)normal_x * radius, along_x ? fixed + (float)normal_z * radius : a};
  const double across[2] = {normal_x, normal_z};
  const struct rim_chart chart = strip_rim_chart(axis, across, above, -1.0, radius);
  for (int c = 0; c + 1 < count; ++c) {
    float net[2][3][4], tex[2][3][2];
    double centre[2][3][3];
    for (int v = 0; v < 2; ++v) {
      const float x = along_x ? columns[c + v] : fixed, z = along_x ? fixed : columns[c + v];
      const float out_x = x + (float)normal_x * radius, out_z = z + (float)normal_z * radius;
      const float mitre = c + v == 0 && end_a == ENDS_IN_MITRE            ? radius
                          : c + v == count - 1 && end_b == ENDS_IN_MITRE ? -radius
                                                                          : 0.0f;
      const float end_x = out_x + (along_x ? mitre : 0.0f), end_z = out_z + (along_x ? 0.0f : mitre);
      control_point(net[v][0], x, above, z, 1.0);
      control_point(net[v][1], x, foot, z, w);
      control_point(net[v][2], end_x, foot, end_z, 1.0);
      strip_column_texture(tex[v], wall_s(x, z, normal_x, normal_z), t0, t2);
      for (int u = 0; u < 3; ++u) {
        centre[v][u][0] = u == 2 ? end_x : out_x;
        centre[v][u][1] = above;
        centre[v][u][2] = u == 2 ? end_z : out_z;
      }
    }
    draw_rim_piece((const float (*)[3][4])net, (const float (*)[3][2])tex, (const double (*)[3][3])centre, 2, 1,
                   &chart);
  }
}

/* The rounded top (rim CAPPED_TOP) or bottom rims of `layer`, or its fillets (FILLETED_FOOT):
 * along every wall of a cell whose rim is rounded (foot filleted). */
static void rim_or_fillet_strip(const struct cube_layers *layers, int layer, int along_x, float fixed, float a,
                                float b, enum strip_end end_a, enum strip_end end_b, int normal_x, int normal_z,
                                float radius, int rim)
{
  if (rim == FILLETED_FOOT) fillet_strip(layers, layer, along_x, fixed, a, b, end_a, end_b, normal_x, normal_z, radius);
  else rim_strip(layers, layer, along_x, fixed, a, b, end_a, end_b, normal_x, normal_z, radius, rim);
}

/* Whether the rim `rim` of cell (i, j) of `layer` runs along its side towards the empty cell
 * (oi, oj): a rim shown there (rim_shown), or a fillet where the layer below fills the cell
 * across. */
static int rim_along(const struct cube_layers *layers, int layer, int i, int j, int oi, int oj, float radius, int rim)
{
  return rim_shown(layers, layer, i, j, radius, rim) &&
         (rim != FILLETED_FOOT || cube_layers_filled(layers, layer - 1, oi, oj));
}

static void rim_strips(const struct cube_layers *layers, int layer, float radius, int rim)
{
  for (int i = 0; i < layers->x_count; ++i)
    for (int j = 0; j + 1 < layers->z_count; ++j) {
      const int before = cube_layers_filled(layers, layer, i - 1, j), after = cube_layers_filled(layers, layer, i, j);
      if (before != after && rim_along(layers, layer, before ? i - 1 : i, j, before ? i : i - 1, j, radius, rim))
        rim_or_fillet_strip(layers, layer, 0, (float)layers->x[i], (float)layers->z[j], (float)layers->z[j + 1],
                            strip_end_at(layers, layer, i, j, radius, rim),
                            strip_end_at(layers, layer, i, j + 1, radius, rim), before ? 1 : -1, 0, radius, rim);
    }
  for (int j = 0; j < layers->z_count; ++j)
    for (int i = 0; i + 1 < layers->x_count; ++i) {
      const int before = cube_layers_filled(layers, layer, i, j - 1), after = cube_layers_filled(layers, layer, i, j);
      if (before != after && rim_along(layers, layer, i, before ? j - 1 : j, i, before ? j : j - 1, radius, rim))
        rim_or_fillet_strip(layers, layer, 1, (float)layers->z[j], (float)layers->x[i], (float)layers->x[i + 1],
                            strip_end_at(layers, layer, i, j, radius, rim),
                            strip_end_at(layers, layer, i + 1, j, radius, rim), 0, before ? 1 : -1, radius, rim);
    }
}

/* Above (below, for rim CAPPED_BOTTOM) the rounded upright at grid point (i, j) of `layer` where
 * the rims of its two walls are rounded: the upright's quarter circle turned by the rim's
 * (rim_corner_net), an eighth of a sphere at a convex corner, a quarter of a torus round the
 * fillet at a concave one. */
static void rim_corner(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  float from[2], corner[2], to[2], s0, s_length;
  const int convex = upright_arc(layers, layer, i, j, radius, from, corner, to, &s0, &s_length);
  if (!corner_rim_rounded(layers, layer, i, j, radius, rim)) return;
  const float axis[2] = {from[0] + to[0] - corner[0], from[1] + to[1] - corner[1]};
  const double arc[3][2] = {{from[0], from[1]}, {corner[0], corner[1]}, {to[0], to[1]}};
  const double axis_xz[2] = {axis[0], axis[1]};
  const float out = rim == CAPPED_TOP ? 1.0f : -1.0f;
  const float top = (float)layers->height[rim == CAPPED_TOP ? layer + 1 : layer], below = top - out * radius;
  const float t0 = texture_t(layers, below), t2 = t0 + out * (float)((PI / 2.0) * radius);
  float net[3][3][4], tex[3][3][2];
  double centre[3][3][3];
  rim_corner_net(arc, axis_xz, convex, below, top, s0, s_length, t0, t2, net, tex, centre);
  const struct rim_chart chart =
      corner_rim_chart(axis_xz, convex ? 0.0 : 2.0 * radius, below, out, radius);
  draw_rim_piece((const float (*)[3][4])net, (const float (*)[3][2])tex, (const double (*)[3][3])centre, 3, 0, &chart);
}

/* Whether fillets meet round the foot of the corner at grid point (i, j) of `layer`: a convex
 * corner (one of the cells around it in the solid) or a concave one (three of them) of a piece
 * whose foot is filleted, standing inside the top of the layer below (which fills the four cells
 * around the point). */
static int fillets_meet_at(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  const int around = cells_around(layers, layer, i, j);
  return (around == 1 || around == 3) && cells_around(layers, layer - 1, i, j) == 4 &&
         corner_rim_rounded(layers, layer, i, j, radius, FILLETED_FOOT);
}

/* Whether fillets_meet_at (i, j) in a corner piece (fillet_corner): round any convex corner, and
 * round a concave one with a rounded upright (at a sharp concave one they meet in a mitre). */
static int fillet_corner_at(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  return fillets_meet_at(layers, layer, i, j, radius) &&
         (cells_around(layers, layer, i, j) == 1 || upright_rounded(layers, layer, i, j, radius));
}

/* Where the fillets along two walls of `layer` meet round the foot of their corner at grid point
 * (i, j): the fillet's profile turned round the upright (turned_profile_net). Round a rounded
 * upright at a convex corner, whose arc runs about an axis R in from both walls, the profile runs
 * from the upright's arc R above the foot to that arc scaled by 2 from the axis on the top below:
 * a quarter of the inner half of a torus of radii 2 R and R. At a concave corner the axis lies R
 * out from both walls, where the profile's end on the top below meets it: the arc scaled by 0, an
 * eighth of a sphere of radius R about the axis R above the foot (the fillets' ends and the
 * upright's foot are its sides, its pole the point where the two fillets' edges on the top below
 * meet). Round a sharp upright the profile runs from the
 * corner's point R above the foot to a quarter circle of radius R about the upright on the top
 * below: a horn piece, its rows 0 and 1 closed in points, whose side curves are the fillets' end
 * profiles. The texture's s runs on from the wall the walk arrives by, as round an upright. */
static void fillet_corner(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  float from[2], corner[2], to[2], s0, s_length;
  upright_arc(layers, layer, i, j, radius, from, corner, to, &s0, &s_length);
  const float upright_axis[2] = {from[0] + to[0] - corner[0], from[1] + to[1] - corner[1]};
  const int rounded = upright_rounded(layers, layer, i, j, radius);
  /* Round a sharp upright the arc moves out to the corner's quarter circle, and s starts and ends at
   * the corner, R further along each wall. */
  const double shift[2] = {rounded ? 0.0 : (double)corner[0] - upright_axis[0],
                           rounded ? 0.0 : (double)corner[1] - upright_axis[1]};
  const double arc[3][2] = {{from[0] + shift[0], from[1] + shift[1]},
                            {corner[0] + shift[0], corner[1] + shift[1]},
                            {to[0] + shift[0], to[1] + shift[1]}};
  const double axis[2] = {upright_axis[0] + shift[0], upright_axis[1] + shift[1]};
  const int convex = cells_around(layers, layer, i, j) == 1;
  const double inner = rounded ? 1.0 : 0.0, scale[3] = {inner, inner, convex ? inner + 1.0 : 0.0};
  if (!rounded) {
    const float s1 = s0 + s_length;
    s0 += radius;
    s_length = s_across(s0, s1 - radius, (float)(PI / 2.0) * radius);
  }
  const float foot = (float)layers->height[layer], above = foot + radius;
  const double y[3] = {above, foot, foot};
  const float t0 = texture_t(layers, above), t2 = t0 - (float)((PI / 2.0) * radius);
  float net[3][3][4], tex[3][3][2];
  double centre[3][3][3];
  turned_profile_net(arc, axis, scale, y, s0, s_length, t0, t2, net, tex, centre);
  /* On the top below the piece's edge is scale[2] R from the axis: 2 R round a rounded upright, R
   * round a sharp one. */
  const struct rim_chart chart = corner_rim_chart(axis, scale[2] * radius, above, -1.0, radius);
  draw_rim_piece((const float (*)[3][4])net, (const float (*)[3][2])tex, (const double (*)[3][3])centre, 3, 1, &chart);
}

/* What `layer` covers of the R x R square of cell (i, j) at its grid point (gi, gj). */
static int square_cover(const struct cube_layers *layers, int layer, int i, int j, int gi, int gj, float radius)
{
  const int filled = cube_layers_filled(layers, layer, i, j);
  if (!upright_rounded(layers, layer, gi, gj, radius)) return filled ? WHOLE_SQUARE : 0;
  /* The cell that differs from the other three holds the arc. */
  const int odd = (cells_around(layers, layer, gi, gj) == 1) == filled;
  if (!odd) return filled ? WHOLE_SQUARE : 0;
  return filled ? QUARTER_DISK : CORNER_PIECE;
}

static void flat_vertex(float x, float y, float z)
{
  glTexCoord2f(x, z);
  glVertex3f(x, y, z);
}

static void flat_rectangle(float x0, float x1, float z0, float z1, float y)
{
  if (x1 <= x0 || z1 <= z0) return;
  glBegin(GL_QUADS);
  flat_vertex(x0, y, z0);
  flat_vertex(x1, y, z0);
  flat_vertex(x1, y, z1);
  flat_vertex(x0, y, z1);
  glEnd();
}

/* The part `cover` of the R x R square at grid point `corner` reaching in by (dx, dz) R, at
 * height y. Its arc runs from the point R along x to the point R along z, the same points on every
 * piece sharing it. */
static void flat_square(const float corner[2], int dx, int dz, int cover, float y, float radius)
{
  const float along_x[2] = {corner[0] + (float)dx * radius, corner[1]};
  const float along_z[2] = {corner[0], corner[1] + (float)dz * radius};
  if (cover == WHOLE_SQUARE) {
    flat_rectangle(dx > 0 ? corner[0] : along_x[0], dx > 0 ? along_x[0] : corner[0], dz > 0 ? corner[1] : along_z[1],
                   dz > 0 ? along_z[1] : corner[1], y);
    return;
  }
  if (!cover) return;
  glBegin(GL_TRIANGLE_FAN);
  if (cover == QUARTER_DISK) flat_vertex(along_x[0], y, along_z[1]);
  else flat_vertex(corner[0], y, corner[1]);
  for (int step = 0; step <= ARC_STEPS; ++step) {
    double p[2];
    quarter_arc_point(along_x, corner, along_z, (double)step / ARC_STEPS, p);
    glTexCoord2d(p[0], p[1]);
    glVertex3d(p[0], y, p[1]);
  }
  glEnd();
}

/* Whether a quarter of a torus turns the rounded top (rim CAPPED_TOP) or bottom rim of `layer`
 * round the rounded upright at grid point (i, j): a concave corner (three of the cells around it
 * in the solid) of a piece whose rim there is rounded. */
static int torus_corner(const struct cube_layers *layers, int layer, int i, int j, float radius, int rim)
{
  return cells_around(layers, layer, i, j) == 3 && upright_rounded(layers, layer, i, j, radius) &&
         corner_rim_rounded(layers, layer, i, j, radius, rim);
}

/* Where a fan of concave_corner_fans starts: the end `end` of the torus's inner rim is R from the
 * concave grid point `corner` along both axes, towards the empty cell (the side of the fillet's
 * axis) along one; the fan starts on the squares' outer side beside it, level with the grid
 * point along that axis. */
static void fan_apex(const float end[2], const float corner[2], const float axis[2], float apex[2])
{
  for (int k = 0; k < 2; ++k) apex[k] = (end[k] > corner[k]) == (axis[k] > corner[k]) ? corner[k] : end[k];
}

/* The texture of a standing corner's torus piece (standing_corner), which meets five neighbours:
 * the fillet's end (its row 0, from the fillet's wall at u = 0 to the top below at u = 1), the
 * upright's foot (column 0), the rim's end (column 2, from the top below at v = 0 to the flush
 * wall at v = 1) and the flush plane (row 2). The fillet and the rim are drawn in halves, the
 * half next to a wall with the wall's texture and the half next to the top below with its (x, z)
 * (draw_net_in_halves), so the piece is drawn in three parts of its grid, each continuing the
 * neighbours it touches:
 * - u up to 1/2 (the fillet's wall half, the upright's foot, the flush plane's first half): the
 *   walls' texture, s from the fillet's round the upright's arc (fillet_s + upright_turn v), t from
 *   the height R above the foot down the fillet by its arc's length (standing_wall_texture);
 * - u from 1/2, v up to 1/2 (the fillet's and the rim's halves next to the top below): the top
 *   below's (x, z), run on by arc length round both the fillet's and the rim's quarter circles
 *   (standing_top_texture);
 * - u and v from 1/2 (the rim's wall half and the flush plane's second half): from the first
 *   part's values along u = 1/2 to the rim's wall texture along its end (s the flush wall's, t
 *   from R below the foot up the rim by its arc's length), linearly in u.
 * The flush plane takes the piece's values on its inner rim, so the two agree there. */
struct standing_texture {
  float fillet_s, upright_turn, rim_s; /* rim_s moved by whole repeats close to fillet_s + upright_turn */
  float t_above, t_below;              /* t R above and R below the foot */
  double corner[2], n_w[2], n_f[2];    /* x, z: the corner; its fillet's wall's and the flush wall's normals */
  double foot, radius;
};

/* The walls' texture of part `part` of the piece (0: u up to 1/2; 1: u and v from 1/2) by its
 * formula, bilinear in the grid parameters (u, v), taken at any (u, v). */
static void standing_part_texture(const struct standing_texture *st, int part, double u, double v, double out[2])
{
  const double quarter = PI / 2.0 * st->radius;
  const double s_round = st->fillet_s + st->upright_turn * v;  /* the first part's s */
  if (part == 0) {
    out[0] = s_round;
    out[1] = st->t_above - quarter * u;
    return;
  }
  const double to_rim = 2 * u - 1;  /* 0 along u = 1/2, 1 along the rim's end */
  out[0] = s_round + (st->rim_s - s_round) * to_rim;
  out[1] = (st->t_above - quarter / 2) * (1 - to_rim) + (st->t_below + quarter * (1 - v)) * to_rim;
}

/* The walls' texture at grid parameters (u, v) of the piece away from the top below. */
static void standing_wall_texture(const struct standing_texture *st, double u, double v, double out[2])
{
  standing_part_texture(st, u > 0.5, u, v, out);
}

/* Part `part`'s texture as a net for glMap2f: bilinear, so its quadratic net holds its values at
 * u, v = 0, 1/2 and 1. */
static void standing_wall_net(const struct standing_texture *st, int part, float tex[3][3][2])
{
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 3; ++u) {
      double value[2];
      standing_part_texture(st, part, u / 2.0, v / 2.0, value);
      tex[v][u][0] = (float)value[0];
      tex[v][u][1] = (float)value[1];
    }
}

/* The top below's (x, z) run on over the part of the piece next to it: a point of the piece at
 * angle turn about the fillet's axis from straight down (towards the fillet's wall) and at angle
 * tube round the piece's tube from the fillet's side (towards the flush plane) takes the top's
 * (x, z) R - R turn out along n_w and R tube - R along n_f from the corner: the fillet's chart
 * where tube is 0, the rim's where turn is 0. */
static void standing_top_texture(const double p[3], const void *data, float out[2])
{
  const struct standing_texture *st = data;
  const double r = st->radius;
  const double from_corner[2] = {p[0] - st->corner[0], p[2] - st->corner[1]};
  const double a = from_corner[0] * st->n_w[0] + from_corner[1] * st->n_w[1];
  const double d = from_corner[0] * st->n_f[0] + from_corner[1] * st->n_f[1];
  const double ra = a - r, rb = p[1] - (st->foot + r);
  const double turn = atan2(-ra, -rb), tube = atan2(d + r, 2 * r - hypot(ra, rb));
  const double along_w = r - r * turn, along_f = r * tube - r;
  out[0] = (float)(st->corner[0] + along_w * st->n_w[0] + along_f * st->n_f[0]);
  out[1] = (float)(st->corner[1] + along_w * st->n_w[1] + along_f * st->n_f[1]);
}

/* A plane in which concave_corner_fans draws: `vertex` draws the point (a, b) of the plane, at
 * parameter u of the torus's inner rim when on_rim. */
struct fan_plane {
  void (*vertex)(const struct fan_plane *plane, double a, double b, int on_rim, double u);
  const struct cube_layers *layers;
  float y;                      /* a top or bottom: its height */
  float origin[2];              /* a wall: (a, b) is the point origin + a along[] at height b */
  int along[2], normal[2];      /* (x, z) */
  float s_shift;                /* a wall's texture: the wall's s moved by whole repeats */
  const struct standing_texture *standing; /* a wall's: the torus piece's texture on the rim */
};

/* Round the concave point `corner` of a plane (a, b) whose torus piece's fillet arc runs from
 * `from` round `corner` to `to`: of the three R x R squares round the point in the solid, what
 * lies outside the torus's inner rim, the arc scaled by 2 from its axis (2 R from the axis,
 * through the squares' far corners' sides). The rim's ends lie at corners of the squares, and
 * every point of it is seen from the middle of the squares' outer sides next to it, so two fans
 * from those points, split at the rim's middle and at the squares' far corner, cover it; their
 * sides along the squares' edges meet the neighbouring pieces there. */
static void concave_corner_fans(const float from[2], const float corner[2], const float to[2],
                                const struct fan_plane *plane)
{
  const float axis[2] = {from[0] + to[0] - corner[0], from[1] + to[1] - corner[1]};
  float far_from[2], far_corner[2], far_to[2], far_square[2], apex_from[2], apex_to[2];
  for (int k = 0; k < 2; ++k) {
    far_from[k] = axis[k] + 2 * (from[k] - axis[k]);
    far_corner[k] = axis[k] + 2 * (corner[k] - axis[k]);
    far_to[k] = axis[k] + 2 * (to[k] - axis[k]);
    far_square[k] = corner[k] - (axis[k] - corner[k]);
  }
  fan_apex(far_from, corner, axis, apex_from);
  fan_apex(far_to, corner, axis, apex_to);
  for (int half = 0; half < 2; ++half) {
    const float *apex = half ? apex_to : apex_from;
    glBegin(GL_TRIANGLE_FAN);
    plane->vertex(plane, apex[0], apex[1], 0, 0);
    if (half) plane->vertex(plane, far_square[0], far_square[1], 0, 0);
    for (int step = half ? ARC_STEPS / 2 : 0; step <= (half ? ARC_STEPS : ARC_STEPS / 2); ++step) {
      double p[2];
      quarter_arc_point(far_from, far_corner, far_to, (double)step / ARC_STEPS, p);
      plane->vertex(plane, p[0], p[1], 1, (double)step / ARC_STEPS);
    }
    if (!half) plane->vertex(plane, far_square[0], far_square[1], 0, 0);
    glEnd();
  }
}

/* A point (x, z) of a top or bottom, its texture (x, z). */
static void level_vertex(const struct fan_plane *plane, double a, double b, int on_rim, double u)
{
  (void)on_rim, (void)u;
  glTexCoord2d(a, b);
  glVertex3d(a, plane->y, b);
}

/* The flat face at height y round the torus piece at the concave grid point (i, j) of `layer`
 * (concave_corner_fans in the plane (x, z)). */
static void torus_corner_flat(const struct cube_layers *layers, int layer, int i, int j, float y, float radius)
{
  float from[2], corner[2], to[2], s0, s_length;
  upright_arc(layers, layer, i, j, radius, from, corner, to, &s0, &s_length);
  const struct fan_plane plane = {.vertex = level_vertex, .layers = layers, .y = y};
  concave_corner_fans(from, corner, to, &plane);
}

/* A point (a, b) of a wall, its texture the wall's moved by the plane's s_shift, on the torus's
 * inner rim the torus piece's texture there (its last row at u), so that the two agree. */
static void wall_vertex(const struct fan_plane *plane, double a, double b, int on_rim, double u)
{
  const double x = plane->origin[0] + a * plane->along[0], z = plane->origin[1] + a * plane->along[1];
  if (on_rim) {
    double st[2];
    standing_wall_texture(plane->standing, u, 1.0, st);
    glTexCoord2d(st[0], st[1]);
  } else {
    glTexCoord2d(x * plane->normal[1] - z * plane->normal[0] + plane->s_shift, b - plane->layers->height[0]);
  }
  glVertex3d(x, b, z);
}

/* The standing corner at grid point (i, j) of `layer` (standing_corner_at): the piece's convex
 * corner whose fillet, along the wall facing n_w, ends against the top rim of the layer below,
 * which runs on along the piece's other wall, flush with the lower layer's side and facing n_f.
 * Seen in that flush plane, with a along n_w from the corner and b the height, the fillet's
 * quarter circle runs from the wall (0, foot + R) round (0, foot) to the top below (R, foot) about
 * its axis (R, foot + R), and the three edges meeting at the corner are the concave edge along
 * the fillet and two convex ones, the upright and the rim: the L's concave corner with its top
 * turned to face n_f. Its piece is the same quarter of a torus (turned_profile_net in that frame:
 * the fillet's quarter circle R inside the flush plane, in the plane and scaled by 2 from its
 * axis), radii 2 R and R about the fillet's axis, between the fillet's end, the upright's
 * quarter cylinder R above the foot and the rim's end, its normals from its tube's centre circle
 * (begin_net_parts); the flush plane keeps what lies outside its arc of radius 2 R
 * (concave_corner_fans). Its texture takes each neighbour's along their seams: the fillet's end
 * (s the fillet's, t from the foot + R to the foot's height), the upright's foot (s as on the
 * upright, moved by whole repeats to start at the fillet's, t at the foot + R) and the rim's end
 * (t from the foot's height to the foot - R, s the fillet's moved as standing_corner_s says),
 * and the flush plane's along its inner rim. */
static void standing_corner(const struct cube_layers *layers, int layer, int i, int j, float radius)
{
  float from[2], corner[2], to[2], s0, s_length;
  upright_arc(layers, layer, i, j, radius, from, corner, to, &s0, &s_length);
  int n_w[2], n_f[2];
  standing_corner_walls(layers, layer, i, j, n_w, n_f);
  const double foot = layers->height[layer];
  const double frame[4][3] = {{corner[0], 0, corner[1]}, {n_w[0], 0, n_w[1]}, {n_f[0], 0, n_f[1]}, {0, 1, 0}};
  const double arc[3][2] = {{0, foot + radius}, {0, foot}, {radius, foot}}, axis[2] = {radius, foot + radius};
  const double scale[3] = {1, 1, 2}, depth[3] = {-radius, 0, 0};
  float net[3][3][4], tex[3][3][2];
  double centre[3][3][3];
  turned_profile_net_in_frame(arc, axis, scale, depth, frame, 0, 0, 0, 0, net, tex, centre);
  /* Which end of the upright's arc lies on the fillet's wall (R in from the flush wall). */
  const float on_fillet_wall[2] = {corner[0] - (float)n_f[0] * radius, corner[1] - (float)n_f[1] * radius};
  const int from_fillet = fabsf(from[0] - on_fillet_wall[0]) + fabsf(from[1] - on_fillet_wall[1]) < radius / 2;
  struct standing_texture st = {
      .fillet_s = wall_s(on_fillet_wall[0], on_fillet_wall[1], n_w[0], n_w[1]),
      .upright_turn = from_fillet ? s_length : -s_length,
      .t_above = texture_t(layers, foot + radius),
      .t_below = texture_t(layers, foot - radius),
      .corner = {corner[0], corner[1]},
      .n_w = {n_w[0], n_w[1]},
      .n_f = {n_f[0], n_f[1]},
      .foot = foot,
      .radius = radius};
  /* The rim's s at its end (its wall's, R out from the corner), moved by whole repeats. */
  const float rim_s = wall_s(corner[0] + (float)n_w[0] * radius, corner[1] + (float)n_w[1] * radius, n_f[0], n_f[1]);
  st.rim_s = (float)(rim_s - CHECKER_PERIOD * nearbyint((rim_s - st.fillet_s - st.upright_turn) / CHECKER_PERIOD));
  float wall_net[3][3][2], rim_net[3][3][2];
  standing_wall_net(&st, 0, wall_net);
  standing_wall_net(&st, 1, rim_net);
  const int half = ARC_STEPS / 2;
  begin_net_parts((const float (*)[3][4])net, (const double (*)[3][3])centre, 1.0f, 3, ARC_STEPS);
  draw_part_mapped((const float (*)[3][2])wall_net, (struct grid_part){0, half, 0, ARC_STEPS});
  draw_part_charted(standing_top_texture, &st, (struct grid_part){half, ARC_STEPS, 0, half});
  draw_part_mapped((const float (*)[3][2])rim_net, (struct grid_part){half, ARC_STEPS, half, ARC_STEPS});
  end_net_parts();

  struct fan_plane plane = {.vertex = wall_vertex, .layers = layers, .origin = {corner[0], corner[1]},
                            .along = {n_w[0], n_w[1]}, .normal = {n_f[0], n_f[1]}, .standing = &st};
  /* The wall's s at the rim's start, (a, b) = (-R, foot + R), moved by whole repeats to the torus's there. */
  const float wall_start_s = wall_s(corner[0] - (float)n_w[0] * radius, corner[1] - (float)n_w[1] * radius, n_f[0], n_f[1]);
  double start[2];
  standing_wall_texture(&st, 0.0, 1.0, start);
  plane.s_shift = (float)(CHECKER_PERIOD * nearbyint((start[0] - wall_start_s) / CHECKER_PERIOD));
  const float fan_from[2] = {0, (float)foot + radius}, fan_corner[2] = {0, (float)foot}, fan_to[2] = {radius, (float)foot};
  glNormal3f((float)n_f[0], 0, (float)n_f[1]);
  concave_corner_fans(fan_from, fan_corner, fan_to, &plane);
}

/* The flat face at height `level`: what the layer below covers and the layer above does not
 * (facing up, up = 1) or the other way round (facing down, up = 0), cell by cell: its middle and
 * its bands along the sides as the cells are, its corners' squares by square_cover. */
static void flat_face(const struct cube_layers *layers, int level, int up, float radius)
{
  const int inner = up ? level - 1 : level, outer = up ? level : level - 1;
  const float y = (float)layers->height[level];
  glNormal3f(0, up ? 1.0f : -1.0f, 0);
  for (int j = 0; j + 1 < layers->z_count; ++j)
    for (int i = 0; i + 1 < layers->x_count; ++i) {
      const int shown = cube_layers_filled(layers, inner, i, j) && !cube_layers_filled(layers, outer, i, j);
      const float x0 = (float)layers->x[i], x1 = (float)layers->x[i + 1];
      const float z0 = (float)layers->z[j], z1 = (float)layers->z[j + 1];
      const float xs[4] = {x0, x0 + radius, x1 - radius, x1}, zs[4] = {z0, z0 + radius, z1 - radius, z1};
      /* Along a rounded rim the band R wide is the rim's strip, and its corners' squares are the
       * strips' and the spheres' eighths. */
      const int rim_bit = up ? CAPPED_TOP : CAPPED_BOTTOM;
      const int capped = rim_shown(layers, inner, i, j, radius, rim_bit);
      /* Along a fillet at the foot of the layer above, the band R wide is the fillet's. */
      const int rim[4] = {(capped && !(cube_layers_capped(layers, inner, i - 1, j) & rim_bit)) ||
                              (up && rim_rounded(layers, outer, i - 1, j, radius, FILLETED_FOOT)),
                          (capped && !(cube_layers_capped(layers, inner, i + 1, j) & rim_bit)) ||
                              (up && rim_rounded(layers, outer, i + 1, j, radius, FILLETED_FOOT)),
                          (capped && !(cube_layers_capped(layers, inner, i, j - 1) & rim_bit)) ||
                              (up && rim_rounded(layers, outer, i, j - 1, radius, FILLETED_FOOT)),
                          (capped && !(cube_layers_capped(layers, inner, i, j + 1) & rim_bit)) ||
                              (up && rim_rounded(layers, outer, i, j + 1, radius, FILLETED_FOOT))};
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          if ((a == 0 && rim[0]) || (a == 2 && rim[1]) || (b == 0 && rim[2]) || (b == 2 && rim[3])) continue;
          if (a != 1 && b != 1) {
            const int gi = a ? i + 1 : i, gj = b ? j + 1 : j;
            /* Round a standing corner the torus piece stands on the top below at one point only. */
            if (torus_corner(layers, inner, gi, gj, radius, rim_bit) || (up && standing_corner_at(layers, outer, gi, gj, radius)))
              continue;
            if (up && fillets_meet_at(layers, outer, gi, gj, radius)) {
              /* Of the squares round a fillets' corner, the bands' are the fillets', the one under
               * the piece above is covered, and the one across the corner keeps what lies outside
               * the corner piece: outside its quarter circle about a sharp upright, outside the
               * 2 R arc (torus_corner_flat, with the bands' squares) about a rounded one. At a
               * concave corner the square outside the piece is the sphere piece's, or the two
               * mitred fillets'. */
              if (cells_around(layers, outer, gi, gj) == 1 && !upright_rounded(layers, outer, gi, gj, radius) &&
                  !cube_layers_filled(layers, outer, i, j)) {
                const float far[2] = {(float)layers->x[gi] + (float)(a ? -1 : 1) * radius,
                                      (float)layers->z[gj] + (float)(b ? -1 : 1) * radius};
                flat_square(far, a ? 1 : -1, b ? 1 : -1, CORNER_PIECE, y, radius);
              }
              continue;
            }
            const int cover = square_cover(layers, inner, i, j, gi, gj, radius) &
                              ~square_cover(layers, outer, i, j, gi, gj, radius);
            const float corner[2] = {(float)layers->x[gi], (float)layers->z[gj]};
            flat_square(corner, a ? -1 : 1, b ? -1 : 1, cover, y, radius);
          } else if (shown) {
            flat_rectangle(xs[a], xs[a + 1], zs[b], zs[b + 1], y);
          }
        }
    }
  for (int j = 0; j < layers->z_count; ++j)
    for (int i = 0; i < layers->x_count; ++i) {
      if (torus_corner(layers, inner, i, j, radius, up ? CAPPED_TOP : CAPPED_BOTTOM))
        torus_corner_flat(layers, inner, i, j, y, radius);
      if (up && fillet_corner_at(layers, outer, i, j, radius) && upright_rounded(layers, outer, i, j, radius) &&
          cells_around(layers, outer, i, j) == 1)
        torus_corner_flat(layers, outer, i, j, y, radius);
    }
}

void draw_layered_block(const struct cube_layers *layers, float radius)
{
  for (int layer = 0; layer < layers->layer_count; ++layer) {
    walls(layers, layer, radius);
    for (int j = 0; j < layers->z_count; ++j)
      for (int i = 0; i < layers->x_count; ++i)
        if (upright_rounded(layers, layer, i, j, radius)) {
          upright_cylinder(layers, layer, i, j, radius);
          rim_corner(layers, layer, i, j, radius, CAPPED_TOP);
          rim_corner(layers, layer, i, j, radius, CAPPED_BOTTOM);
        }
    rim_strips(layers, layer, radius, CAPPED_TOP);
    rim_strips(layers, layer, radius, CAPPED_BOTTOM);
    rim_strips(layers, layer, radius, FILLETED_FOOT);
    for (int j = 0; j < layers->z_count; ++j)
      for (int i = 0; i < layers->x_count; ++i)
        if (fillet_corner_at(layers, layer, i, j, radius)) fillet_corner(layers, layer, i, j, radius);
        else if (standing_corner_at(layers, layer, i, j, radius)) standing_corner(layers, layer, i, j, radius);
  }
  for (int level = 0; level <= layers->layer_count; ++level) {
    flat_face(layers, level, 1, radius);
    flat_face(layers, level, 0, radius);
  }
}
