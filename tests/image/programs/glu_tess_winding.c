/* The GLU tessellator's winding rules (GLU 1.3, section 5.5) on shapes the glu_tessellation
 * program leaves out, in a 4 x 3 grid of flat-coloured panels:
 *   top row: three nested squares all counter-clockwise (winding numbers 1, 2 and 3 from the
 *     outside in) under GLU_TESS_WINDING_ODD, NONZERO, POSITIVE and ABS_GEQ_TWO;
 *   middle row: a pentagram (a self-intersecting contour whose centre winds twice) under ODD and
 *     ABS_GEQ_TWO; the nested squares with the middle one clockwise (winding 1, 0, 1) under
 *     NONZERO; the pentagram with gluTessNormal(0, 0, -1), which makes its windings negative,
 *     under GLU_TESS_WINDING_NEGATIVE;
 *   bottom row: GLU_TESS_BOUNDARY_ONLY of the nested squares under ABS_GEQ_TWO and of the
 *     pentagram under NONZERO (line loops); two squares sharing an edge and a corner square
 *     touching them at one vertex, under NONZERO; a contour with repeated vertices and a spike
 *     that folds back on itself, under ODD.
 * The coverage is decided by the winding rule and the fill rule on the same vertices (inputs and
 * crossings), so it must be exactly Mesa's. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

#include <math.h>

enum { WIDTH = 480, HEIGHT = 360, CELL = 120 };

/* The crossings the combine callback is given, kept for the rest of the frame. */
static GLdouble crossings[256][3];
static int crossingCount;

static void GLAPIENTRY beginCallback(GLenum type) { glBegin(type); }
static void GLAPIENTRY endCallback(void) { glEnd(); }
static void GLAPIENTRY vertexCallback(void *data) { glVertex3dv((const GLdouble *)data); }
static void GLAPIENTRY combineCallback(GLdouble coords[3], void *data[4], GLfloat weight[4],
                                       void **out)
{
  GLdouble *crossing = crossings[crossingCount++];
  (void)data;
  (void)weight;
  for (int k = 0; k < 3; ++k) crossing[k] = coords[k];
  *out = crossing;
}

static GLdouble squares[3][4][3];
static GLdouble star[5][3];

static void makeShapes(void)
{
  for (int s = 0; s < 3; ++s) {
    const double r = 0.9 - 0.3 * s;
    const double corners[4][2] = {{-r, -r}, {r, -r}, {r, r}, {-r, r}};
    for (int i = 0; i < 4; ++i) {
      squares[s][i][0] = corners[i][0];
      squares[s][i][1] = corners[i][1];
      squares[s][i][2] = 0.0;
    }
  }
  for (int i = 0; i < 5; ++i) {
    /* Every second point of a regular pentagon: a pentagram, counter-clockwise. */
    const double a = 1.5707963267948966 + 2.0 * 3.141592653589793 * (2 * i % 5) / 5.0;
    star[i][0] = 0.92 * cos(a);
    star[i][1] = 0.92 * sin(a) - 0.08;
    star[i][2] = 0.0;
  }
}

static void cell(int column, int row)
{
  glViewport(column * CELL, HEIGHT - (row + 1) * CELL, CELL, CELL);
}

static void contour(GLUtesselator *tess, GLdouble (*points)[3], int count, int reversed)
{
  gluTessBeginContour(tess);
  for (int i = 0; i < count; ++i) {
    GLdouble *p = points[reversed ? count - 1 - i : i];
    gluTessVertex(tess, p, p);
  }
  gluTessEndContour(tess);
}

/* The three nested squares, the middle one reversed if asked. */
static void nested(GLUtesselator *tess, GLenum winding, int middleReversed)
{
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, winding);
  gluTessBeginPolygon(tess, NULL);
  for (int s = 0; s < 3; ++s) contour(tess, squares[s], 4, s == 1 && middleReversed);
  gluTessEndPolygon(tess);
}

static void pentagram(GLUtesselator *tess, GLenum winding)
{
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, winding);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, star, 5, 0);
  gluTessEndPolygon(tess);
}

static void sharedEdges(GLUtesselator *tess)
{
  static GLdouble left[4][3] = {{-0.8, -0.6, 0}, {0.0, -0.6, 0}, {0.0, 0.2, 0}, {-0.8, 0.2, 0}};
  static GLdouble right[4][3] = {{0.0, -0.6, 0}, {0.8, -0.6, 0}, {0.8, 0.2, 0}, {0.0, 0.2, 0}};
  static GLdouble corner[3][3] = {{0.8, 0.2, 0}, {0.8, 0.85, 0}, {0.2, 0.85, 0}};
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_NONZERO);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, left, 4, 0);
  contour(tess, right, 4, 0);
  contour(tess, corner, 3, 0);
  gluTessEndPolygon(tess);
}

static void degenerate(GLUtesselator *tess)
{
  /* A square with a doubled corner, a vertex repeated along an edge, and a spike out and back. */
  static GLdouble points[9][3] = {{-0.7, -0.7, 0}, {-0.7, -0.7, 0}, {0.0, -0.7, 0}, {0.7, -0.7, 0},
                                  {0.7, 0.0, 0}, {0.95, 0.5, 0}, {0.7, 0.0, 0}, {0.7, 0.7, 0},
                                  {-0.7, 0.7, 0}};
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, points, 9, 0);
  gluTessEndPolygon(tess);
}

static void draw(void)
{
  static const GLenum rules[4] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
                                  GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};
  GLUtesselator *tess = gluNewTess();
  makeShapes();
  gluTessCallback(tess, GLU_TESS_BEGIN, (void(GLAPIENTRY *)(void))beginCallback);
  gluTessCallback(tess, GLU_TESS_END, (void(GLAPIENTRY *)(void))endCallback);
  gluTessCallback(tess, GLU_TESS_VERTEX, (void(GLAPIENTRY *)(void))vertexCallback);
  gluTessCallback(tess, GLU_TESS_COMBINE, (void(GLAPIENTRY *)(void))combineCallback);

  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  for (int i = 0; i < 4; ++i) {
    cell(i, 0);
    glColor3f(0.3f + 0.2f * i, 0.8f - 0.15f * i, 0.4f);
    nested(tess, rules[i], 0);
  }

  cell(0, 1);
  glColor3f(0.9f, 0.7f, 0.2f);
  pentagram(tess, GLU_TESS_WINDING_ODD);
  cell(1, 1);
  glColor3f(0.9f, 0.4f, 0.3f);
  pentagram(tess, GLU_TESS_WINDING_ABS_GEQ_TWO);
  cell(2, 1);
  glColor3f(0.4f, 0.6f, 0.95f);
  nested(tess, GLU_TESS_WINDING_NONZERO, 1);
  cell(3, 1);
  glColor3f(0.7f, 0.5f, 0.9f);
  gluTessNormal(tess, 0.0, 0.0, -1.0);
  pentagram(tess, GLU_TESS_WINDING_NEGATIVE);
  gluTessNormal(tess, 0.0, 0.0, 0.0);

  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
  cell(0, 2);
  glColor3f(0.9f, 0.9f, 0.9f);
  nested(tess, GLU_TESS_WINDING_ABS_GEQ_TWO, 0);
  cell(1, 2);
  glColor3f(0.5f, 0.95f, 0.6f);
  pentagram(tess, GLU_TESS_WINDING_NONZERO);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);
  cell(2, 2);
  glColor3f(0.95f, 0.6f, 0.3f);
  sharedEdges(tess);
  cell(3, 2);
  glColor3f(0.3f, 0.8f, 0.8f);
  degenerate(tess);

  gluDeleteTess(tess);
  crossingCount = 0;
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
