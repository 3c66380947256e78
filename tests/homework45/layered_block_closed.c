/* Whether the surface layered_block.c draws is closed: the drawing is recorded by stand-ins for
 * the GL calls it makes (the evaluator's quarter cylinders evaluated here, as glEvalMesh2 would),
 * cut into triangles, and every triangle edge must have a twin, an edge of another triangle with
 * the same end points (to 1e-5): a crack, a hole or a T-junction leaves an edge without one. Each
 * object named on the command line is checked at nine radii from 0 to its largest.
 *   homework45_layered_closed OBJECT.wings...
 * Prints a line per object and radius, and exits 1 when an edge has no twin. */
#include <GL/glut.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cube_layers.h"
#include "layered_block.h"

struct triangle {
  double corner[3][3];
};

static struct triangle *triangles;
static size_t triangle_count, triangle_capacity;
/* The vertices of the primitive between glBegin and glEnd. */
static double primitive[4096][3];
static int primitive_count;
static GLenum primitive_mode;
static GLfloat cylinder_net[3][3][4];
static int net_rows;
static int grid_steps_u, grid_steps_v;

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
  else if (primitive_mode == GL_TRIANGLE_FAN)
    for (int i = 1; i + 1 < primitive_count; ++i) add_triangle(v[0], v[i], v[i + 1]);
  else {
    fprintf(stderr, "homework45_layered_closed: primitive mode %u not recorded\n", primitive_mode);
    exit(2);
  }
}

void glVertex3d(GLdouble x, GLdouble y, GLdouble z)
{
  if (primitive_count == 4096) exit(2);
  primitive[primitive_count][0] = x;
  primitive[primitive_count][1] = y;
  primitive[primitive_count][2] = z;
  ++primitive_count;
}

void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { glVertex3d(x, y, z); }
void glTexCoord2f(GLfloat s, GLfloat t) { (void)s, (void)t; }
void glTexCoord2d(GLdouble s, GLdouble t) { (void)s, (void)t; }
void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { (void)x, (void)y, (void)z; }
void glEnable(GLenum capability) { (void)capability; }
void glDisable(GLenum capability) { (void)capability; }

void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2,
             GLint vstride, GLint vorder, const GLfloat *points)
{
  (void)u1, (void)u2, (void)v1, (void)v2;
  if (target != GL_MAP2_VERTEX_4) return;
  if (ustride != 4 || uorder != 3 || vstride != 12 || (vorder != 2 && vorder != 3)) exit(2);
  net_rows = vorder;
  memcpy(cylinder_net, points, (size_t)vorder * sizeof cylinder_net[0]);
}

void glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2)
{
  (void)u1, (void)u2, (void)v1, (void)v2;
  grid_steps_u = un;
  grid_steps_v = vn;
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

void glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2)
{
  (void)mode;
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

/* An edge's end points rounded to 1e-5, the smaller first. */
struct edge_key {
  long long end[2][3];
};

static int compare_edges(const void *a, const void *b) { return memcmp(a, b, sizeof(struct edge_key)); }

static void round_point(const double p[3], long long out[3])
{
  for (int k = 0; k < 3; ++k) out[k] = llround(p[k] * 1e5);
}

/* How many of the recorded triangles' edges have no twin (degenerate triangles, such as a fan's
 * at a cylinder's pole, left out). */
static size_t edges_without_twin(void)
{
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
    lonely += (j - i) % 2;
    i = j;
  }
  free(edges);
  return lonely;
}

int main(int argc, char **argv)
{
  int failed = 0;
  for (int a = 1; a < argc; ++a) {
    struct wings_mesh mesh;
    struct cube_layers layers;
    char error[300];
    if (!wings_read_mesh(argv[a], &mesh, error, sizeof error) ||
        !cube_layers_from_mesh(&mesh, &layers, error, sizeof error)) {
      fprintf(stderr, "homework45_layered_closed: %s: %s\n", argv[a], error);
      return 1;
    }
    wings_mesh_free(&mesh);
    for (int step = 0; step <= 8; ++step) {
      const float radius = (float)(layers.max_radius * step / 8);
      triangle_count = 0;
      draw_layered_block(&layers, radius);
      const size_t lonely = edges_without_twin();
      printf("%s at radius %g: %zu triangles, %zu edges without a twin\n", argv[a], radius, triangle_count, lonely);
      failed |= lonely > 0;
    }
    cube_layers_free(&layers);
  }
  free(triangles);
  return failed;
}
