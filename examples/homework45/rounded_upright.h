/* A rounded upright edge, as both ways of drawing the object draw it (homework45.c for an object
 * of one layer of cubes, layered_block.c for more): a quarter cylinder, the rational quadratic
 * quarter arc swept straight up. */
#ifndef HOMEWORK45_ROUNDED_UPRIGHT_H
#define HOMEWORK45_ROUNDED_UPRIGHT_H

/* Steps along each quarter arc, on the strips and on the top's outline alike: an even number
 * (the flat pieces round a torus piece split its arc in the middle). A build may choose another,
 * as the tests do to check the surface at other depths. */
#ifndef ARC_STEPS
#define ARC_STEPS 8
#endif

/* The point at parameter u of the quarter arc from `from` to `to` around `corner` (x, z): the
 * rational quadratic with those control points and weights 1, sqrt(2)/2, 1, which the evaluator
 * draws, so that flat faces along it meet the cylinder's vertices. */
void quarter_arc_point(const float from[2], const float corner[2], const float to[2], double u, double out[2]);

/* The quarter cylinder over that arc from height y0 to y1, by glMap2f (GL_MAP2_VERTEX_4) and
 * glEvalMesh2 with ARC_STEPS steps round and v_steps up; GL_AUTO_NORMAL's dP/du x dP/dv points out of
 * the solid when the arc runs counter-clockwise seen from above. The texture's s runs from s0 to
 * s0 + arc (the arc's length), t from t0 at y0 to t1 at y1. */
void quarter_cylinder(const float from[2], const float corner[2], const float to[2], float y0, float y1, float s0,
                      float arc, float t0, float t1, int v_steps);

#endif
