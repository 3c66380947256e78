/* The GLU tessellator (GLU 1.3, chapter 5), as red book programs use it, in a 4 x 3 grid.
 *
 * Top row: a rectangle with a triangular hole (two contours, combine callback set); a
 * self-intersecting star with GLU_TESS_WINDING_POSITIVE whose crossings get colours interpolated
 * by the combine callback (smooth shading, _DATA callbacks); a convex hexagon with a colour per
 * vertex (output as one fan, identical to SGI's); a concave polygon with a hole in the GLU 1.0
 * interface (gluBeginPolygon, gluNextContour, gluEndPolygon) in a tilted plane, which the
 * tessellator finds itself.
 * Middle row and the first panel of the bottom row: three overlapping, differently oriented
 * rectangles under the five winding rules (ODD, NONZERO, POSITIVE, NEGATIVE, ABS_GEQ_TWO).
 * Bottom row, then: the same rectangles' boundary under NONZERO (GLU_TESS_BOUNDARY_ONLY, line
 * loops); a concave polygon with a hole drawn in GL_LINE mode with the edge flag callback set, so
 * that only its outline shows; the same filled. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

#include <math.h>
#include <stdlib.h>

enum { WIDTH = 480, HEIGHT = 360, CELL = 120 };

/* A vertex as the callbacks see it: position and colour. */
typedef struct {
  GLdouble xyz[3];
  GLdouble rgb[3];
} ColorVertex;

/* Vertices the combine callback creates; freed at the end of the frame. */
static ColorVertex *created[64];
static int createdCount;

static void GLAPIENTRY beginCallback(GLenum type) { glBegin(type); }
static void GLAPIENTRY endCallback(void) { glEnd(); }
static void GLAPIENTRY vertexCallback(void *data) { glVertex3dv((const GLdouble *)data); }
static void GLAPIENTRY colorVertexCallback(void *data, void *polygon)
{
  const ColorVertex *v = (const ColorVertex *)data;
  (void)polygon;
  glColor3dv(v->rgb);
  glVertex3dv(v->xyz);
}
static void GLAPIENTRY edgeFlagCallback(GLboolean flag) { glEdgeFlag(flag); }

static void GLAPIENTRY combineCallback(GLdouble coords[3], void *data[4], GLfloat weight[4],
                                       void **out)
{
  GLdouble *v = (GLdouble *)malloc(3 * sizeof(GLdouble));
  (void)data;
  (void)weight;
  v[0] = coords[0];
  v[1] = coords[1];
  v[2] = coords[2];
  created[createdCount++] = (ColorVertex *)(void *)v;
  *out = v;
}

static void GLAPIENTRY combineColorCallback(GLdouble coords[3], void *data[4], GLfloat weight[4],
                                            void **out, void *polygon)
{
  ColorVertex *v = (ColorVertex *)malloc(sizeof(ColorVertex));
  int i, k;
  (void)polygon;
  for (i = 0; i < 3; ++i) v->xyz[i] = coords[i];
  for (k = 0; k < 3; ++k) {
    v->rgb[k] = 0.0;
    for (i = 0; i < 4; ++i) {
      if (data[i]) v->rgb[k] += weight[i] * ((ColorVertex *)data[i])->rgb[k];
    }
  }
  created[createdCount++] = v;
  *out = v;
}

static void cell(int column, int row)
{
  glViewport(column * CELL, HEIGHT - (row + 1) * CELL, CELL, CELL);
}

static void contour(GLUtesselator *tess, GLdouble (*points)[3], int count)
{
  int i;
  gluTessBeginContour(tess);
  for (i = 0; i < count; ++i) gluTessVertex(tess, points[i], points[i]);
  gluTessEndContour(tess);
}

static void plainCallbacks(GLUtesselator *tess)
{
  gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
  gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
  gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
  gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combineCallback);
}

static void rectangleWithHole(GLUtesselator *tess)
{
  static GLdouble outer[4][3] = {{-0.8, -0.6, 0}, {0.8, -0.6, 0}, {0.8, 0.6, 0}, {-0.8, 0.6, 0}};
  static GLdouble hole[3][3] = {{-0.3, -0.3, 0}, {0.0, 0.4, 0}, {0.3, -0.3, 0}};
  glColor3f(0.9f, 0.2f, 0.2f);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, outer, 4);
  contour(tess, hole, 3);
  gluTessEndPolygon(tess);
}

static void colouredStar(GLUtesselator *tess)
{
  static ColorVertex star[5] = {
      {{0.0, 0.85, 0}, {1, 0, 0}},     {{0.5, -0.7, 0}, {0, 1, 0}},  {{-0.8, 0.25, 0}, {0, 0, 1}},
      {{0.8, 0.25, 0}, {1, 1, 0}},     {{-0.5, -0.7, 0}, {1, 0, 1}}};
  int i;
  gluTessCallback(tess, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)colorVertexCallback);
  gluTessCallback(tess, GLU_TESS_COMBINE_DATA, (_GLUfuncptr)combineColorCallback);
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
  gluTessBeginPolygon(tess, star);
  gluTessBeginContour(tess);
  for (i = 0; i < 5; ++i) gluTessVertex(tess, star[i].xyz, &star[i]);
  gluTessEndContour(tess);
  gluTessEndPolygon(tess);
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
  gluTessCallback(tess, GLU_TESS_VERTEX_DATA, NULL);
  gluTessCallback(tess, GLU_TESS_COMBINE_DATA, NULL);
}

static void colouredHexagon(GLUtesselator *tess)
{
  static ColorVertex hexagon[6] = {
      {{0.8, 0.0, 0}, {1, 0, 0}},    {{0.4, 0.7, 0}, {1, 1, 0}},   {{-0.4, 0.7, 0}, {0, 1, 0}},
      {{-0.8, 0.0, 0}, {0, 1, 1}},   {{-0.4, -0.7, 0}, {0, 0, 1}}, {{0.4, -0.7, 0}, {1, 0, 1}}};
  int i;
  gluTessCallback(tess, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)colorVertexCallback);
  gluTessBeginPolygon(tess, NULL);
  gluTessBeginContour(tess);
  for (i = 0; i < 6; ++i) gluTessVertex(tess, hexagon[i].xyz, &hexagon[i]);
  gluTessEndContour(tess);
  gluTessEndPolygon(tess);
  gluTessCallback(tess, GLU_TESS_VERTEX_DATA, NULL);
}

/* The polygon lies in a tilted plane through the origin (turned 50 degrees about x, then 30
 * about y), so the tessellator must find the plane from the vertices. */
static void tilt(GLdouble (*points)[3], int count)
{
  const double ax = 50.0 * 3.14159265358979323846 / 180.0, ay = 30.0 * 3.14159265358979323846 / 180.0;
  int i;
  for (i = 0; i < count; ++i) {
    const double x = points[i][0], y = points[i][1] * cos(ax), z = points[i][1] * sin(ax);
    points[i][0] = x * cos(ay) + z * sin(ay);
    points[i][1] = y;
    points[i][2] = -x * sin(ay) + z * cos(ay);
  }
}

static void tiltedConcaveWithHole(GLUtesselator *tess)
{
  /* The outer contour repeats its first vertex at the end, as programs often do. */
  GLdouble outer[6][3] = {{-0.7, -0.7, 0}, {0.7, -0.7, 0}, {0.7, 0.7, 0},
                          {0.0, 0.1, 0},   {-0.7, 0.7, 0}, {-0.7, -0.7, 0}};
  GLdouble hole[4][3] = {{-0.2, -0.5, 0}, {-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, -0.5, 0}};
  int i;
  tilt(outer, 6);
  tilt(hole, 4);
  glColor3f(0.2f, 0.7f, 0.9f);
  gluBeginPolygon(tess);
  for (i = 0; i < 6; ++i) gluTessVertex(tess, outer[i], outer[i]);
  gluNextContour(tess, GLU_INTERIOR);
  for (i = 0; i < 4; ++i) gluTessVertex(tess, hole[i], hole[i]);
  gluEndPolygon(tess);
}

static GLdouble rects[3][4][3] = {
    {{-0.8, -0.8, 0}, {0.4, -0.8, 0}, {0.4, 0.4, 0}, {-0.8, 0.4, 0}},
    {{-0.4, -0.4, 0}, {0.8, -0.4, 0}, {0.8, 0.8, 0}, {-0.4, 0.8, 0}},
    {{-0.6, -0.2, 0}, {-0.6, 0.6, 0}, {0.2, 0.6, 0}, {0.2, -0.2, 0}}};

static void overlappingRectangles(GLUtesselator *tess, GLenum rule)
{
  int i;
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule);
  gluTessBeginPolygon(tess, NULL);
  for (i = 0; i < 3; ++i) contour(tess, rects[i], 4);
  gluTessEndPolygon(tess);
  gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
}

static GLdouble frame[5][3] = {
    {-0.8, -0.8, 0}, {0.8, -0.8, 0}, {0.8, 0.8, 0}, {0.0, 0.2, 0}, {-0.8, 0.8, 0}};
static GLdouble window[4][3] = {{-0.4, -0.5, 0}, {-0.4, 0.0, 0}, {0.4, 0.0, 0}, {0.4, -0.5, 0}};

static void draw(void)
{
  GLUtesselator *tess = gluNewTess();
  static const GLenum rules[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
                                  GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE,
                                  GLU_TESS_WINDING_ABS_GEQ_TWO};
  int i;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  plainCallbacks(tess);

  cell(0, 0);
  rectangleWithHole(tess);
  cell(1, 0);
  colouredStar(tess);
  cell(2, 0);
  colouredHexagon(tess);
  cell(3, 0);
  tiltedConcaveWithHole(tess);

  for (i = 0; i < 5; ++i) {
    cell((i + 0) % 4, 1 + (i + 0) / 4);
    glColor3f(0.3f + 0.15f * (float)i, 0.8f - 0.1f * (float)i, 0.3f);
    overlappingRectangles(tess, rules[i]);
  }

  cell(1, 2);
  glColor3f(1.0f, 1.0f, 1.0f);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
  overlappingRectangles(tess, GLU_TESS_WINDING_NONZERO);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);

  cell(2, 2);
  glColor3f(1.0f, 0.8f, 0.3f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  gluTessCallback(tess, GLU_TESS_EDGE_FLAG, (_GLUfuncptr)edgeFlagCallback);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, frame, 5);
  contour(tess, window, 4);
  gluTessEndPolygon(tess);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

  cell(3, 2);
  glColor3f(0.6f, 0.4f, 0.9f);
  gluTessBeginPolygon(tess, NULL);
  contour(tess, frame, 5);
  contour(tess, window, 4);
  gluTessEndPolygon(tess);
  gluTessCallback(tess, GLU_TESS_EDGE_FLAG, NULL);

  gluDeleteTess(tess);
  for (i = 0; i < createdCount; ++i) free(created[i]);
  createdCount = 0;
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
