/* Drawing the object of several layers of cubes (cube_layers.h) with its marked uprights rounded
 * layer by layer, and the top and bottom rims of its capped pieces. */
#ifndef HOMEWORK45_LAYERED_BLOCK_H
#define HOMEWORK45_LAYERED_BLOCK_H

#include "cube_layers.h"

/* Draws the object with its rounded uprights at `radius` (0: sharp; at most layers->max_radius):
 * walls, quarter cylinders, rim strips, eighths of spheres and quarters of tori, fillets and their
 * corner pieces, and the flat
 * pieces of every height, with normals and texture coordinates (s along a wall, t the height
 * above the bottom, (x, z) on the flat pieces). */
void draw_layered_block(const struct cube_layers *layers, float radius);

#endif
