/* Cutting the homework's object into layers of cells (cube_layers.h). A cell is in the solid when
 * a ray from its centre straight up crosses one more top face than bottom faces (fill_cells);
 * a face holds the column's centre when a ray from it along +x crosses the face's edges an odd
 * number of times, which needs no order of the edges round the face. The centres lie off every
 * grid line, so no ray grazes an edge. */
#include "cube_layers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int ascending(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The distinct values of the vertices' coordinate `axis` (values closer than `tolerance` taken as
 * one, the smallest of them) into *values, ascending, and each vertex's place among them into
 * place[3 v + axis]. Returns their count, or -1 when out of memory. */
static int grid_lines(const struct wings_mesh *mesh, int axis, double tolerance, double **values, int *place)
{
  double *sorted = malloc((size_t)mesh->vertex_count * sizeof *sorted + 1);
  if (!sorted) return -1;
  for (long v = 0; v < mesh->vertex_count; ++v) sorted[v] = mesh->position[v][axis];
  qsort(sorted, (size_t)mesh->vertex_count, sizeof *sorted, ascending);
  int count = 0;
  for (long k = 0; k < mesh->vertex_count; ++k)
    if (count == 0 || sorted[k] - sorted[count - 1] > tolerance) sorted[count++] = sorted[k];
  for (long v = 0; v < mesh->vertex_count; ++v) {
    /* The first line at or above the coordinate less the tolerance is its own. */
    const double p = mesh->position[v][axis] - tolerance;
    int low = 0, high = count - 1;
    while (low < high) {
      const int middle = (low + high) / 2;
      if (sorted[middle] >= p) high = middle;
      else low = middle + 1;
    }
    place[3 * v + axis] = low;
  }
  *values = sorted;
  return count;
}

int cube_layers_filled(const struct cube_layers *layers, int layer, int i, int j)
{
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  if (layer < 0 || layer >= layers->layer_count || i < 0 || i >= cells_x || j < 0 || j >= cells_z) return 0;
  return layers->filled[((size_t)layer * (size_t)cells_z + (size_t)j) * (size_t)cells_x + (size_t)i];
}

int cube_layers_rounded(const struct cube_layers *layers, int layer, int i, int j)
{
  if (layer < 0 || layer >= layers->layer_count || i < 0 || i >= layers->x_count || j < 0 || j >= layers->z_count)
    return 0;
  return layers->rounded[((size_t)layer * (size_t)layers->z_count + (size_t)j) * (size_t)layers->x_count + (size_t)i];
}

int cube_layers_capped(const struct cube_layers *layers, int layer, int i, int j)
{
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  if (!layers->capped || layer < 0 || layer >= layers->layer_count || i < 0 || i >= cells_x || j < 0 ||
      j >= cells_z)
    return 0;
  return layers->capped[((size_t)layer * (size_t)cells_z + (size_t)j) * (size_t)cells_x + (size_t)i];
}

int cube_layers_alike(const struct cube_layers *layers)
{
  const size_t cells = (size_t)(layers->x_count - 1) * (size_t)(layers->z_count - 1);
  for (int k = 1; k < layers->layer_count; ++k)
    if (memcmp(layers->filled, layers->filled + (size_t)k * cells, cells) != 0) return 0;
  return 1;
}

/* How many of the four cells around grid point (i, j) of `layer` are in the solid; whether they
 * are two diagonal ones goes into *diagonal. */
static int cells_around(const struct cube_layers *layers, int layer, int i, int j, int *diagonal)
{
  const int a = cube_layers_filled(layers, layer, i - 1, j - 1), b = cube_layers_filled(layers, layer, i, j - 1);
  const int c = cube_layers_filled(layers, layer, i - 1, j), d = cube_layers_filled(layers, layer, i, j);
  *diagonal = a == d && b == c && a != b;
  return a + b + c + d;
}

/* Which cells of each layer the solid fills (the rays of the comment at the top). Going down a
 * column, a top face (outward normal +y) enters the solid and a bottom face leaves it, so the
 * count of tops less bottoms passed is how many times the column is inside: 0 or 1 in a solid,
 * 2 where parts of the object overlap, -1 where faces turn their inside out. A face's normal is
 * Newell's: half the sum of Vs x Ve over its edges walked counter-clockwise (left edges from Vs
 * to Ve, right edges from Ve to Vs), which needs no order of the edges round the face. */
static int fill_cells(const struct wings_mesh *mesh, struct cube_layers *layers, const int *place,
                      const int *face_axis, const int *face_level, char *error, size_t size)
{
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  unsigned char *holds = malloc((size_t)mesh->face_count + 1);
  int *faces_at = malloc((size_t)(layers->layer_count + 1) * sizeof *faces_at);
  int *turn_at = malloc((size_t)(layers->layer_count + 1) * sizeof *turn_at);
  long *face_at = malloc((size_t)(layers->layer_count + 1) * sizeof *face_at);
  double *normal_y = calloc((size_t)mesh->face_count + 1, sizeof *normal_y);
  int ok = holds && faces_at && turn_at && face_at && normal_y ? 1 : wings_failed(error, size, "out of memory");
  for (long e = 0; ok && e < mesh->edge_count; ++e) {
    const struct winged_edge *edge = &mesh->edges[e];
    const double *a = mesh->position[edge->vs], *b = mesh->position[edge->ve];
    const double cross_y = a[2] * b[0] - a[0] * b[2];
    normal_y[edge->lf] += cross_y;
    normal_y[edge->rf] -= cross_y;
  }
  for (int j = 0; ok && j < cells_z; ++j)
    for (int i = 0; ok && i < cells_x; ++i) {
      const double cx = (layers->x[i] + layers->x[i + 1]) / 2, cz = (layers->z[j] + layers->z[j + 1]) / 2;
      memset(holds, 0, (size_t)mesh->face_count + 1);
      for (long e = 0; e < mesh->edge_count; ++e) {
        const struct winged_edge *edge = &mesh->edges[e];
        const double z0 = layers->z[place[3 * edge->vs + 2]], z1 = layers->z[place[3 * edge->ve + 2]];
        /* Crossing the line z = cz, the edge runs along z, at one x. */
        if ((z0 > cz) != (z1 > cz) && layers->x[place[3 * edge->vs]] > cx) {
          holds[edge->lf] ^= 1;
          holds[edge->rf] ^= 1;
        }
      }
      for (int k = 0; k <= layers->layer_count; ++k) faces_at[k] = turn_at[k] = 0, face_at[k] = -1;
      for (long f = 0; f < mesh->face_count; ++f)
        if (face_axis[f] == 1 && holds[f]) {
          const int k = face_level[f];
          if (faces_at[k]++ > 0) {
            ok = wings_failed(error, size, "object 1, faces %ld and %ld: both at height %g above x %g, z %g (faces "
                              "overlap; a closed object made of cubes is expected)", face_at[k], f,
                              layers->height[k], cx, cz);
            break;
          }
          face_at[k] = f;
          turn_at[k] = normal_y[f] > 0 ? 1 : -1;
        }
      int inside = 0;
      for (int k = layers->layer_count; ok && k >= 0; --k) {
        inside += turn_at[k];
        if (inside > 1)
          ok = wings_failed(error, size, "object 1, face %ld: below it, above x %g, z %g, the object is inside "
                            "itself twice from height %g to %g (parts of it overlap; a closed object made of cubes "
                            "is expected)", face_at[k], cx, cz, k > 0 ? layers->height[k - 1] : layers->height[k],
                            layers->height[k]);
        else if (inside < 0)
          ok = wings_failed(error, size, "object 1, face %ld: at height %g above x %g, z %g it faces into the object "
                            "(its vertices run clockwise seen from outside; a closed object made of cubes is "
                            "expected)", face_at[k], layers->height[k], cx, cz);
        else if (k > 0)
          layers->filled[((size_t)(k - 1) * (size_t)cells_z + (size_t)j) * (size_t)cells_x + (size_t)i] =
              (unsigned char)inside;
      }
      if (ok && inside)
        ok = wings_failed(error, size, "object 1 is not closed: above x %g, z %g its faces do not pair up into "
                          "bottoms and tops", cx, cz);
    }
  free(holds);
  free(faces_at);
  free(turn_at);
  free(face_at);
  free(normal_y);
  return ok;
}

/* Whether the edge between grid points a and b (x, y, z grid indices) runs along x or z at one
 * height; if so, *along_x says which, and the grid lines it spans along that axis are [*from, *to). */
static int horizontal_segment(const int *a, const int *b, int *along_x, int *from, int *to)
{
  if (a[1] != b[1] || (a[0] == b[0]) == (a[2] == b[2])) return 0;
  *along_x = a[2] == b[2];
  const int axis = *along_x ? 0 : 2;
  *from = a[axis] < b[axis] ? a[axis] : b[axis];
  *to = a[axis] < b[axis] ? b[axis] : a[axis];
  return 1;
}

/* The slot of the grid segment from grid point (i, j) one step along x (along_x) or z, at height
 * `level`, in cap_pieces' arrays: [along_x][level][j][i]. */
static size_t rim_slot(const struct cube_layers *layers, int along_x, int level, int i, int j)
{
  const size_t points = (size_t)layers->x_count * (size_t)layers->z_count;
  const size_t levels = (size_t)layers->layer_count + 1;
  return ((size_t)along_x * levels + (size_t)level) * points + (size_t)j * (size_t)layers->x_count + (size_t)i;
}

/* Whether there are edges along that grid segment, all of them hard. */
static int rim_hard(const unsigned char *covered, const unsigned char *soft, const struct cube_layers *layers,
                    int along_x, int level, int i, int j)
{
  const size_t slot = rim_slot(layers, along_x, level, i, j);
  return covered[slot] && !soft[slot];
}

/* Whether cell (i, j) is one of the piece numbered `start` in `piece` (-1 off the grid). */
static int in_piece(const struct cube_layers *layers, const int *piece, int start, int i, int j)
{
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  return i >= 0 && i < cells_x && j >= 0 && j < cells_z && piece[j * cells_x + i] == start;
}

/* Whether the piece numbered `start` of `layer`'s footprint, whose cells lie from (i0, j0) to
 * (i1, j1), is outlined by loops with a rounded upright at every concave corner (its rim turns
 * round the fillet in a piece of torus; at a sharp convex corner the rim's strips meet in a
 * mitre): one round it and one round each hole, with no two of its cells meeting at a corner
 * only. A loop of right angles turns once, so the outer loop's convex corners outnumber its
 * concave ones by four; a hole's loop turns the other way and takes four more concave ones. */
static int loops_round_fillets(const struct cube_layers *layers, const int *piece, int start, int layer, int i0,
                                  int i1, int j0, int j1)
{
  int convex = 0, concave = 0;
  for (int gj = j0; gj <= j1 + 1; ++gj)
    for (int gi = i0; gi <= i1 + 1; ++gi) {
      const int around = in_piece(layers, piece, start, gi - 1, gj - 1) + in_piece(layers, piece, start, gi, gj - 1) +
                         in_piece(layers, piece, start, gi - 1, gj) + in_piece(layers, piece, start, gi, gj);
      if (around == 3 && !cube_layers_rounded(layers, layer, gi, gj)) return 0;
      if (around == 2 && in_piece(layers, piece, start, gi - 1, gj - 1) == in_piece(layers, piece, start, gi, gj))
        return 0; /* two cells meeting at a corner only */
      convex += around == 1;
      concave += around == 3;
    }
  return convex - concave <= 4 && (convex - concave) % 4 == 0;
}

/* How the foot of the piece numbered `start` of `layer`'s footprint (`piece` numbers the layer's
 * cells), whose cells lie from (i0, j0) to (i1, j1), is filleted (FILLETED_FOOT in
 * cube_layers.h): 0 not at all; else the layer below fills the cells under it and this layer
 * leaves every cell round it (beside it or across a corner) empty, and each side of its outline
 * is inside the lower layer's top (which fills the cells beyond it; the foot's edges there hard)
 * or flush with the lower layer's side (which fills none of them), at least one inside. At a
 * convex corner between two sides inside the layer below fills the cell across the corner too;
 * where a side inside meets a flush one it does not (the lower layer's side runs on past the
 * corner under the flush side), and the corner's upright must be rounded: a standing corner,
 * where the fillet ends against the lower layer's top rim in a piece of torus (returns 2: the
 * foot is filleted only when that rim is rounded, cap_pieces); where two flush sides meet the
 * upright runs on down. At a concave corner both sides are inside (the two fillets meet in an
 * eighth of a sphere round a rounded upright, in a mitre at a sharp one) or both flush. Returns 1
 * for a foot with no standing corner. */
static int foot_filleted(const struct cube_layers *layers, const unsigned char *covered,
                                  const unsigned char *soft, const int *piece, int start, int layer, int i0, int i1,
                                  int j0, int j1)
{
  if (layer == 0) return 0;
  int inside = 0, standing = 0;
  for (int j = j0 - 1; j <= j1 + 1; ++j)
    for (int i = i0 - 1; i <= i1 + 1; ++i) {
      if (in_piece(layers, piece, start, i, j)) {
        if (!cube_layers_filled(layers, layer - 1, i, j)) return 0;
        /* Its sides on the outline inside the lower layer's top: the foot's edges there hard. */
        const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (int n = 0; n < 4; ++n) {
          const int ni = next[n][0], nj = next[n][1];
          if (in_piece(layers, piece, start, ni, nj) || !cube_layers_filled(layers, layer - 1, ni, nj)) continue;
          const int along_x = n >= 2;
          if (!rim_hard(covered, soft, layers, along_x, layer, n == 1 ? i + 1 : i, n == 3 ? j + 1 : j)) return 0;
          ++inside;
        }
        continue;
      }
      int touches = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) touches |= in_piece(layers, piece, start, i + di, j + dj);
      if (touches && cube_layers_filled(layers, layer, i, j)) return 0;
    }
  if (inside == 0) return 0;
  for (int gj = j0; gj <= j1 + 1; ++gj)
    for (int gi = i0; gi <= i1 + 1; ++gi) {
      const int cells[4][2] = {{gi - 1, gj - 1}, {gi, gj - 1}, {gi - 1, gj}, {gi, gj}};
      int around = 0, odd = -1;
      for (int c = 0; c < 4; ++c) around += in_piece(layers, piece, start, cells[c][0], cells[c][1]);
      if (around == 2) {
        if (in_piece(layers, piece, start, gi - 1, gj - 1) == in_piece(layers, piece, start, gi, gj))
          return 0; /* two cells meeting at a corner only */
        /* Along a straight side: inside the lower layer's top on both sides of the point, or flush
         * on both (the lower layer's side does not end in the middle of the foot's side). */
        int below = 0;
        for (int c = 0; c < 4; ++c)
          if (!in_piece(layers, piece, start, cells[c][0], cells[c][1]))
            below += cube_layers_filled(layers, layer - 1, cells[c][0], cells[c][1]);
        if (below == 1) return 0;
        continue;
      }
      if (around != 1) continue;
      for (int c = 0; c < 4; ++c)
        if (in_piece(layers, piece, start, cells[c][0], cells[c][1])) odd = c;
      /* The cells beside the corner's cell along x and along z, and the one across the corner. */
      const int beside_x = odd ^ 1, beside_z = odd ^ 2, across = odd ^ 3;
      const int fx = cube_layers_filled(layers, layer - 1, cells[beside_x][0], cells[beside_x][1]);
      const int fz = cube_layers_filled(layers, layer - 1, cells[beside_z][0], cells[beside_z][1]);
      if (cube_layers_filled(layers, layer - 1, cells[across][0], cells[across][1]) != (fx && fz)) return 0;
      if (fx != fz) {
        if (!cube_layers_rounded(layers, layer, gi, gj)) return 0;
        standing = 1;
      }
    }
  return 1 + standing;
}

/* A piece of a layer's footprint (its cells joined side to side), as cap_pieces sees it. */
struct footprint_piece {
  int layer, first, count; /* its cells: members[first .. first + count - 1] */
  int top_possible;        /* outlined by loops with its concave corners' uprights rounded,
                              every edge along its top rim (but under a layer standing on it) hard */
  int bottom_capped;       /* the same below, with nothing below it */
  int foot;                /* foot_filleted */
  int below;               /* with a foot, the piece of the layer below under it */
  int top_capped, foot_filleted; /* found by cap_pieces */
};

/* Which cells have their top or bottom rim rounded or their foot filleted (cube_layers.h): each
 * piece of a layer's footprint outlined by loops (a rectangle, an L, a ring, ...) with every concave
 * corner's upright rounded, every edge along its top (bottom) rim hard and nothing below it (for
 * its bottom rim) or, above it, only pieces whose feet are filleted (for its top rim: its rim
 * then runs along its sides where nothing stands, and ends where a flush side of a piece on it
 * meets a filleted one); and each foot foot_filleted finds, when it ends against no rim or
 * against the rounded top rim of the piece under it. Since a foot ending against a rim needs it
 * rounded and a rim under pieces needs their feet filleted, both are first taken as possible and
 * then given up in turn until every one left has what it needs. */
static int cap_pieces(const struct wings_mesh *mesh, struct cube_layers *layers, const int *place)
{
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  const size_t cells = (size_t)cells_x * (size_t)cells_z;
  /* Whether every edge along the grid segment from (i, j) to (i + 1, j) (rim_x) or to (i, j + 1)
   * (rim_z) at height `level` is hard, and whether there is one, in the slots rim_slot gives. */
  const size_t points = (size_t)layers->x_count * (size_t)layers->z_count;
  const size_t levels = (size_t)layers->layer_count + 1;
  const size_t all_cells = (size_t)layers->layer_count * cells;
  unsigned char *covered = calloc(2 * levels * points + 1, 1), *soft = calloc(2 * levels * points + 1, 1);
  int *piece = malloc(all_cells * sizeof *piece + 1), *stack = malloc(cells * sizeof *stack + 1);
  int *members = malloc(all_cells * sizeof *members + 1);
  struct footprint_piece *pieces = malloc(all_cells * sizeof *pieces + 1);
  layers->capped = calloc(all_cells + 1, 1);
  int ok = covered && soft && piece && stack && members && pieces && layers->capped;
  for (long e = 0; ok && e < mesh->edge_count; ++e) {
    const int *a = &place[3 * mesh->edges[e].vs], *b = &place[3 * mesh->edges[e].ve];
    int along_x, from, to;
    if (!horizontal_segment(a, b, &along_x, &from, &to)) continue;
    for (int c = from; c < to; ++c) {
      const size_t at = rim_slot(layers, along_x, a[1], along_x ? c : a[0], along_x ? a[2] : c);
      covered[at] = 1;
      soft[at] |= (unsigned char)!mesh->hard[e];
    }
  }
  int piece_count = 0, member_count = 0;
  for (size_t c = 0; ok && c < all_cells; ++c) piece[c] = -1;
  for (int k = 0; ok && k < layers->layer_count; ++k) {
    int *layer_piece = piece + (size_t)k * cells;
    for (int start = 0; start < (int)cells; ++start) {
      if (layer_piece[start] >= 0 || !cube_layers_filled(layers, k, start % cells_x, start / cells_x)) continue;
      /* The piece of the footprint through cell `start`, its bounds and whether anything is below it. */
      struct footprint_piece *p = &pieces[piece_count];
      int top = 0, i0 = cells_x, i1 = -1, j0 = cells_z, j1 = -1, covered_below = 0;
      p->layer = k, p->first = member_count, p->count = 0;
      stack[top++] = start;
      layer_piece[start] = piece_count;
      while (top > 0) {
        const int c = stack[--top], i = c % cells_x, j = c / cells_x;
        members[member_count++] = c;
        ++p->count;
        i0 = i < i0 ? i : i0, i1 = i > i1 ? i : i1, j0 = j < j0 ? j : j0, j1 = j > j1 ? j : j1;
        covered_below |= cube_layers_filled(layers, k - 1, i, j);
        const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (int n = 0; n < 4; ++n) {
          const int ni = next[n][0], nj = next[n][1];
          if (!cube_layers_filled(layers, k, ni, nj) || layer_piece[nj * cells_x + ni] >= 0) continue;
          layer_piece[nj * cells_x + ni] = piece_count;
          stack[top++] = nj * cells_x + ni;
        }
      }
      const int loop = loops_round_fillets(layers, layer_piece, piece_count, k, i0, i1, j0, j1);
      for (int side = 0; side < 2; ++side) {
        /* side 0: the top rim, at level k + 1; side 1: the bottom's. Every side of a cell with no
         * cell of the layer beside it is on the rim, but at the top where a cell of the layer
         * above stands on the cell (its wall runs on down there). */
        const int level = side ? k : k + 1;
        int capped = loop && !(side && covered_below);
        for (int m = 0; capped && m < p->count; ++m) {
          const int i = members[p->first + m] % cells_x, j = members[p->first + m] / cells_x;
          const int under = !side && cube_layers_filled(layers, k + 1, i, j);
          capped = (under || cube_layers_filled(layers, k, i - 1, j) || rim_hard(covered, soft, layers, 0, level, i, j)) &&
                   (under || cube_layers_filled(layers, k, i + 1, j) || rim_hard(covered, soft, layers, 0, level, i + 1, j)) &&
                   (under || cube_layers_filled(layers, k, i, j - 1) || rim_hard(covered, soft, layers, 1, level, i, j)) &&
                   (under || cube_layers_filled(layers, k, i, j + 1) || rim_hard(covered, soft, layers, 1, level, i, j + 1));
        }
        if (side) p->bottom_capped = capped;
        else p->top_possible = capped;
      }
      p->foot = foot_filleted(layers, covered, soft, layer_piece, piece_count, k, i0, i1, j0, j1);
      p->below = p->foot ? piece[(size_t)(k - 1) * cells + (size_t)members[p->first]] : -1;
      p->top_capped = p->top_possible;
      p->foot_filleted = p->foot != 0;
      ++piece_count;
    }
  }
  for (int changed = ok; changed;) {
    changed = 0;
    for (int n = 0; n < piece_count; ++n) {
      struct footprint_piece *p = &pieces[n];
      for (int m = 0; p->top_capped && m < p->count; ++m) {
        const int above = p->layer + 1 < layers->layer_count ? piece[(size_t)(p->layer + 1) * cells + (size_t)members[p->first + m]] : -1;
        if (above >= 0 && !pieces[above].foot_filleted) p->top_capped = 0, changed = 1;
      }
      if (p->foot_filleted && p->foot == 2 && !pieces[p->below].top_capped) p->foot_filleted = 0, changed = 1;
    }
  }
  for (int n = 0; ok && n < piece_count; ++n) {
    const struct footprint_piece *p = &pieces[n];
    const unsigned char rims = (unsigned char)((p->top_capped ? CAPPED_TOP : 0) | (p->bottom_capped ? CAPPED_BOTTOM : 0) |
                                               (p->foot_filleted ? FILLETED_FOOT : 0));
    for (int m = 0; m < p->count; ++m) layers->capped[(size_t)p->layer * cells + (size_t)members[p->first + m]] = rims;
  }
  free(covered);
  free(soft);
  free(piece);
  free(stack);
  free(members);
  free(pieces);
  return ok;
}

/* Which uprights are rounded in each layer, and how many hard edges stay sharp. */
static int mark_hard_edges(const struct wings_mesh *mesh, struct cube_layers *layers, const int *place,
                           const int *face_axis, const int *face_level, char *error, size_t size)
{
  const size_t points = (size_t)layers->x_count * (size_t)layers->z_count;
  const size_t all = (size_t)layers->layer_count * points;
  unsigned char *covered = calloc(all + 1, 1), *soft = calloc(all + 1, 1);
  if (!covered || !soft) {
    free(covered);
    free(soft);
    return wings_failed(error, size, "out of memory");
  }
  /* An upright line of a layer is rounded when every edge along it is hard. */
  for (long e = 0; e < mesh->edge_count; ++e) {
    const struct winged_edge *edge = &mesh->edges[e];
    const int *a = &place[3 * edge->vs], *b = &place[3 * edge->ve];
    if (a[0] != b[0] || a[2] != b[2]) continue;
    const size_t point = (size_t)a[2] * (size_t)layers->x_count + (size_t)a[0];
    for (int k = a[1] < b[1] ? a[1] : b[1]; k < (a[1] < b[1] ? b[1] : a[1]); ++k) {
      covered[(size_t)k * points + point] = 1;
      soft[(size_t)k * points + point] |= (unsigned char)!mesh->hard[e];
    }
  }
  for (int k = 0; k < layers->layer_count; ++k)
    for (int j = 0; j < layers->z_count; ++j)
      for (int i = 0; i < layers->x_count; ++i) {
        int diagonal;
        const int around = cells_around(layers, k, i, j, &diagonal);
        const size_t at = (size_t)k * points + (size_t)j * (size_t)layers->x_count + (size_t)i;
        layers->rounded[at] = (around == 1 || around == 3) && covered[at] && !soft[at];
      }
  free(covered);
  free(soft);
  if (!cap_pieces(mesh, layers, place)) return wings_failed(error, size, "out of memory");
  /* A hard edge between faces in different planes is a crease: rounded when it is upright and
   * rounded in every layer it runs through, or along a capped piece's top or bottom rim, else left
   * sharp. */
  for (long e = 0; e < mesh->edge_count; ++e) {
    const struct winged_edge *edge = &mesh->edges[e];
    if (!mesh->hard[e]) continue;
    if (face_axis[edge->lf] == face_axis[edge->rf] && face_level[edge->lf] == face_level[edge->rf]) continue;
    const int *a = &place[3 * edge->vs], *b = &place[3 * edge->ve];
    int rounded = a[0] == b[0] && a[2] == b[2];
    for (int k = a[1] < b[1] ? a[1] : b[1]; rounded && k < (a[1] < b[1] ? b[1] : a[1]); ++k)
      rounded = cube_layers_rounded(layers, k, a[0], a[2]);
    int along_x, from, to;
    if (horizontal_segment(a, b, &along_x, &from, &to)) {
      /* Along x or z at a height: on a capped rim when every cell it runs beside is capped on one
       * side of it, as the top of the layer below or the bottom of the layer above, or along a
       * filleted foot of the layer above. */
      for (int side = 0; side < 3 && !rounded; ++side) {
        const int k = side ? a[1] : a[1] - 1, bit = side == 2 ? FILLETED_FOOT : side ? CAPPED_BOTTOM : CAPPED_TOP;
        rounded = 1;
        for (int c = from; rounded && c < to; ++c)
          rounded = along_x ? (cube_layers_capped(layers, k, c, a[2]) & bit) != (cube_layers_capped(layers, k, c, a[2] - 1) & bit)
                            : (cube_layers_capped(layers, k, a[0], c) & bit) != (cube_layers_capped(layers, k, a[0] - 1, c) & bit);
      }
    }
    layers->sharp_hard_edges += !rounded;
  }
  return 1;
}

int cube_layers_from_mesh(const struct wings_mesh *mesh, struct cube_layers *layers, char *error, size_t size)
{
  memset(layers, 0, sizeof *layers);
  double extent = 0;
  for (long v = 0; v < mesh->vertex_count; ++v)
    for (int axis = 0; axis < 3; ++axis) extent = fmax(extent, fabs(mesh->position[v][axis]));
  const double tolerance = 1e-9 * fmax(extent, 1e-300);
  int *place = malloc(3 * (size_t)mesh->vertex_count * sizeof *place + 1);
  /* Each face's plane: the axis along which all its vertices lie on one grid line, and that line. */
  int *face_axis = malloc((size_t)mesh->face_count * sizeof *face_axis + 1);
  int *face_level = malloc((size_t)mesh->face_count * sizeof *face_level + 1);
  int *low = malloc(3 * (size_t)mesh->face_count * sizeof *low + 1);
  int *high = malloc(3 * (size_t)mesh->face_count * sizeof *high + 1);
  int ok = place && face_axis && face_level && low && high ? 1 : wings_failed(error, size, "out of memory");
  int counts[3] = {0, 0, 0};
  double *lines[3] = {NULL, NULL, NULL};
  for (int axis = 0; ok && axis < 3; ++axis) {
    counts[axis] = grid_lines(mesh, axis, tolerance, &lines[axis], place);
    if (counts[axis] < 0) ok = wings_failed(error, size, "out of memory");
  }
  layers->x = lines[0], layers->height = lines[1], layers->z = lines[2];
  layers->x_count = counts[0], layers->z_count = counts[2], layers->layer_count = counts[1] - 1;
  for (int axis = 0; ok && axis < 3; ++axis)
    if (counts[axis] < 2)
      ok = wings_failed(error, size, "object 1 is flat: all its vertices have %c %g (an object made of cubes is "
                        "expected)", "xyz"[axis], lines[axis][0]);
  for (long f = 0; ok && f < mesh->face_count; ++f)
    for (int axis = 0; axis < 3; ++axis) low[3 * f + axis] = counts[axis], high[3 * f + axis] = -1;
  for (long e = 0; ok && e < mesh->edge_count; ++e) {
    const struct winged_edge *edge = &mesh->edges[e];
    int along = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const int a = place[3 * edge->vs + axis], b = place[3 * edge->ve + axis];
      along += a != b;
      for (int side = 0; side < 2; ++side) {
        const long f = side ? edge->rf : edge->lf;
        if (a < low[3 * f + axis]) low[3 * f + axis] = a;
        if (b < low[3 * f + axis]) low[3 * f + axis] = b;
        if (a > high[3 * f + axis]) high[3 * f + axis] = a;
        if (b > high[3 * f + axis]) high[3 * f + axis] = b;
      }
    }
    if (along != 1)
      ok = wings_failed(error, size, "object 1, edge %ld: not along the x, y or z axis (an object made of cubes "
                        "is expected)", e);
    else if (edge->lf == edge->rf)
      ok = wings_failed(error, size, "object 1, edge %ld: face %ld on both of its sides (a closed object is "
                        "expected)", e, edge->lf);
  }
  for (long f = 0; ok && f < mesh->face_count; ++f) {
    face_axis[f] = -1;
    face_level[f] = 0;
    for (int axis = 2; axis >= 0; --axis)
      if (low[3 * f + axis] == high[3 * f + axis]) face_axis[f] = axis, face_level[f] = low[3 * f + axis];
    if (face_axis[f] < 0 && high[3 * f] >= 0)
      ok = wings_failed(error, size, "object 1, face %ld: not in a plane x, y or z = constant (an object made of "
                        "cubes is expected)", f);
  }
  const size_t cells = (size_t)(counts[0] - 1) * (size_t)(counts[2] - 1) * (size_t)(counts[1] - 1);
  const size_t points = (size_t)counts[0] * (size_t)counts[2] * (size_t)(counts[1] - 1);
  if (ok) {
    layers->filled = calloc(cells + 1, 1);
    layers->rounded = calloc(points + 1, 1);
    if (!layers->filled || !layers->rounded) ok = wings_failed(error, size, "out of memory");
  }
  if (ok) ok = fill_cells(mesh, layers, place, face_axis, face_level, error, size);
  int any = 0;
  for (size_t c = 0; ok && c < cells; ++c) any |= layers->filled[c];
  if (ok && !any) ok = wings_failed(error, size, "object 1 encloses no cube");
  for (int k = 0; ok && k < layers->layer_count; ++k)
    for (int j = 1; ok && j + 1 < layers->z_count; ++j)
      for (int i = 1; ok && i + 1 < layers->x_count; ++i) {
        int diagonal;
        cells_around(layers, k, i, j, &diagonal);
        if (diagonal)
          ok = wings_failed(error, size, "object 1: between heights %g and %g its cubes meet only along the "
                            "upright line at x %g, z %g", layers->height[k], layers->height[k + 1], layers->x[i],
                            layers->z[j]);
      }
  if (ok) ok = mark_hard_edges(mesh, layers, place, face_axis, face_level, error, size);
  if (ok) {
    layers->max_radius = INFINITY;
    for (int i = 0; i + 1 < layers->x_count; ++i)
      layers->max_radius = fmin(layers->max_radius, (layers->x[i + 1] - layers->x[i]) / 2);
    for (int j = 0; j + 1 < layers->z_count; ++j)
      layers->max_radius = fmin(layers->max_radius, (layers->z[j + 1] - layers->z[j]) / 2);
    /* A filleted foot and a rounded top rim share the layer's height, its wall between them
     * (none at the largest radius); so do the top and bottom rims of a piece that fillets end
     * against (which must stay rounded while the fillets are). */
    const size_t footprint_cells = (size_t)(layers->x_count - 1) * (size_t)(layers->z_count - 1);
    for (int k = 0; k < layers->layer_count; ++k)
      for (size_t c = 0; c < footprint_cells; ++c) {
        const int capped = layers->capped[(size_t)k * footprint_cells + c];
        const int under_fillet = (capped & CAPPED_TOP) && k + 1 < layers->layer_count &&
                                 layers->filled[(size_t)(k + 1) * footprint_cells + c];
        if (!(capped & FILLETED_FOOT) && !under_fillet) continue;
        const int rims = !!(capped & FILLETED_FOOT) + !!(capped & CAPPED_TOP) + !!(capped & CAPPED_BOTTOM);
        const double room = (layers->height[k + 1] - layers->height[k]) / rims;
        if (room < layers->max_radius) layers->max_radius = room, layers->radius_limited_by_fillet = 1;
      }
  }
  free(place);
  free(face_axis);
  free(face_level);
  free(low);
  free(high);
  if (!ok) cube_layers_free(layers);
  return ok;
}

void cube_layers_free(struct cube_layers *layers)
{
  free(layers->x);
  free(layers->z);
  free(layers->height);
  free(layers->filled);
  free(layers->rounded);
  free(layers->capped);
  memset(layers, 0, sizeof *layers);
}
