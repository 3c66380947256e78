/* Rational quadratic patches as the homework draws them, through the GL evaluators: each rounded
 * piece (a rim's strip, a corner's piece of sphere) is a net of homogeneous control points handed
 * to glMap2f and drawn by glEvalMesh2. Shared by both ways of drawing the object (homework45.c
 * for an object of one layer of cubes, layered_block.c for more). */
#ifndef HOMEWORK45_RATIONAL_PATCH_H
#define HOMEWORK45_RATIONAL_PATCH_H

/* One homogeneous control point: (x, y, z) weighted by w, i.e. (x w, y w, z w, w). */
void control_point(float out[4], double x, double y, double z, double w);

/* Draws the patch net[v][u] (rows = 2 or 3 rows of 3 homogeneous points) with texture coordinates
 * tex[v][u] and normals from the polynomial net normals[v][u] (GL_AUTO_NORMAL is off while it
 * draws, since its dP/du x dP/dv vanishes where a sphere's net closes in a pole; GL_NORMALIZE
 * makes them unit length), ARC_STEPS steps along u and v_steps along v. */
void draw_rational_patch(const float net[][3][4], const float tex[][3][2], const float normals[][3][3], int rows,
                         int v_steps);

#endif
