/* Rational quadratic patches as the homework draws them, through the GL evaluators: each rounded
 * piece (a rim's strip, a corner's piece of sphere) is a net of homogeneous control points handed
 * to glMap2f and drawn by glEvalMesh2. Shared by both ways of drawing the object (homework45.c
 * for an object of one layer of cubes, layered_block.c for more). */
#ifndef HOMEWORK45_RATIONAL_PATCH_H
#define HOMEWORK45_RATIONAL_PATCH_H

/* One homogeneous control point: (x, y, z) weighted by w, i.e. (x w, y w, z w, w). */
void control_point(float out[4], double x, double y, double z, double w);

/* The texture coordinates of one column of a strip's 3-point net (a rim or a fillet, u = 0, 1, 2
 * across it): s along the strip, t from t0 through their midpoint to t2. */
void strip_column_texture(float tex[3][2], float s, float t0, float t2);

/* The point of the rational patch net[v][u] (rows = 2 or 3 rows of 3 homogeneous points) at
 * (u, v), in double precision. */
void rational_patch_point(const float net[][3][4], int rows, double u, double v, double out[3]);

/* The net of a profile (rows: the quarter circle from the upright at y[0] through y[1] to y[2])
 * turned about an upright axis (x, z) by a quarter arc arc[0..2] (x, z: from, corner, to): its rows
 * are the arc's control points scaled from the axis by scale[v] at height y[v], weighted by the
 * products of the two arcs' weights (exact for a surface of revolution). The texture's s runs from
 * s0 over s_length round the arc, t from t0 on row 0 to t2 on row 2; centre[v][u] is the tube's
 * centre circle, the arc scaled by scale[2] at height y[0], for begin_net_parts. */
void turned_profile_net(const double arc[3][2], const double axis[2], const double scale[3], const double y[3],
                        float s0, float s_length, float t0, float t2, float net[3][3][4], float tex[3][3][2],
                        double centre[3][3][3]);

/* turned_profile_net in another frame: the net's points and centres (x, y, z) are taken as the
 * points frame[0] + x frame[1] + y frame[2] + z frame[3] (an origin and three orthonormal axes),
 * so that the profile turns about an axis along frame[2] (NULL: the object's own axes). */
void turned_profile_net_in_frame(const double arc[3][2], const double axis[2], const double scale[3],
                                 const double y[3], const double frame[4][3], float s0, float s_length, float t0,
                                 float t2, float net[3][3][4], float tex[3][3][2], double centre[3][3][3]);

/* The net of the piece where a rim rounded on both sides of a rounded upright turns with it: the
 * rim's quarter circle turned about the upright's axis (x, z) by the upright's quarter arc
 * arc[0..2] (x, z: from, corner, to). Its rows are the arc's control points scaled from the axis
 * by the rim's profile, at heights `below` (R below the rim, scale 1), `rim` (scale 1) and `rim`
 * (scale 0 at a convex corner, where the net closes in a pole: an eighth of a sphere; 2 at a
 * concave one: a quarter of the inner half of a torus of radii 2 R and R about the fillet's
 * axis), weighted by the products of the two arcs' weights. The texture's s runs from s0 over
 * s_length round the arc, t from t0 at `below` to t2 on the rim; centre[v][u] is the tube's
 * centre circle at `below` (the sphere's centre), for begin_net_parts. */
void rim_corner_net(const double arc[3][2], const double axis[2], int convex, double below, double rim, float s0,
                    float s_length, float t0, float t2, float net[3][3][4], float tex[3][3][2],
                    double centre[3][3][3]);

/* A texture chart: the texture coordinates of a point of a patch, from the point itself and what
 * `chart` holds. */
typedef void (*point_texture)(const double point[3], const void *chart, float out[2]);

/* The texture of a top (or a bottom) run on over the half of a rim next to it, by the rim's arc
 * length: a point R phi along the rim's quarter circle from the top's edge (phi the angle from
 * the top's side, measured about the circle's centre) takes the top's (x, z) R phi beyond the
 * edge. Over a strip along a wall the edge is a line (on the top, above or below the strip's axis)
 * and "beyond" runs across the wall; over a corner's piece the edge is the arc top_distance from
 * the upright's axis (0 at a convex corner, where the piece is a sphere closing in the axis; 2 R
 * above a fillet, the torus's inner rim) and "beyond" runs along the radius from the axis. A
 * fillet along a foot is charted alike from the top it stands on: its circle's centre lies above
 * that top (out -1: the top's edge is straight below it), and round a corner's foot its edge is
 * 2 R from the axis (R round a sharp upright). phi is taken with its sign (positive on the side
 * of the edge where the point lies), so "beyond" needs no direction: the chart follows the
 * surface whichever way it leaves the top. */
struct rim_chart {
  int corner;            /* a corner's piece (else a strip) */
  double axis[2];        /* x, z: a point of the strip's axis, or the corner's upright axis */
  double across[2];      /* a strip's: the unit direction (x, z) across its wall, either way */
  double top_distance;   /* a corner's: its edge's distance from the axis */
  double below, out, r;  /* the circle's centre height; the top's side of it (1 above, -1 below); R */
};

/* The chart of a strip whose axis passes through (x, z) = axis, its wall across `across`. */
struct rim_chart strip_rim_chart(const double axis[2], const double across[2], double below, double out, double r);

/* The chart of a corner's piece about the upright axis (x, z) = axis, its edge on the top
 * top_distance from the axis. */
struct rim_chart corner_rim_chart(const double axis[2], double top_distance, double below, double out, double r);

/* The texture coordinates the chart (a struct rim_chart) gives to a point of the top's half. */
void rim_top_texture(const double point[3], const void *chart, float out[2]);

/* Drawing a patch net[v][u] (rows = 2 or 3 rows of 3 homogeneous points) in parts, each with its
 * own texture. begin_net_parts sets the maps of its points and normals and its grid (ARC_STEPS
 * steps along u, v_steps along v). The normals come from the centres of the surface's curvature:
 * it lies at distance R from centre[v][u] (the centre nearest each control point, on a strip's
 * axis or a corner piece's tube centre circle), so side w(u, v) (P(u, v) - centre) is a
 * polynomial patch with control points side w_ij (P_ij - centre_ij), whose value, normalized, is
 * the exact unit normal, also at a sphere's pole (GL_AUTO_NORMAL's dP/du x dP/dv vanishes there,
 * so it is off while the parts are drawn; GL_NORMALIZE makes them unit length): side 1 for a rim
 * (the solid inside its tube), -1 for a fillet (outside it). draw_part_mapped draws a part of the grid with the
 * texture net tex (glEvalMesh2 on the part), draw_part_charted with the chart's texture point
 * by point (the same grid points by glEvalPoint2, in the triangle strips glEvalMesh2 draws);
 * end_net_parts ends. The parts share the points of their common sides, as the whole patch's
 * mesh would, with its neighbours too. */
struct grid_part {
  int i0, i1, j0, j1;  /* columns [i0, i1] of the grid along u, rows [j0, j1] along v */
};
void begin_net_parts(const float net[][3][4], const double centre[][3][3], float side, int rows, int v_steps);
void draw_part_mapped(const float tex[][3][2], struct grid_part part);
void draw_part_charted(point_texture texture, const void *chart, struct grid_part part);
void end_net_parts(void);

/* Draws a rim's (side 1) or a fillet's (side -1) patch (as begin_net_parts takes it) in the two
 * halves of its quarter circle, which runs along u (a strip) or, with arc_along_v, along v (a
 * corner's piece), from the wall to the top, or from the top to the wall with top_first: the
 * wall's half with the texture net tex (whose t runs on from the wall over the whole arc; its
 * wall half is drawn), the top's half with the top's texture run on by arc length (`chart`,
 * rim_top_texture), point by point, since that is not a polynomial of the patch's parameters.
 * The halves are the two halves of the same grid of points (ARC_STEPS and v_steps are even), so
 * they meet each other and the patch's neighbours where the whole patch would. The checkerboard
 * then crosses from each face onto the piece without a jump, changing from the wall's to the
 * top's along the arc's middle, as the scene language's rounding does. */
void draw_net_in_halves(const float net[][3][4], const float tex[][3][2], const double centre[][3][3], float side,
                        int rows, int v_steps, int arc_along_v, int top_first, const struct rim_chart *chart);

#endif
