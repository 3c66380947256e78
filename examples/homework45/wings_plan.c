/* The homework's object of one layer of cubes (or of layers alike), from a Wings3D mesh
 * (wings_mesh.c): the outline of its top, its corners and which of its edges are hard. */
#include "wings_plan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The outline of the top faces (those with every vertex at the top), walked along their edges
 * that border a face which is not on top, in one loop or several (round holes): *outline_next
 * gets the vertex after each one of it (-1 elsewhere), *loop_starts a vertex of each loop and
 * *loop_count their number, for the caller to free. */
static int trace_outline(const struct wings_mesh *o, struct floor_plan *plan, char *error, size_t size,
                         long **outline_next, long **loop_starts, int *loop_count)
{
  const double extent = fmax(plan->top - plan->bottom, 1e-300);
  const double tolerance = 1e-9 * extent;
  int *on_top = malloc((size_t)o->face_count * sizeof *on_top + 1);
  long *next = malloc((size_t)o->vertex_count * sizeof *next + 1);
  if (!on_top || !next) {
    free(on_top);
    free(next);
    return wings_failed(error, size, "out of memory");
  }
  for (long f = 0; f < o->face_count; ++f) on_top[f] = 1;
  for (long v = 0; v < o->vertex_count; ++v) next[v] = -1;
  for (long e = 0; e < o->edge_count; ++e) {
    const struct winged_edge *edge = &o->edges[e];
    const int top = fabs(o->position[edge->vs][1] - plan->top) <= tolerance &&
                    fabs(o->position[edge->ve][1] - plan->top) <= tolerance;
    if (!top) on_top[edge->lf] = on_top[edge->rf] = 0;
  }
  long start = -1;
  int ok = 1;
  for (long e = 0; e < o->edge_count && ok; ++e) {
    const struct winged_edge *edge = &o->edges[e];
    if (on_top[edge->lf] == on_top[edge->rf]) continue;
    const long from = on_top[edge->lf] ? edge->vs : edge->ve, to = on_top[edge->lf] ? edge->ve : edge->vs;
    if (next[from] >= 0)
      ok = wings_failed(error, size, "object 1: the outline of its top passes vertex %ld twice", from);
    next[from] = to;
    start = from;
  }
  free(on_top);
  if (ok && start < 0) ok = wings_failed(error, size, "object 1 has no top faces");
  /* Each loop walked once round: every outline vertex has one edge out (checked above) and must
   * come back to where its loop began without meeting another loop's vertex. */
  long *starts = malloc((size_t)o->vertex_count * sizeof *starts + 1);
  unsigned char *walked = calloc((size_t)o->vertex_count + 1, 1);
  if (ok && (!starts || !walked)) ok = wings_failed(error, size, "out of memory");
  int loops = 0;
  /* The first loop from the vertex the last outline edge leaves (where a single loop always
   * began), the others from their lowest vertex. */
  for (long k = -1; ok && k < o->vertex_count; ++k) {
    const long first = k < 0 ? start : k;
    if (first < 0 || next[first] < 0 || walked[first]) continue;
    starts[loops++] = first;
    for (long v = first; ok;) {
      walked[v] = 1;
      v = next[v];
      if (v < 0 || (walked[v] && v != first)) ok = wings_failed(error, size, "object 1: the outline of its top does not close");
      else if (v == first) break;
    }
  }
  free(walked);
  /* Loops that touch (cubes meeting along an upright edge only) or a loop that touches itself
   * would be drawn as solids that meet in a line: not a plan this program rounds. */
  for (long v = 0; ok && v < o->vertex_count; ++v)
    for (long w = v + 1; ok && next[v] >= 0 && w < o->vertex_count; ++w)
      if (next[w] >= 0 && o->position[v][0] == o->position[w][0] && o->position[v][2] == o->position[w][2])
        ok = wings_failed(error, size, "object 1: the outline of its top touches itself at vertices %ld and %ld", v, w);
  if (!ok) {
    free(next);
    free(starts);
    return 0;
  }
  *outline_next = next;
  *loop_starts = starts;
  *loop_count = loops;
  return 1;
}

/* The corners of the outline's loop through `start`, into *plan: its vertices where it turns, and
 * those where it goes straight on but the rim's hardness changes (rim_kind[v]: the kind of the
 * rim edges along the outline edge from v to next[v], at the top and the bottom), so that a side
 * hard only in part is two sides, one rounded, one not; side[v] gets first_side + the side
 * (corner k to corner k + 1) of each of the loop's vertices' edges. */
static int find_corners(const struct wings_mesh *o, struct plan_loop *plan, const long *next, long start,
                        const int *rim_kind, char *error, size_t size, long *side, long first_side)
{
  long loop = 0;
  for (long v = start;;) {
    ++loop;
    v = next[v];
    if (v == start) break;
  }
  plan->xz = calloc((size_t)loop, sizeof *plan->xz);
  plan->rounded = calloc((size_t)loop, sizeof *plan->rounded);
  plan->convex = calloc((size_t)loop, sizeof *plan->convex);
  plan->straight = calloc((size_t)loop, sizeof *plan->straight);
  plan->top_hard = calloc((size_t)loop, sizeof *plan->top_hard);
  plan->bottom_hard = calloc((size_t)loop, sizeof *plan->bottom_hard);
  long *corner_vertex = calloc((size_t)loop, sizeof *corner_vertex);
  if (!plan->xz || !plan->rounded || !plan->convex || !plan->straight || !plan->top_hard || !plan->bottom_hard ||
      !corner_vertex) {
    free(corner_vertex);
    return wings_failed(error, size, "out of memory");
  }
  long v = start;
  for (long k = 0; k < loop; ++k) {
    const long before = v, here = next[v], after = next[next[v]];
    v = here;
    const double ax = o->position[here][0] - o->position[before][0], az = o->position[here][2] - o->position[before][2];
    const double bx = o->position[after][0] - o->position[here][0], bz = o->position[after][2] - o->position[here][2];
    const double turn = ax * bz - az * bx, along = ax * bx + az * bz;
    const double scale = hypot(ax, az) * hypot(bx, bz);
    const int straight = fabs(turn) <= 1e-9 * scale && along > 0;
    if (straight && rim_kind[before] == rim_kind[here]) continue; /* straight on */
    if (!straight && fabs(along) > 1e-9 * scale)
      return free(corner_vertex),
             wings_failed(error, size, "object 1: its outline turns at vertex %ld by an angle other than 90 degrees",
                          here);
    corner_vertex[plan->corners] = here;
    plan->xz[plan->corners][0] = o->position[here][0];
    plan->xz[plan->corners][1] = o->position[here][2];
    plan->convex[plan->corners] = !straight && turn > 0; /* turning left in (x, z); made "convex" below */
    plan->straight[plan->corners] = straight;
    ++plan->corners;
  }
  /* The side of each outline edge, named by the vertex it leaves: the corners come in the
   * order of the walk. */
  v = corner_vertex[0];
  for (long k = 0, c = 0, current = 0; k < loop && plan->corners > 0; ++k) {
    if (c < plan->corners && v == corner_vertex[c]) current = c++;
    side[v] = first_side + current;
    v = next[v];
  }
  free(corner_vertex);
  return 1;
}

int floor_plan_from_mesh(const struct wings_mesh *mesh, int layers_alike, struct floor_plan *plan, char *error,
                         size_t error_size)
{
  memset(plan, 0, sizeof *plan);
  const struct wings_mesh object = *mesh;
  int ok = 1;
  if (ok) {
    plan->bottom = plan->top = object.position[0][1];
    plan->min_x = plan->max_x = object.position[0][0];
    plan->min_z = plan->max_z = object.position[0][2];
    for (long v = 0; v < object.vertex_count; ++v) {
      plan->bottom = fmin(plan->bottom, object.position[v][1]);
      plan->top = fmax(plan->top, object.position[v][1]);
      plan->min_x = fmin(plan->min_x, object.position[v][0]);
      plan->max_x = fmax(plan->max_x, object.position[v][0]);
      plan->min_z = fmin(plan->min_z, object.position[v][2]);
      plan->max_z = fmax(plan->max_z, object.position[v][2]);
    }
  }
  /* A solid standing upright: every vertex at the bottom or the top (or, with layers alike, in
   * between), above or below another. */
  const double tolerance = 1e-9 * fmax(plan->top - plan->bottom, 1e-300);
  for (long v = 0; ok && v < object.vertex_count; ++v) {
    const double *p = object.position[v];
    if (!layers_alike && fabs(p[1] - plan->bottom) > tolerance && fabs(p[1] - plan->top) > tolerance) {
      ok = wings_failed(error, error_size, "object 1, vertex %ld: at height %g, between the bottom %g and the top %g "
                        "(a solid made of one layer of cubes is expected)", v, p[1], plan->bottom, plan->top);
      break;
    }
    int twin = 0;
    for (long w = 0; w < object.vertex_count && !twin; ++w)
      twin = w != v && object.position[w][0] == p[0] && object.position[w][2] == p[2] &&
             fabs(object.position[w][1] - p[1]) > tolerance;
    if (!twin) ok = wings_failed(error, error_size, "object 1, vertex %ld: no vertex above or below it (the object "
                                 "does not stand upright)", v);
  }
  long *outline_next = NULL, *loop_starts = NULL;
  int loop_count = 0;
  if (ok) ok = trace_outline(&object, plan, error, error_size, &outline_next, &loop_starts, &loop_count);
  /* Per outline vertex v, the rim edges along the outline edge from v to next[v] and the hard
   * ones among them, at the top ([0], [1]) and at the bottom ([2], [3]); and the kind of that
   * stretch of rim: bit 0 when its top edges are all hard, bit 1 its bottom's. */
  long *rim_counts = NULL, *top_twin = NULL, *outline_side = NULL;
  int *rim_kind = NULL, *on_bottom = NULL;
  if (ok) {
    rim_counts = calloc(4 * (size_t)object.vertex_count + 1, sizeof *rim_counts);
    rim_kind = calloc((size_t)object.vertex_count + 1, sizeof *rim_kind);
    top_twin = malloc((size_t)object.vertex_count * sizeof *top_twin + 1);
    outline_side = malloc((size_t)object.vertex_count * sizeof *outline_side + 1);
    /* The bottom's rim: edges along the bottom between a bottom face and a side face (one
     * layer of cubes: a side face has vertices at the top too). */
    on_bottom = calloc((size_t)object.face_count + 1, sizeof *on_bottom);
    plan->loops = calloc((size_t)loop_count + 1, sizeof *plan->loops);
    if (!rim_counts || !rim_kind || !top_twin || !outline_side || !on_bottom || !plan->loops)
      ok = wings_failed(error, error_size, "out of memory");
    else
      plan->loop_count = loop_count;
  }
  for (long f = 0; ok && f < object.face_count; ++f) on_bottom[f] = 1;
  for (long e = 0; ok && e < object.edge_count; ++e) {
    const struct winged_edge *edge = &object.edges[e];
    if (fabs(object.position[edge->vs][1] - plan->bottom) > tolerance ||
        fabs(object.position[edge->ve][1] - plan->bottom) > tolerance)
      on_bottom[edge->lf] = on_bottom[edge->rf] = 0;
  }
  /* The outline vertex above each vertex (itself on the outline), -1 where there is none. */
  for (long v = 0; ok && v < object.vertex_count; ++v) {
    top_twin[v] = -1;
    outline_side[v] = -1;
    for (long w = 0; w < object.vertex_count && top_twin[v] < 0; ++w)
      if (outline_next[w] >= 0 && object.position[w][0] == object.position[v][0] &&
          object.position[w][2] == object.position[v][2])
        top_twin[v] = w;
  }
  for (long e = 0; ok && e < object.edge_count; ++e) {
    const struct winged_edge *edge = &object.edges[e];
    const int rim = outline_next[edge->vs] == edge->ve || outline_next[edge->ve] == edge->vs;
    const int bottom_rim = !rim && on_bottom[edge->lf] != on_bottom[edge->rf];
    if (!rim && !bottom_rim) continue;
    /* The outline edge it is (or lies below), named by the vertex it leaves. */
    const long a = rim ? edge->vs : top_twin[edge->vs], b = rim ? edge->ve : top_twin[edge->ve];
    long at = -1;
    if (a >= 0 && b >= 0) at = outline_next[a] == b ? a : outline_next[b] == a ? b : -1;
    const int hard = object.hard[e];
    if (at < 0) {
      /* (Not below an outline edge: no side to round it along.) */
      plan->sharp_hard_edges += hard;
      continue;
    }
    rim_counts[4 * at + (bottom_rim ? 2 : 0)] += 1;
    rim_counts[4 * at + (bottom_rim ? 2 : 0) + 1] += hard;
  }
  for (long v = 0; ok && v < object.vertex_count; ++v)
    for (int level = 0; level < 2; ++level) {
      const long edges = rim_counts[4 * v + 2 * level], hard = rim_counts[4 * v + 2 * level + 1];
      rim_kind[v] |= (hard > 0 && hard == edges) << level;
    }
  /* The loops' corners; their sides numbered on from loop to loop (first_side). */
  long *first_side = calloc((size_t)loop_count + 1, sizeof *first_side);
  if (ok && !first_side) ok = wings_failed(error, error_size, "out of memory");
  long sides = 0;
  for (int l = 0; ok && l < loop_count; ++l) {
    struct plan_loop *loop = &plan->loops[l];
    first_side[l] = sides;
    ok = find_corners(&object, loop, outline_next, loop_starts[l], rim_kind, error, error_size, outline_side, sides);
    sides += loop->corners;
    int turns = 0;
    for (int i = 0; ok && i < loop->corners; ++i) turns += !loop->straight[i];
    if (ok && turns < 4) ok = wings_failed(error, error_size, "object 1: a loop of its outline has %d corners", turns);
  }
  if (ok) {
    /* With the solid on the left of every walk seen from above the signed areas in (z, x) add up
     * to the top's, which is positive (the outer loops' positive, the holes' negative); the trace
     * walks every loop the same way round, so all are reversed or none. */
    double area = 0;
    for (int l = 0; l < loop_count; ++l) {
      const struct plan_loop *loop = &plan->loops[l];
      for (int i = 0; i < loop->corners; ++i) {
        const double *a = loop->xz[i], *b = loop->xz[(i + 1) % loop->corners];
        area += a[1] * b[0] - b[1] * a[0];
      }
    }
    /* Walked with the solid on its left, the outline turns right in (x, z) at its convex
     * corners; reversing the walk turns every left turn into a right one. */
    const int reversed = area < 0;
    for (int l = 0; l < loop_count; ++l) {
      struct plan_loop *loop = &plan->loops[l];
      if (reversed) {
        for (int i = 0, j = loop->corners - 1; i < j; ++i, --j) {
          double x = loop->xz[i][0], z = loop->xz[i][1];
          int left = loop->convex[i], straight = loop->straight[i];
          loop->xz[i][0] = loop->xz[j][0], loop->xz[i][1] = loop->xz[j][1], loop->convex[i] = loop->convex[j];
          loop->straight[i] = loop->straight[j];
          loop->xz[j][0] = x, loop->xz[j][1] = z, loop->convex[j] = left, loop->straight[j] = straight;
        }
      } else {
        for (int i = 0; i < loop->corners; ++i) loop->convex[i] = !loop->straight[i] && !loop->convex[i];
      }
    }
    plan->max_radius = INFINITY;
    for (int l = 0; l < loop_count; ++l) {
      const struct plan_loop *loop = &plan->loops[l];
      for (int i = 0; i < loop->corners; ++i) {
        const double *a = loop->xz[i], *b = loop->xz[(i + 1) % loop->corners];
        plan->max_radius = fmin(plan->max_radius, hypot(b[0] - a[0], b[1] - a[1]) / 2);
      }
    }
    /* Hard edges: uprights round their corner; those along the top (or the bottom) of a side
     * round that stretch of the rim when all of them there are hard; others stay sharp here.
     * Per side in the order of the walk (before any reversal): rim edges and hard ones, at the
     * top ([0]) and at the bottom ([1]). */
    long *counts = calloc(4 * (size_t)sides + 1, sizeof *counts);
    if (!counts) ok = wings_failed(error, error_size, "out of memory");
    for (long v = 0; ok && v < object.vertex_count; ++v)
      if (outline_side[v] >= 0)
        for (int c = 0; c < 4; ++c) counts[4 * outline_side[v] + c] += rim_counts[4 * v + c];
    int any_rim = 0;
    for (int l = 0; ok && l < loop_count; ++l) {
      struct plan_loop *loop = &plan->loops[l];
      const int n = loop->corners;
      /* An upright at a corner is rounded when every edge along it is hard (one edge in an
       * object of one layer, one per layer in an object of layers alike); one hard only in part
       * stays sharp. */
      int *uprights = calloc(2 * (size_t)n + 1, sizeof *uprights);
      if (!uprights) {
        ok = wings_failed(error, error_size, "out of memory");
        break;
      }
      for (long e = 0; e < object.edge_count; ++e) {
        const struct winged_edge *edge = &object.edges[e];
        const double *a = object.position[edge->vs], *b = object.position[edge->ve];
        const int upright = a[0] == b[0] && a[2] == b[2];
        for (int i = 0; i < n && upright; ++i)
          if (loop->xz[i][0] == a[0] && loop->xz[i][1] == a[2]) {
            uprights[2 * i] += 1;
            uprights[2 * i + 1] += object.hard[e];
          }
        /* (A hard upright in the middle of a straight side, or a hard edge between two top or
         * two bottom faces, or between two sides' faces one above the other, has nothing to
         * round.) */
      }
      for (int i = 0; i < n; ++i) {
        if (loop->straight[i]) continue;  /* where a side's rim changes: an upright there rounds nothing */
        loop->rounded[i] = uprights[2 * i + 1] > 0 && uprights[2 * i + 1] == uprights[2 * i];
        if (!loop->rounded[i]) plan->sharp_hard_edges += uprights[2 * i + 1];
      }
      free(uprights);
      for (int side = 0; side < n; ++side) {
        /* Reversing the corners' order turns side k (corner k to k + 1) into side n - 2 - k. */
        const int to = reversed ? (2 * n - 2 - side) % n : side;
        for (int level = 0; level < 2; ++level) {
          const long *c = &counts[4 * (first_side[l] + side) + 2 * level];
          const int whole = c[1] > 0 && c[1] == c[0];
          (level ? loop->bottom_hard : loop->top_hard)[to] = whole;
          if (!whole) plan->sharp_hard_edges += (int)c[1];
          any_rim |= whole;
        }
      }
    }
    /* Two rounded rims share the height; one takes at most half of it, as on a face's side. */
    if (any_rim) plan->max_radius = fmin(plan->max_radius, (plan->top - plan->bottom) / 2);
    free(counts);
  }
  free(first_side);
  free(rim_counts);
  free(rim_kind);
  free(top_twin);
  free(on_bottom);
  free(outline_next);
  free(outline_side);
  free(loop_starts);
  if (!ok) floor_plan_free(plan);
  return ok;
}

void floor_plan_free(struct floor_plan *plan)
{
  for (int l = 0; plan->loops && l < plan->loop_count; ++l) {
    struct plan_loop *loop = &plan->loops[l];
    free(loop->xz);
    free(loop->rounded);
    free(loop->convex);
    free(loop->straight);
    free(loop->top_hard);
    free(loop->bottom_hard);
  }
  free(plan->loops);
  plan->loops = NULL;
  plan->loop_count = 0;
}
