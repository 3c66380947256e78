/* Drawing the object of one floor plan raised (wings_plan.h), its outline one loop or several
 * (round holes): its hard upright edges rounded into quarter cylinders, the rims of its top and
 * its bottom along their hard stretches into quarter cylinders, meeting in sphere and torus
 * pieces and mitres. */
#ifndef HOMEWORK45_PLAN_BLOCK_H
#define HOMEWORK45_PLAN_BLOCK_H

#include "wings_plan.h"

/* Draws the object with its marked edges rounded at `radius` (0: sharp; at most
 * plan->max_radius), with normals and texture coordinates: on the sides s the length walked
 * round each loop of the outline, stretched or shrunk a little so that the whole walk is a whole
 * number of the texture's repeats along s (`s_repeat`: the checkerboard then meets itself where
 * the walk closes), and t the height above the bottom over `texture_height`, running on across the rounded
 * strips by their arc length; (x, z) on the top and the bottom, and on the rims' halves next to
 * them, run on by arc length. */
void draw_plan_block(const struct floor_plan *plan, float radius, float texture_height, float s_repeat);

#endif
