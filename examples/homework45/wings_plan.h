/* The object of a Wings3D file (.wings) as the homework draws it: a solid made of cubes standing
 * on the floor, that is a floor plan (a polygon with right-angled corners) raised from a bottom
 * to a top height (one layer of cubes, or layers alike), with the edges marked hard in Wings3D
 * (its "hard edges") to be rounded: the upright edges at the plan's corners, and the edges
 * around the top. */
#ifndef HOMEWORK45_WINGS_PLAN_H
#define HOMEWORK45_WINGS_PLAN_H

#include <stddef.h>

#include "wings_mesh.h"

/* One loop of the outline of the top: the outer outline, or a hole's. */
struct plan_loop {
  int corners;        /* its corners, collinear vertices left out but where the rim's hardness
                         changes (straight) */
  double (*xz)[2];    /* x, z of each corner, in the order of a walk with the solid on its left
                         seen from above (+y): the outer outline counter-clockwise, a hole's
                         clockwise */
  int *rounded;       /* whether the upright edges at each corner are hard */
  int *convex;        /* whether the solid's angle at the corner is 90 degrees (else 270, or 180
                         where straight) */
  int *straight;      /* whether the outline goes straight on at the corner: a vertex in the
                         middle of a side where its rim's hardness changes, so that the side's
                         hard stretch is a side of its own, rounded, and the rest another */
  int *top_hard;      /* whether every edge along the top of side i (from corner i to
                         corner i + 1) is hard: that stretch of the top's rim is rounded */
  int *bottom_hard;   /* the same along the bottom of side i */
};

struct floor_plan {
  int loop_count;
  struct plan_loop *loops; /* the outline's loops: one, or more round holes (a ring of cubes) */
  double bottom, top; /* heights */
  double min_x, max_x, min_z, max_z;
  double max_radius;  /* half the outline's shortest side (and of the height, with a rim
                         rounded) */
  int sharp_hard_edges; /* hard edges this program leaves sharp: uprights hard only in part, and
                           rim edges along no side's edge */
};

/* The plan of a mesh's object. Its vertices must lie at its bottom or its top unless
 * `layers_alike` says that the object, cut at the heights of its vertices, has the same footprint
 * in every layer (cube_layers.h): then it is the same solid, its sides split by edges that round
 * nothing. Returns 0 and writes the reason into `error` when the object is not such a solid. */
int floor_plan_from_mesh(const struct wings_mesh *mesh, int layers_alike, struct floor_plan *plan, char *error,
                         size_t error_size);
void floor_plan_free(struct floor_plan *plan);

#endif
