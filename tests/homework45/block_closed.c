/* Whether the surface homework45 draws is closed: the drawing of layered_block.c (an object of
 * several layers) or, after --plan, of plan_block.c (one floor plan raised) is recorded by
 * stand-ins for the GL and GLU calls it makes (the evaluator's quarter cylinders evaluated here,
 * as glEvalMesh2 would; the tessellated top and bottom as a fan from a point off their outline's
 * centroid, whose inner edges pair up among themselves, so that every edge of the outline must
 * meet the walls' and rims' edges), cut into triangles, and every triangle edge must have a twin, an edge
 * of another triangle with the same end points (to 1e-5): a crack, a hole or a T-junction leaves
 * an edge without one. Each object named on the command line is checked at nine radii from 0 to
 * its largest.
 * The vertices' normals (glNormal, the evaluator's normal map or GL_AUTO_NORMAL's dP/du x dP/dv)
 * and texture coordinates are recorded too: where two vertices at one point have normals less
 * than 30 degrees apart (a seam, not a sharp crease), they must agree to 1e-3 radians, and their
 * texture coordinates must agree but for whole repeats of the checkerboard (0.25 in s, 1 in t),
 * except on the flat tops and bottoms (normal straight up or down), whose texture is (x, z) and
 * must equal that of a rim's half drawn with the top's chart (glEvalPoint2) where they meet,
 * except where a rim's two halves meet (one drawn with its own texture, one by glEvalMesh2),
 * along a mitre's crease (two rims' strips ending in a sharp corner's diagonal plane) and at a
 * horn piece's tip (two fillets meeting round a sharp upright's foot). Every point drawn within
 * a filleted foot's reach must lie R from the fillet's axis, and round a standing corner (a
 * fillet ending against the rim of the layer below, where the foot's side is flush with that
 * layer's side) R from the torus piece's centre circle, its normal pointing away from it.
 * Where two rational patches share a side (their side curves have the same end points), the
 * curves must be the same: their control points (divided by their weights) and their weights
 * (relative to the first) agree, so the patches meet along the whole side, not only at the
 * vertices drawn. glMap2f takes single-precision control points: the rims' pieces, built by one
 * function (control_point), share theirs bit for bit (to 1e-12), while an upright's quarter
 * cylinder rounds its weighted points in single precision and meets them to that rounding (one
 * or two units in the last place, a few 1e-7), and at the largest radius of a grid whose spacing
 * is not a power of two, the strips' columns a + R and b - R, rounded apart, leave 1e-6. So the
 * count of sides not exact to 1e-12 and the largest gap are printed, and a gap beyond 1e-5 (the
 * twin test's tolerance) fails.
 *   homework45_block_closed [--scale=SX,SY,SZ] [--plan] OBJECT.wings...
 * (--scale stretches the objects after it along x, y and z: cells of other sizes than the test
 * files' unit cubes, layers lower than their cells are wide; --plan draws the objects after it as
 * their floor plans raised, which they must be, as homework45 does with one layer of cubes.)
 * Prints a line per object and radius, and exits 1 when an edge has no twin, a seam is not
 * smooth, two patches that share a side are apart along it, a fillet's point is off its axis or
 * a standing corner's point is off its circle or its normal turned from it by more than 1e-3. */
#include <GL/glut.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cube_layers.h"
#include "layered_block.h"
#include "plan_block.h"
#include "wings_plan.h"

/* How far a fillet's drawn point may lie off R from its axis: glMap2f takes single-precision
 * control points, whose rounding moves the evaluated points by a few 1e-8 (1e-9 is out of reach). */
#define FILLET_TOLERANCE 1e-7
/* How far a rim's top half's texture may lie from the top's (x, z) run on by arc length: the
 * texture coordinates are single precision, the points and normals evaluated from single-precision
 * control points. */
#define CHART_TOLERANCE 1e-5
struct triangle {
  double corner[3][3];
};

static struct triangle *triangles;
static size_t triangle_count, triangle_capacity;
/* The vertices of the primitive between glBegin and glEnd. */
static double primitive[4096][3];
static int primitive_count;
static GLenum primitive_mode;
static GLfloat cylinder_net[3][3][4], normal_net[3][3][3], texture_net[3][3][2];
static int net_rows, normal_map_on, auto_normal_on = 1;
static double current_normal[3], current_texture[2];

/* Every vertex drawn: its point, normal and texture coordinates. */
struct drawn_vertex {
  double point[3], normal[3], texture[2];
  int horn_tip; /* the tip of a horn piece (below) */
  int charted;  /* drawn by glEvalPoint2 with its own texture coordinates: a rim's half next to the top */
  int mapped;   /* its texture coordinates from the evaluator's texture map */
};
static struct drawn_vertex *drawn;
static size_t drawn_count, drawn_capacity;

static void add_drawn(const double point[3], const double normal[3], const double texture[2])
{
  if (drawn_count == drawn_capacity) {
    drawn_capacity = drawn_capacity ? 2 * drawn_capacity : 4096;
    drawn = realloc(drawn, drawn_capacity * sizeof *drawn);
    if (!drawn) exit(2);
  }
  memcpy(drawn[drawn_count].point, point, sizeof(double[3]));
  memcpy(drawn[drawn_count].normal, normal, sizeof(double[3]));
  memcpy(drawn[drawn_count].texture, texture, sizeof(double[2]));
  drawn[drawn_count].horn_tip = 0;
  drawn[drawn_count].charted = 0;
  drawn[drawn_count].mapped = 0;
  ++drawn_count;
}
static int grid_steps_u, grid_steps_v;

/* A side of a drawn patch: its control points divided by their weights, and the weights
 * relative to the first. */
struct side_curve {
  int order;
  double point[3][3], weight[3];
};
static struct side_curve *sides;
static size_t side_count, side_capacity;

static void add_side(const GLfloat (*control)[4], int order, int stride)
{
  if (side_count == side_capacity) {
    side_capacity = side_capacity ? 2 * side_capacity : 1024;
    sides = realloc(sides, side_capacity * sizeof *sides);
    if (!sides) exit(2);
  }
  struct side_curve *side = &sides[side_count++];
  side->order = order;
  for (int k = 0; k < order; ++k) {
    const GLfloat *h = control[k * stride];
    for (int c = 0; c < 3; ++c) side->point[k][c] = (double)h[c] / h[3];
    side->weight[k] = (double)h[3] / control[0][3];
  }
}

/* The four sides of the patch in cylinder_net: its first and last rows, its first and last
 * columns. */
static void add_patch_sides(void)
{
  const GLfloat (*first)[4] = (const GLfloat (*)[4])cylinder_net[0];
  add_side(first, 3, 1);
  add_side((const GLfloat (*)[4])cylinder_net[net_rows - 1], 3, 1);
  add_side(first, net_rows, 3);
  add_side(first + 2, net_rows, 3);
}

static double distance(const double a[3], const double b[3])
{
  return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

/* How far apart the control points and relative weights of sides a and b are, b walked forwards
 * or backwards; a negative value when they do not share their end points (to 1e-5). */
static double side_mismatch(const struct side_curve *a, const struct side_curve *b)
{
  if (a->order != b->order) return -1;
  const int last = a->order - 1;
  for (int backwards = 0; backwards < 2; ++backwards) {
    const int first_b = backwards ? last : 0, last_b = backwards ? 0 : last;
    if (distance(a->point[0], b->point[first_b]) > 1e-5 || distance(a->point[last], b->point[last_b]) > 1e-5)
      continue;
    double mismatch = 0;
    for (int k = 0; k <= last; ++k) {
      const int kb = backwards ? last - k : k;
      mismatch = fmax(mismatch, distance(a->point[k], b->point[kb]));
      mismatch = fmax(mismatch, fabs(a->weight[k] / a->weight[0] * b->weight[first_b] - b->weight[kb]));
    }
    return mismatch;
  }
  return -1;
}

/* How many pairs of patches share a side whose curves differ by more than 1e-12 (sides that
 * shrink to a point, such as a sphere's pole, left out); the largest difference goes into *gap. */
static size_t inexact_seams(double *gap)
{
  size_t inexact = 0;
  *gap = 0;
  for (size_t i = 0; i < side_count; ++i) {
    if (distance(sides[i].point[0], sides[i].point[sides[i].order - 1]) < 1e-5) continue;
    for (size_t j = i + 1; j < side_count; ++j) {
      const double mismatch = side_mismatch(&sides[i], &sides[j]);
      inexact += mismatch > 1e-12;
      *gap = fmax(*gap, mismatch);
    }
  }
  return inexact;
}

static void add_triangle(const double *a, const double *b, const double *c)
{
  if (triangle_count == triangle_capacity) {
    triangle_capacity = triangle_capacity ? 2 * triangle_capacity : 4096;
    triangles = realloc(triangles, triangle_capacity * sizeof *triangles);
    if (!triangles) exit(2);
  }
  memcpy(triangles[triangle_count].corner[0], a, sizeof(double[3]));
  memcpy(triangles[triangle_count].corner[1], b, sizeof(double[3]));
  memcpy(triangles[triangle_count].corner[2], c, sizeof(double[3]));
  ++triangle_count;
}

void glBegin(GLenum mode)
{
  primitive_mode = mode;
  primitive_count = 0;
}

void glEnd(void)
{
  const double (*v)[3] = (const double (*)[3])primitive;
  if (primitive_mode == GL_QUAD_STRIP)
    for (int i = 0; i + 3 < primitive_count; i += 2) {
      add_triangle(v[i], v[i + 1], v[i + 3]);
      add_triangle(v[i], v[i + 3], v[i + 2]);
    }
  else if (primitive_mode == GL_QUADS)
    for (int i = 0; i + 3 < primitive_count; i += 4) {
      add_triangle(v[i], v[i + 1], v[i + 2]);
      add_triangle(v[i], v[i + 2], v[i + 3]);
    }
  else if (primitive_mode == GL_TRIANGLE_STRIP)
    for (int i = 0; i + 2 < primitive_count; ++i) add_triangle(v[i], v[i + 1], v[i + 2]);
  else if (primitive_mode == GL_TRIANGLE_FAN)
    for (int i = 1; i + 1 < primitive_count; ++i) add_triangle(v[0], v[i], v[i + 1]);
  else {
    fprintf(stderr, "homework45_block_closed: primitive mode %u not recorded\n", primitive_mode);
    exit(2);
  }
}

void glVertex3d(GLdouble x, GLdouble y, GLdouble z)
{
  if (primitive_count == 4096) exit(2);
  primitive[primitive_count][0] = x;
  primitive[primitive_count][1] = y;
  primitive[primitive_count][2] = z;
  add_drawn(primitive[primitive_count], current_normal, current_texture);
  ++primitive_count;
}

void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { glVertex3d(x, y, z); }
void glTexCoord2d(GLdouble s, GLdouble t)
{
  current_texture[0] = s;
  current_texture[1] = t;
}
void glTexCoord2f(GLfloat s, GLfloat t) { glTexCoord2d(s, t); }
void glTexCoord2fv(const GLfloat *st) { glTexCoord2d(st[0], st[1]); }
void glVertex3dv(const GLdouble *p) { glVertex3d(p[0], p[1], p[2]); }
void glNormal3d(GLdouble x, GLdouble y, GLdouble z)
{
  current_normal[0] = x;
  current_normal[1] = y;
  current_normal[2] = z;
}
void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { glNormal3d(x, y, z); }
void glNormal3fv(const GLfloat *n) { glNormal3d(n[0], n[1], n[2]); }

/* GLU's tessellator, as the program uses it (the top and the bottom, one contour per loop of the
 * outline, and the walls' bands): each contour's vertices go to the vertex callback as a fan
 * about an apex half a unit off the contour's centroid along the normal (the centroid may be a
 * vertex of a concave outline; the apex gets the texture (x, z) the program gives the top's
 * points). A hole's fan lies over the outer one's instead of being cut out of it, but the edges
 * twin as they would: each contour's edges once, the fans' inner edges among themselves. */
struct GLUtesselator {
  void (GLAPIENTRY *begin)(GLenum);
  void (GLAPIENTRY *vertex)(void *);
  void (GLAPIENTRY *end)(void);
  void *data[4096];
  double point[4096][3], normal[3];
  int count;
};
static GLUtesselator the_tessellator;
GLUtesselator *GLAPIENTRY gluNewTess(void) { return &the_tessellator; }
void GLAPIENTRY gluTessCallback(GLUtesselator *tess, GLenum which, _GLUfuncptr callback)
{
  if (which == GLU_TESS_BEGIN) tess->begin = (void (GLAPIENTRY *)(GLenum))callback;
  else if (which == GLU_TESS_VERTEX) tess->vertex = (void (GLAPIENTRY *)(void *))callback;
  else if (which == GLU_TESS_END) tess->end = (void (GLAPIENTRY *)(void))callback;
  else exit(2);
}
void GLAPIENTRY gluTessNormal(GLUtesselator *tess, GLdouble x, GLdouble y, GLdouble z)
{
  tess->normal[0] = x;
  tess->normal[1] = y;
  tess->normal[2] = z;
}
void GLAPIENTRY gluTessBeginPolygon(GLUtesselator *tess, GLvoid *data) { (void)tess, (void)data; }
void GLAPIENTRY gluTessBeginContour(GLUtesselator *tess) { tess->count = 0; }
void GLAPIENTRY gluTessVertex(GLUtesselator *tess, GLdouble *location, GLvoid *data)
{
  if (tess->count == 4096) exit(2);
  memcpy(tess->point[tess->count], location, sizeof(double[3]));
  tess->data[tess->count++] = data;
}
void GLAPIENTRY gluTessEndContour(GLUtesselator *tess)
{
  if (tess->count == 0) return;
  double apex[3] = {0, 0, 0};
  for (int i = 0; i < tess->count; ++i)
    for (int k = 0; k < 3; ++k) apex[k] += tess->point[i][k] / tess->count;
  for (int k = 0; k < 3; ++k) apex[k] += 0.5 * tess->normal[k];
  tess->begin(GL_TRIANGLE_FAN);
  glTexCoord2d(apex[0], apex[2]);
  glVertex3d(apex[0], apex[1], apex[2]);
  for (int i = 0; i <= tess->count; ++i) tess->vertex(tess->data[i % tess->count]);
  tess->end();
}
void GLAPIENTRY gluTessEndPolygon(GLUtesselator *tess) { (void)tess; }
void glEnable(GLenum capability)
{
  if (capability == GL_MAP2_NORMAL) normal_map_on = 1;
  if (capability == GL_AUTO_NORMAL) auto_normal_on = 1;
}
void glDisable(GLenum capability)
{
  if (capability == GL_MAP2_NORMAL) normal_map_on = 0;
  if (capability == GL_AUTO_NORMAL) auto_normal_on = 0;
}

void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2,
             GLint vstride, GLint vorder, const GLfloat *points)
{
  (void)u1, (void)u2, (void)v1, (void)v2;
  if (target == GL_MAP2_NORMAL || target == GL_MAP2_TEXTURE_COORD_2) {
    const int size = target == GL_MAP2_NORMAL ? 3 : 2;
    if (ustride != size || uorder != 3 || vstride != 3 * size || vorder > 3) exit(2);
    for (int v = 0; v < vorder; ++v)
      for (int u = 0; u < 3; ++u)
        for (int k = 0; k < size; ++k) {
          const float value = points[v * vstride + u * ustride + k];
          if (size == 3) normal_net[v][u][k] = value;
          else texture_net[v][u][k] = value;
        }
    return;
  }
  if (target != GL_MAP2_VERTEX_4) return;
  if (ustride != 4 || uorder != 3 || vstride != 12 || (vorder != 2 && vorder != 3)) exit(2);
  net_rows = vorder;
  memcpy(cylinder_net, points, (size_t)vorder * sizeof cylinder_net[0]);
}

/* Set by glMapGrid2f, which the program calls once per patch: the patch's sides are still to be
 * recorded by the first glEvalMesh2 or glEvalPoint2 that draws it. */
static int sides_pending;

void glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2)
{
  (void)u1, (void)u2, (void)v1, (void)v2;
  grid_steps_u = un;
  grid_steps_v = vn;
  sides_pending = 1;
}

/* The rational patch (quadratic in u; linear in v for 2 rows, quadratic for 3) at (u, v). */
static void cylinder_point(double u, double v, double out[3])
{
  double h[4] = {0, 0, 0, 0};
  const double bu[3] = {(1 - u) * (1 - u), 2 * u * (1 - u), u * u};
  const double bv[3] = {net_rows == 2 ? 1 - v : (1 - v) * (1 - v), net_rows == 2 ? v : 2 * v * (1 - v), v * v};
  for (int j = 0; j < net_rows; ++j)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 4; ++k) h[k] += bv[j] * bu[i] * cylinder_net[j][i][k];
  for (int k = 0; k < 3; ++k) out[k] = h[k] / h[3];
}

/* A polynomial map's value at (u, v): the normal map's (size 3) or the texture map's (size 2). */
static void polynomial_point(int size, double u, double v, double *out)
{
  const double bu[3] = {(1 - u) * (1 - u), 2 * u * (1 - u), u * u};
  const double bv[3] = {net_rows == 2 ? 1 - v : (1 - v) * (1 - v), net_rows == 2 ? v : 2 * v * (1 - v), v * v};
  for (int k = 0; k < size; ++k) out[k] = 0;
  for (int j = 0; j < net_rows; ++j)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < size; ++k)
        out[k] += bv[j] * bu[i] * (size == 3 ? normal_net[j][i][k] : texture_net[j][i][k]);
}

/* Whether row `row` of the patch's net closes in one point (its control points divided by their
 * weights equal): a sphere's pole, or the tip of a horn piece, where two fillets meet round the
 * foot of a sharp upright and the normal turns through the right angle between its walls. */
static int row_closes(int row)
{
  for (int u = 1; u < 3; ++u)
    for (int k = 0; k < 3; ++k)
      if (fabs(cylinder_net[row][u][k] / cylinder_net[row][u][3] - cylinder_net[row][0][k] / cylinder_net[row][0][3]) >
          1e-9)
        return 0;
  return 1;
}

/* The vertex the evaluator draws at (u, v), with its normal, and `texture` for its texture
 * coordinates (NULL: the texture map's). */
static void record_grid_vertex(double u, double v, const double *texture)
{
  double point[3], normal[3], mapped_texture[2];
  cylinder_point(u, v, point);
  if (normal_map_on) {
    polynomial_point(3, u, v, normal);
  } else {
    /* dP/du x dP/dv, by central differences inside the patch. */
    const double h = 1e-6, uc = fmin(fmax(u, h), 1 - h), vc = fmin(fmax(v, h), 1 - h);
    double a[3], b[3], c[3], d[3];
    cylinder_point(uc - h, v, a);
    cylinder_point(uc + h, v, b);
    cylinder_point(u, vc - h, c);
    cylinder_point(u, vc + h, d);
    const double du[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, dv[3] = {d[0] - c[0], d[1] - c[1], d[2] - c[2]};
    normal[0] = du[1] * dv[2] - du[2] * dv[1];
    normal[1] = du[2] * dv[0] - du[0] * dv[2];
    normal[2] = du[0] * dv[1] - du[1] * dv[0];
  }
  if (!texture) {
    polynomial_point(2, u, v, mapped_texture);
    texture = mapped_texture;
  }
  const int mapped = texture == mapped_texture;
  add_drawn(point, normal, texture);
  drawn[drawn_count - 1].mapped = mapped;
  drawn[drawn_count - 1].horn_tip = v == 0 && net_rows == 3 && row_closes(0);
}

void glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2)
{
  (void)mode;
  if (sides_pending) add_patch_sides();
  sides_pending = 0;
  for (int j = j1; j <= j2; ++j)
    for (int i = i1; i <= i2; ++i) record_grid_vertex((double)i / grid_steps_u, (double)j / grid_steps_v, NULL);
  for (int j = j1; j < j2; ++j)
    for (int i = i1; i < i2; ++i) {
      double a[3], b[3], c[3], d[3];
      cylinder_point((double)i / grid_steps_u, (double)j / grid_steps_v, a);
      cylinder_point((double)(i + 1) / grid_steps_u, (double)j / grid_steps_v, b);
      cylinder_point((double)(i + 1) / grid_steps_u, (double)(j + 1) / grid_steps_v, c);
      cylinder_point((double)i / grid_steps_u, (double)(j + 1) / grid_steps_v, d);
      add_triangle(a, b, c);
      add_triangle(a, c, d);
    }
}

/* One grid point inside glBegin/glEnd, with the current texture coordinates (the program draws
 * this way with the texture's map off). */
void glEvalPoint2(GLint i, GLint j)
{
  if (sides_pending) add_patch_sides();
  sides_pending = 0;
  if (primitive_count == 4096) exit(2);
  const double u = (double)i / grid_steps_u, v = (double)j / grid_steps_v;
  cylinder_point(u, v, primitive[primitive_count]);
  ++primitive_count;
  record_grid_vertex(u, v, current_texture);
  drawn[drawn_count - 1].charted = 1;
}

/* An edge's end points rounded to 1e-5, the smaller first. */
struct edge_key {
  long long end[2][3];
};

static int compare_edges(const void *a, const void *b) { return memcmp(a, b, sizeof(struct edge_key)); }

static void round_point(const double p[3], long long out[3])
{
  for (int k = 0; k < 3; ++k) out[k] = llround(p[k] * 1e5);
}

static int by_x(const void *a, const void *b)
{
  const double x = (*(const double *const *)a)[0], y = (*(const double *const *)b)[0];
  return (x > y) - (x < y);
}

/* Moves every triangle corner within 1e-6 of an earlier one (in order of x) onto it, so that
 * copies of one point a rounding error apart round alike even where they straddle a multiple of
 * 1e-5 (the objects' points lie on dyadic fractions such as k / 64, some exactly halfway). */
static void merge_close_corners(void)
{
  const size_t count = 3 * triangle_count;
  double **corners = malloc(count * sizeof *corners + 1);
  if (!corners) exit(2);
  for (size_t t = 0; t < triangle_count; ++t)
    for (int k = 0; k < 3; ++k) corners[3 * t + k] = triangles[t].corner[k];
  qsort(corners, count, sizeof *corners, by_x);
  for (size_t i = 1; i < count; ++i)
    for (size_t j = i; j-- > 0 && corners[i][0] - corners[j][0] < 1e-6;)
      if (fabs(corners[i][1] - corners[j][1]) < 1e-6 && fabs(corners[i][2] - corners[j][2]) < 1e-6) {
        memcpy(corners[i], corners[j], sizeof(double[3]));
        break;
      }
  free(corners);
}

/* How many of the recorded triangles' edges have no twin (degenerate triangles, such as a fan's
 * at a cylinder's pole, left out). */
static size_t edges_without_twin(void)
{
  merge_close_corners();
  struct edge_key *edges = malloc(3 * triangle_count * sizeof *edges + 1);
  if (!edges) exit(2);
  size_t count = 0;
  for (size_t t = 0; t < triangle_count; ++t) {
    const double(*p)[3] = triangles[t].corner;
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    if (sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) < 1e-12) continue;
    for (int k = 0; k < 3; ++k) {
      long long a[3], b[3];
      round_point(p[k], a);
      round_point(p[(k + 1) % 3], b);
      const int order = memcmp(a, b, sizeof a);
      if (order == 0) continue;
      memcpy(edges[count].end[0], order < 0 ? a : b, sizeof a);
      memcpy(edges[count].end[1], order < 0 ? b : a, sizeof a);
      ++count;
    }
  }
  qsort(edges, count, sizeof *edges, compare_edges);
  size_t lonely = 0;
  for (size_t i = 0; i < count;) {
    size_t j = i;
    while (j < count && compare_edges(&edges[i], &edges[j]) == 0) ++j;
    if ((j - i) % 2 && lonely < 3)
      fprintf(stderr, "edge without a twin: (%g, %g, %g) to (%g, %g, %g)\n", edges[i].end[0][0] * 1e-5,
              edges[i].end[0][1] * 1e-5, edges[i].end[0][2] * 1e-5, edges[i].end[1][0] * 1e-5,
              edges[i].end[1][1] * 1e-5, edges[i].end[1][2] * 1e-5);
    lonely += (j - i) % 2;
    i = j;
  }
  free(edges);
  return lonely;
}

static int by_point(const void *a, const void *b)
{
  const struct drawn_vertex *p = a, *q = b;
  for (int k = 0; k < 3; ++k) {
    const long long x = llround(p->point[k] * 1e5), y = llround(q->point[k] * 1e5);
    if (x != y) return (x > y) - (x < y);
  }
  return 0;
}

/* Whether unit normals a and b meet in a mitre's crease, where two rims' strips end in a sharp
 * corner's diagonal plane (as on the one-layer object, the crease of the exact rounded solid):
 * the same height above the horizontal (the same point of the rim's quarter circle), turned to
 * two walls, one facing along x and one along z. */
static int mitre_crease(const double a[3], const double b[3])
{
  const double e = 1e-6;
  return fabs(a[1] - b[1]) < e && fabs(a[1]) < 1 - e &&
         ((fabs(a[2]) < e && fabs(b[0]) < e) || (fabs(a[0]) < e && fabs(b[2]) < e));
}

/* How far x is from a whole multiple of `period`. */
static double off_period(double x, double period) { return fabs(x - period * floor(x / period + 0.5)); }

/* How many pairs of vertices at one point meet in a seam that is not smooth: normals less than
 * 30 degrees apart but more than 1e-3 radians, or (off the flat tops and bottoms) texture
 * coordinates that differ by more than 1e-4 beyond whole repeats. The pole of a sphere's net,
 * where the evaluator's normal map is exact but the point is shared by the whole row, counts
 * like any other point; a horn piece's tip, on the sharp upright's line, does not. */
static size_t rough_seams(void)
{
  qsort(drawn, drawn_count, sizeof *drawn, by_point);
  size_t rough = 0;
  for (size_t i = 0; i < drawn_count;) {
    size_t j = i;
    while (j < drawn_count && by_point(&drawn[i], &drawn[j]) == 0) ++j;
    for (size_t a = i; a < j; ++a)
      for (size_t b = a + 1; b < j; ++b) {
        double na[3], nb[3];
        const double la = sqrt(drawn[a].normal[0] * drawn[a].normal[0] + drawn[a].normal[1] * drawn[a].normal[1] +
                               drawn[a].normal[2] * drawn[a].normal[2]);
        const double lb = sqrt(drawn[b].normal[0] * drawn[b].normal[0] + drawn[b].normal[1] * drawn[b].normal[1] +
                               drawn[b].normal[2] * drawn[b].normal[2]);
        if (la < 1e-12 || lb < 1e-12 || drawn[a].horn_tip || drawn[b].horn_tip) continue;
        for (int k = 0; k < 3; ++k) na[k] = drawn[a].normal[k] / la, nb[k] = drawn[b].normal[k] / lb;
        const double angle = acos(fmin(1.0, fmax(-1.0, na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2])));
        if (angle > 30 * 3.14159265358979323846 / 180 || mitre_crease(na, nb)) continue;
        int bad = angle > 1e-3;
        const int flat = fabs(na[1]) >= 0.999 || fabs(nb[1]) >= 0.999;
        const int charted = drawn[a].charted + drawn[b].charted;
        if (flat && charted && !drawn[a].mapped && !drawn[b].mapped)
          /* A rim's top half meets the top (or another top half): the top's (x, z) itself, not a
           * repeat of it. (Where a fillet, which keeps the wall's texture, meets a rim's top half
           * at the largest radius, with no top left between them, they differ.) */
          bad |= fabs(drawn[a].texture[0] - drawn[b].texture[0]) > 1e-4 ||
                 fabs(drawn[a].texture[1] - drawn[b].texture[1]) > 1e-4;
        else if (!flat && charted != 1)  /* one charted: the rim's middle, where the charts change */
          bad |= off_period(drawn[a].texture[0] - drawn[b].texture[0], 0.25) > 1e-4 ||
                 off_period(drawn[a].texture[1] - drawn[b].texture[1], 1.0) > 1e-4;
        if (bad && rough < 3)
          fprintf(stderr, "seam at (%g, %g, %g): normals (%g, %g, %g) and (%g, %g, %g), texture (%g, %g) and (%g, %g)\n",
                  drawn[a].point[0], drawn[a].point[1], drawn[a].point[2], na[0], na[1], na[2], nb[0], nb[1], nb[2],
                  drawn[a].texture[0], drawn[a].texture[1], drawn[b].texture[0], drawn[b].texture[1]);
        rough += bad;
      }
    i = j;
  }
  return rough;
}

/* How many of the four cells around grid point (i, j) `layer` fills. */
static int cells_around(const struct cube_layers *layers, int layer, int i, int j)
{
  return cube_layers_filled(layers, layer, i - 1, j - 1) + cube_layers_filled(layers, layer, i, j - 1) +
         cube_layers_filled(layers, layer, i - 1, j) + cube_layers_filled(layers, layer, i, j);
}

/* How far from R the drawn points in the reach of a filleted foot (cube_layers.h) of layer k, the
 * piece cells[0 .. count - 1] (each j * cells_x + i), lie from its fillets' axes, at most: a
 * point between the foot and R above it has a distance d across from the sides of its cells on
 * the outline that stand inside the top below (a side flush with the lower layer's side has no
 * fillet: a point nearer to one is left out, as is one beyond a corner with a flush side, a
 * standing corner's, standing_corner_error's, or the upright's running on down), with the
 * outline's uprights rounded (round a rounded convex corner the arc about its axis R in from both
 * walls; at a rounded concave corner the fillet's arc about its axis R out from both walls), and
 * must lie R from the fillets' axes, hypot(R - d, foot + R - y) = R: on a fillet, on a torus or
 * horn piece round a convex corner, on the sphere piece or a mitre in a concave one. A point of
 * the top below left under a fillet, or of a wall reaching below R, lies off it by
 * R (sqrt(2) - 1) or more. */
static double foot_fillet_error(const struct cube_layers *layers, int k, const int *cells, int count,
                                    double radius)
{
  const int cells_x = layers->x_count - 1;
  const double foot = layers->height[k], e = 1e-9;
  double worst = 0;
  for (size_t v = 0; v < drawn_count; ++v) {
    const double *p = drawn[v].point;
    if (p[1] < foot - e || p[1] > foot + radius + e) continue;
    /* Across from the cells' sides on the outline, those inside the top below and the flush ones. */
    double d = INFINITY, flush = INFINITY;
    for (int c = 0; c < count; ++c) {
      const int i = cells[c] % cells_x, j = cells[c] / cells_x;
      const double x0 = layers->x[i], x1 = layers->x[i + 1], z0 = layers->z[j], z1 = layers->z[j + 1];
      const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
      for (int n = 0; n < 4; ++n) {
        if (cube_layers_filled(layers, k, next[n][0], next[n][1])) continue;
        /* How far p lies out beyond the side, and along it past its ends. */
        const double out = n == 0 ? x0 - p[0] : n == 1 ? p[0] - x1 : n == 2 ? z0 - p[2] : p[2] - z1;
        if (out < -e) continue;
        const double past = n < 2 ? fmax(fmax(z0 - p[2], p[2] - z1), 0.0) : fmax(fmax(x0 - p[0], p[0] - x1), 0.0);
        const double to_side = hypot(fmax(out, 0.0), past);
        if (cube_layers_filled(layers, k - 1, next[n][0], next[n][1])) d = fmin(d, to_side);
        else flush = fmin(flush, to_side);
      }
    }
    if (flush < d - e) continue;
    /* Round the rounded uprights. */
    int standing = 0;
    for (int c = 0; c < count && !standing; ++c)
      for (int corner = 0; corner < 4; ++corner) {
        const int gi = cells[c] % cells_x + (corner & 1), gj = cells[c] / cells_x + (corner >> 1);
        const int around = cells_around(layers, k, gi, gj);
        if (around != 1 && around != 3) continue;
        /* The one cell round the point that differs from the others, and its direction. */
        int qx = 0, qz = 0;
        for (int dj = -1; dj <= 0; ++dj)
          for (int di = -1; di <= 0; ++di)
            if (cube_layers_filled(layers, k, gi + di, gj + dj) == (around == 1)) qx = di ? -1 : 1, qz = dj ? -1 : 1;
        const double g[2] = {layers->x[gi], layers->z[gj]};
        const double r = cube_layers_rounded(layers, k, gi, gj) ? radius : 0.0;
        const double axis[2] = {g[0] + qx * r, g[1] + qz * r};
        const double along = (p[0] - g[0]) * qx, across = (p[2] - g[1]) * qz;
        if (around == 1) {
          /* Outside the cell beyond its arc's axis on both sides: from the arc, when both sides'
           * fillets turn round the corner (a standing corner's where one side is flush, and no
           * fillet's where both are: the upright runs on down). */
          if ((p[0] - axis[0]) * qx >= 0 || (p[2] - axis[1]) * qz >= 0) continue;
          const int inside_x = cube_layers_filled(layers, k - 1, gi + (qx > 0 ? -1 : 0), gj + (qz > 0 ? 0 : -1));
          const int inside_z = cube_layers_filled(layers, k - 1, gi + (qx > 0 ? 0 : -1), gj + (qz > 0 ? -1 : 0));
          if (!inside_x || !inside_z) standing = 1;
          else d = hypot(p[0] - axis[0], p[2] - axis[1]) - r;
          break;
        }
        if (r > 0 && along >= -e && along <= radius + e && across >= -e && across <= radius + e) {
          /* In the empty cell's R x R square at a rounded concave corner: from the fillet's arc. */
          d = fmax(0.0, radius - hypot(p[0] - axis[0], p[2] - axis[1]));
          break;
        }
      }
    if (standing || d < -e || d > radius + e) continue;
    worst = fmax(worst, fabs(hypot(radius - d, foot + radius - p[1]) - radius));
  }
  return worst;
}

/* How far from R the drawn points in the reach of every filleted foot lie from its fillets' axes,
 * at most (foot_fillet_error). */
static double fillet_axis_error(const struct cube_layers *layers, double radius)
{
  double worst = 0;
  if (radius <= 0 || !layers) return 0;
  const int cells_x = layers->x_count - 1, cells_z = layers->z_count - 1;
  int *piece = malloc((size_t)cells_x * (size_t)cells_z * sizeof *piece + 1);
  unsigned char *seen = malloc((size_t)cells_x * (size_t)cells_z + 1);
  if (!piece || !seen) exit(2);
  for (int k = 1; k < layers->layer_count; ++k) {
    memset(seen, 0, (size_t)cells_x * (size_t)cells_z);
    for (int start = 0; start < cells_x * cells_z; ++start) {
      if (seen[start] || !(cube_layers_capped(layers, k, start % cells_x, start / cells_x) & FILLETED_FOOT)) continue;
      /* The piece through `start`: its cells joined side to side. */
      int count = 0, done = 0;
      piece[count++] = start;
      seen[start] = 1;
      while (done < count) {
        const int i = piece[done] % cells_x, j = piece[done] / cells_x;
        ++done;
        const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (int n = 0; n < 4; ++n) {
          const int ni = next[n][0], nj = next[n][1];
          if (!cube_layers_filled(layers, k, ni, nj) || seen[nj * cells_x + ni]) continue;
          seen[nj * cells_x + ni] = 1;
          piece[count++] = nj * cells_x + ni;
        }
      }
      worst = fmax(worst, foot_fillet_error(layers, k, piece, count, radius));
    }
  }
  free(piece);
  free(seen);
  return worst;
}

/* A standing corner (a filleted foot's corner between a fillet's side, facing n_w, and a side
 * flush with the layer below, facing n_f): its grid point (x, z) and the foot's height. */
struct standing {
  double g[2], n_w[2], n_f[2], foot;
};

/* The standing corners of the object, into out (at most `capacity`); returns how many. */
static int standing_corners(const struct cube_layers *layers, struct standing *out, int capacity)
{
  int count = 0;
  for (int k = 1; k < layers->layer_count; ++k)
    for (int j = 0; j < layers->z_count; ++j)
      for (int i = 0; i < layers->x_count; ++i) {
        if (cells_around(layers, k, i, j) != 1 || cells_around(layers, k - 1, i, j) != 2) continue;
        int qi = 0, qj = 0;
        for (int di = -1; di <= 0; ++di)
          for (int dj = -1; dj <= 0; ++dj)
            if (cube_layers_filled(layers, k, i + di, j + dj)) qi = di, qj = dj;
        if (!(cube_layers_capped(layers, k, i + qi, j + qj) & FILLETED_FOOT)) continue;
        if (count == capacity) exit(2);
        const int qx = qi ? -1 : 1, qz = qj ? -1 : 1;
        const int past_x = cube_layers_filled(layers, k - 1, qx > 0 ? i - 1 : i, qz > 0 ? j : j - 1);
        const struct standing corner = {{layers->x[i], layers->z[j]},
                                        {past_x ? -qx : 0, past_x ? 0 : -qz},
                                        {past_x ? 0 : -qx, past_x ? -qz : 0},
                                        layers->height[k]};
        out[count++] = corner;
      }
  return count;
}

/* Point p in a standing corner's frame, a along n_w from the corner and depth behind the flush
 * plane (along -n_f); whether it lies where the torus piece and its seams do (R deep behind the
 * flush plane, within R of the corner along n_w and of the foot in height). */
static int in_standing_corner(const struct standing *c, const double p[3], double radius, double *a, double *depth)
{
  const double e = 1e-9;
  *a = (p[0] - c->g[0]) * c->n_w[0] + (p[2] - c->g[1]) * c->n_w[1];
  *depth = -((p[0] - c->g[0]) * c->n_f[0] + (p[2] - c->g[1]) * c->n_f[1]);
  return !(*depth < e || *depth > radius + e || *a < -radius - e || *a > radius + e ||
           fabs(p[1] - c->foot) > radius + e);
}

#define MAX_STANDING 64

/* How far the drawn points round each standing corner lie off R from the torus piece's centre
 * circle, at most, and how far their normals turn from the direction away from it (radians, into
 * *normal_error): the points in_standing_corner are the torus piece's and its seams' with the
 * fillet's end, the upright's foot and the rim's end. In the flush plane, with a along n_w from
 * the corner, the circle lies R deep, about the fillet's axis (a, y) = (R, foot + R), of radius
 * 2 R. */
static double standing_corner_error(const struct cube_layers *layers, double radius, double *normal_error)
{
  double worst = 0;
  *normal_error = 0;
  if (radius <= 0 || !layers) return 0;
  struct standing corners[MAX_STANDING];
  const int count = standing_corners(layers, corners, MAX_STANDING);
  for (int c = 0; c < count; ++c) {
    const double *n_w = corners[c].n_w, *n_f = corners[c].n_f, foot = corners[c].foot;
    for (size_t v = 0; v < drawn_count; ++v) {
      const double *p = drawn[v].point;
      double a, depth;
      if (!in_standing_corner(&corners[c], p, radius, &a, &depth)) continue;
      const double in_plane = hypot(a - radius, p[1] - foot - radius);
      worst = fmax(worst, fabs(hypot(in_plane - 2 * radius, depth - radius) - radius));
      /* The nearest point of the circle, and the direction from it to the point. */
      const double c_a = radius + 2 * radius * (a - radius) / in_plane;
      const double c_y = foot + radius + 2 * radius * (p[1] - foot - radius) / in_plane;
      const double out_a = a - c_a, out_depth = depth - radius, out_y = p[1] - c_y;
      const double away[3] = {out_a * n_w[0] - out_depth * n_f[0], out_y, out_a * n_w[1] - out_depth * n_f[1]};
      const double *n = drawn[v].normal;
      const double dot = (away[0] * n[0] + away[1] * n[1] + away[2] * n[2]) /
                         (sqrt(away[0] * away[0] + away[1] * away[1] + away[2] * away[2]) *
                          sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
      *normal_error = fmax(*normal_error, acos(fmin(1.0, fmax(-1.0, dot))));
    }
  }
  return worst;
}

/* The texture a point p of a standing corner's torus piece takes from the top below, the corner
 * in_standing_corner (a, depth): at angle turn about the fillet's axis from straight down and
 * angle tube round the piece's tube from the fillet's side, the top's (x, z) R - R turn out along
 * n_w and R tube - R along n_f from the corner (the fillet's unrolling, and the rim's). */
static void standing_top_texture(const struct standing *c, const double p[3], double a, double depth, double radius,
                                 double out[2])
{
  const double ra = a - radius, rb = p[1] - c->foot - radius;
  const double turn = atan2(-ra, -rb), tube = atan2(radius - depth, 2 * radius - hypot(ra, rb));
  const double along_w = radius - radius * turn, along_f = radius * tube - radius;
  for (int k = 0; k < 2; ++k) out[k] = c->g[k] + along_w * c->n_w[k] + along_f * c->n_f[k];
}

/* How far the texture of a rim's or a fillet's half drawn with a top's chart lies from that top's
 * (x, z) run on by arc length, at most, over every such vertex: at angle phi = acos |n_y| from the
 * vertical (n its unit normal) a point of the quarter circle is R sin phi from the top's edge
 * along the normal's horizontal direction h, and its texture must be the top's (x, z) R phi from
 * the edge: (x, z) + h R (phi - sin phi) on a rim, whose circle bulges out of the solid (on
 * strips, on a sphere's eighth from its pole, on a torus piece above a fillet from its inner
 * rim), (x, z) - h R (phi - sin phi) on a fillet, whose circle is hollow: there the point lies on
 * the side of the top (the nearest of the layers' heights) that its normal faces. Round a
 * standing corner, where the torus piece's part next to the top below unrolls along both its
 * quarter circles, standing_top_texture. The tops lie at the heights height[0 .. height_count - 1];
 * layers is NULL for an object drawn from its plan (no standing corners). It also says how many
 * vertices were drawn so (*count). */
static double charted_texture_error(const double *height, int height_count, const struct cube_layers *layers,
                                    float radius, size_t *count)
{
  double worst = 0;
  *count = 0;
  struct standing corners[MAX_STANDING];
  const int standing_count = radius > 0 && layers ? standing_corners(layers, corners, MAX_STANDING) : 0;
  for (size_t i = 0; i < drawn_count; ++i) {
    if (!drawn[i].charted) continue;
    ++*count;
    const double *p = drawn[i].point, *n = drawn[i].normal;
    double expected[2];
    int standing = 0;
    for (int c = 0; c < standing_count && !standing; ++c) {
      double a, depth;
      if (!in_standing_corner(&corners[c], p, radius, &a, &depth)) continue;
      standing_top_texture(&corners[c], p, a, depth, radius, expected);
      standing = 1;
    }
    if (!standing) {
      double level = height[0];
      for (int k = 1; k < height_count; ++k)
        if (fabs(height[k] - p[1]) < fabs(level - p[1])) level = height[k];
      const double sign = (p[1] - level) * n[1] > 0 ? -1.0 : 1.0;
      const double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double horizontal = hypot(n[0], n[2]);
      const double phi = acos(fmin(1.0, fabs(n[1]) / length));
      const double beyond = horizontal > 0 ? sign * radius * (phi - sin(phi)) / horizontal : 0.0;
      expected[0] = p[0] + beyond * n[0];
      expected[1] = p[2] + beyond * n[2];
    }
    worst = fmax(worst, fmax(fabs(drawn[i].texture[0] - expected[0]), fabs(drawn[i].texture[1] - expected[1])));
  }
  return worst;
}

/* Checks what was recorded of one drawing of the object `name` at `radius` (layers NULL for an
 * object drawn from its plan, its tops at the heights height[0 .. height_count - 1]), prints a
 * line and returns whether it failed. */
static int check_drawing(const char *name, float radius, const struct cube_layers *layers, const double *height,
                         int height_count)
{
  double gap;
  const size_t lonely = edges_without_twin(), rough = rough_seams(), inexact = inexact_seams(&gap);
  const double off_axis = fillet_axis_error(layers, radius);
  double standing_normal;
  const double off_circle = standing_corner_error(layers, radius, &standing_normal);
  size_t charted;
  const double chart_error = charted_texture_error(height, height_count, layers, radius, &charted);
  printf("%s at radius %g: %zu triangles, %zu edges without a twin, %zu rough seams, %zu shared patch sides "
         "not exact to 1e-12 (largest gap %.3g), fillet points off R from the axis by %.3g, standing corners' "
         "points off R from their circle by %.3g, their normals off by %.3g, %zu vertices of rims' top halves "
         "off their texture by %.3g\n", name, radius, triangle_count, lonely, rough, inexact, gap, off_axis,
         off_circle, standing_normal, charted, chart_error);
  if (gap > 1e-5) fprintf(stderr, "homework45_block_closed: %s: patches %g apart\n", name, gap);
  if (off_axis > FILLET_TOLERANCE)
    fprintf(stderr, "homework45_block_closed: %s: a fillet's point %g off R from its axis\n", name, off_axis);
  if (off_circle > FILLET_TOLERANCE || standing_normal > 1e-3)
    fprintf(stderr, "homework45_block_closed: %s: a standing corner's point %g off R from its circle, a normal "
            "%g off\n", name, off_circle, standing_normal);
  if (chart_error > CHART_TOLERANCE)
    fprintf(stderr, "homework45_block_closed: %s: a rim's top half's texture %g off the top's run on\n", name,
            chart_error);
  return lonely > 0 || rough > 0 || gap > 1e-5 || off_axis > FILLET_TOLERANCE || off_circle > FILLET_TOLERANCE ||
         standing_normal > 1e-3 || chart_error > CHART_TOLERANCE;
}

static void forget_drawing(void)
{
  triangle_count = 0;
  drawn_count = 0;
  side_count = 0;
}

int main(int argc, char **argv)
{
  int failed = 0, as_plan = 0;
  double scale[3] = {1, 1, 1};
  for (int a = 1; a < argc; ++a) {
    struct wings_mesh mesh;
    struct cube_layers layers;
    char error[300];
    if (sscanf(argv[a], "--scale=%lf,%lf,%lf", &scale[0], &scale[1], &scale[2]) == 3) continue;
    if (strcmp(argv[a], "--plan") == 0) {
      as_plan = 1;
      continue;
    }
    if (!wings_read_mesh(argv[a], &mesh, error, sizeof error)) {
      fprintf(stderr, "homework45_block_closed: %s: %s\n", argv[a], error);
      return 1;
    }
    for (long v = 0; v < mesh.vertex_count; ++v)
      for (int k = 0; k < 3; ++k) mesh.position[v][k] *= scale[k];
    const int has_cells = cube_layers_from_mesh(&mesh, &layers, error, sizeof error);
    if (!has_cells && !as_plan) {
      fprintf(stderr, "homework45_block_closed: %s: %s\n", argv[a], error);
      return 1;
    }
    if (as_plan) {
      /* As homework45 draws it: the texture's t over the object's height, or over one unit when
       * it is several layers alike. */
      struct floor_plan plan;
      if (!floor_plan_from_mesh(&mesh, has_cells && cube_layers_alike(&layers), &plan, error, sizeof error)) {
        fprintf(stderr, "homework45_block_closed: %s: %s\n", argv[a], error);
        return 1;
      }
      const float texture_height = has_cells && layers.layer_count > 1 ? 1.0f : (float)(plan.top - plan.bottom);
      const double height[2] = {plan.bottom, plan.top};
      for (int step = 0; step <= 8; ++step) {
        const float radius = (float)(plan.max_radius * step / 8);
        forget_drawing();
        draw_plan_block(&plan, radius, texture_height, 0.25f);  /* homework45's checkerboard */
        failed |= check_drawing(argv[a], radius, NULL, height, 2);
      }
      floor_plan_free(&plan);
    } else {
      for (int step = 0; step <= 8; ++step) {
        const float radius = (float)(layers.max_radius * step / 8);
        forget_drawing();
        draw_layered_block(&layers, radius);
        failed |= check_drawing(argv[a], radius, &layers, layers.height, layers.layer_count + 1);
      }
    }
    wings_mesh_free(&mesh);
    if (has_cells) cube_layers_free(&layers);
  }
  free(triangles);
  free(drawn);
  free(sides);
  return failed;
}
