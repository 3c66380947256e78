/* glMultiDrawArrays and glMultiDrawElements (OpenGL 1.4, section 2.8) and glDrawRangeElements
 * (1.2), as programs batch many small shapes into one call. Each entry of a multi-draw is a
 * primitive of its own, as if glDrawArrays or glDrawElements were called once per entry: a loop
 * closes on its own first vertex, a strip or fan starts afresh, the line stipple restarts, and
 * flat shading counts the provoking vertex from the entry's start. Six panels:
 *
 *   top:    line loops, stippled (0x0F0F, factor 2), from one glMultiDrawArrays with an entry of
 *           count 0 and one of count 1 among them (they draw nothing); the same shapes as line
 *           strips, flat shaded; three flat-shaded triangle fans (each fan's colours start over)
 *   bottom: triangle strips of a grid from glMultiDrawElements (GL_UNSIGNED_SHORT index lists of
 *           different lengths, one odd, whose last vertex is left over); glDrawRangeElements of
 *           GL_QUADS from GL_UNSIGNED_BYTE indices that use only the middle of the arrays (the
 *           range given), a count that is not a multiple of 4 (the last 3 are ignored); polygons
 *           in GL_LINE mode from glMultiDrawArrays with an edge-flag array hiding their inner
 *           edges, and a display list compiled from glMultiDrawArrays whose arrays are then
 *           changed: the list keeps the vertices of compile time (spec 5.4), drawn beside the
 *           changed arrays. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { PANEL = 160, WIDTH = 3 * PANEL, HEIGHT = 2 * PANEL, GRID = 6 };

/* Regular polygons, one after another in one array: corners, their colours. */
enum { SHAPES = 5, MAX_CORNERS = 64 };
static GLfloat shapeXY[MAX_CORNERS][2];
static GLubyte shapeRGB[MAX_CORNERS][3];
static GLint shapeFirst[SHAPES];
static GLsizei shapeCount[SHAPES];

static void makeShapes(float cx0, float cy0)
{
  /* Corners per shape: a triangle, nothing, a hexagon, a single vertex, a pentagon. */
  static const int corners[SHAPES] = {3, 0, 6, 1, 5};
  static const float centres[SHAPES][2] = {{35, 40}, {0, 0}, {105, 45}, {80, 80}, {75, 110}};
  static const float radii[SHAPES] = {28, 0, 34, 0, 36};
  int n = 0;
  for (int s = 0; s < SHAPES; ++s) {
    shapeFirst[s] = n;
    shapeCount[s] = corners[s];
    for (int i = 0; i < corners[s]; ++i, ++n) {
      const double a = 0.3 + 6.283185307179586 * i / corners[s];
      shapeXY[n][0] = cx0 + centres[s][0] + radii[s] * (float)cos(a);
      shapeXY[n][1] = cy0 + centres[s][1] + radii[s] * (float)sin(a);
      shapeRGB[n][0] = (GLubyte)(60 + 40 * i);
      shapeRGB[n][1] = (GLubyte)(250 - 35 * i);
      shapeRGB[n][2] = (GLubyte)(s * 60);
    }
  }
}

static void useShapeArrays(void)
{
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, shapeXY);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, shapeRGB);
}

static void stippledLoops(void)
{
  makeShapes(0.0f, PANEL);
  useShapeArrays();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0F0F);
  glLineWidth(2.0f);
  glMultiDrawArrays(GL_LINE_LOOP, shapeFirst, shapeCount, SHAPES);
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
}

static void flatStrips(void)
{
  makeShapes(PANEL, PANEL);
  useShapeArrays();
  glShadeModel(GL_FLAT);
  glMultiDrawArrays(GL_LINE_STRIP, shapeFirst, shapeCount, SHAPES);
  /* Their corners as points, smooth, to show which colour each segment took. */
  glShadeModel(GL_SMOOTH);
  glPointSize(5.0f);
  glMultiDrawArrays(GL_POINTS, shapeFirst, shapeCount, SHAPES);
  glPointSize(1.0f);
}

static void flatFans(void)
{
  makeShapes(2 * PANEL, PANEL);
  useShapeArrays();
  glShadeModel(GL_FLAT);
  glMultiDrawArrays(GL_TRIANGLE_FAN, shapeFirst, shapeCount, SHAPES);
  glShadeModel(GL_SMOOTH);
}

/* A (GRID + 1) x (GRID + 1) grid of vertices in the bottom-left panel, strips of rows. */
static void gridStrips(void)
{
  static GLfloat xy[GRID + 1][GRID + 1][2];
  static GLubyte rgb[GRID + 1][GRID + 1][3];
  static GLushort rows[GRID][2 * (GRID + 1)];
  for (int j = 0; j <= GRID; ++j) {
    for (int i = 0; i <= GRID; ++i) {
      xy[j][i][0] = 12.0f + 22.5f * i + 3.0f * j;
      xy[j][i][1] = 10.0f + 22.0f * j + 2.0f * (float)sin(i);
      rgb[j][i][0] = (GLubyte)(40 * i);
      rgb[j][i][1] = (GLubyte)(40 * j);
      rgb[j][i][2] = (GLubyte)(((i + j) & 1) ? 220 : 90);
    }
  }
  GLsizei counts[GRID];
  const void *lists[GRID];
  for (int j = 0; j < GRID; ++j) {
    for (int i = 0; i <= GRID; ++i) {
      rows[j][2 * i] = (GLushort)((j + 1) * (GRID + 1) + i);
      rows[j][2 * i + 1] = (GLushort)(j * (GRID + 1) + i);
    }
    /* Rows of different lengths: full, shorter, and one odd count. */
    counts[j] = 2 * (GRID + 1) - 2 * (j % 3);
    lists[j] = rows[j];
  }
  counts[3] = 9;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, xy);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb);
  glMultiDrawElements(GL_TRIANGLE_STRIP, counts, GL_UNSIGNED_SHORT, lists, GRID);
}

static void rangeQuads(void)
{
  /* 24 vertices in a 6 x 4 lattice; the indices use 6..17 only (the middle two rows). */
  static GLfloat xy[24][3];
  static GLfloat rgba[24][4];
  for (int k = 0; k < 24; ++k) {
    const int i = k % 6, j = k / 6;
    xy[k][0] = PANEL + 10.0f + 27.0f * i + (j == 2 ? 6.0f : 0.0f);
    xy[k][1] = -40.0f + 62.0f * j;
    xy[k][2] = 0.0f;
    rgba[k][0] = i / 5.0f;
    rgba[k][1] = 0.3f + 0.2f * j;
    rgba[k][2] = 1.0f - i / 5.0f;
    rgba[k][3] = 1.0f;
  }
  /* Three quads between rows 1 and 2, then three indices that make no quad. */
  static const GLubyte indices[15] = {6, 7, 13, 12, 8, 9, 15, 14, 10, 11, 17, 16, 6, 11, 17};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xy);
  glColorPointer(4, GL_FLOAT, 0, rgba);
  glDrawRangeElements(GL_QUADS, 6, 17, 15, GL_UNSIGNED_BYTE, indices);
}

/* Two concave outlines split into triangles, as a tessellator hands them over, drawn in
 * GL_LINE mode: the edge flags hide the diagonals. */
static void edgeFlagPolygons(void)
{
  static GLfloat xy[12][2] = {
      /* an arrow as two triangles and a quad, for GL_TRIANGLES... */
      {10, 110}, {50, 150}, {50, 130}, {10, 110}, {50, 130}, {50, 90},
      /* ...and a quad */
      {50, 130}, {90, 130}, {90, 90}, {50, 90}, {0, 0}, {0, 0}};
  static GLboolean flags[12] = {GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE,
                                GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
  const GLint first[2] = {0, 6};
  const GLsizei count[2] = {6, 4};
  glPushMatrix();
  glTranslatef(2 * PANEL + 8.0f, 0.0f, 0.0f);
  glDisableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, xy);
  glEdgeFlagPointer(0, flags);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(1.0f, 1.0f, 0.3f);
  glLineWidth(2.0f);
  /* The first entry as GL_TRIANGLES, the second (a quad) as one more GL_POLYGON. */
  glMultiDrawArrays(GL_TRIANGLES, first, count, 1);
  glMultiDrawArrays(GL_POLYGON, first + 1, count + 1, 1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glLineWidth(1.0f);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glPopMatrix();
}

static void compiledList(void)
{
  static GLfloat xy[8][2] = {{0, 0}, {30, 0}, {30, 30}, {0, 30}, {40, 5}, {60, 5}, {50, 35}, {0, 0}};
  static GLubyte rgb[8][3] = {{255, 80, 80}, {255, 160, 80}, {255, 255, 80}, {160, 255, 80},
                              {80, 200, 255}, {80, 80, 255}, {200, 80, 255}, {0, 0, 0}};
  const GLint first[2] = {0, 4};
  const GLsizei count[2] = {4, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, xy);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMultiDrawArrays(GL_POLYGON, first, count, 2);
  glEndList();
  /* Change the arrays after compiling: the list must not see this. */
  for (int i = 0; i < 7; ++i) {
    xy[i][1] += 8.0f * (i % 2);
    rgb[i][0] = (GLubyte)(255 - rgb[i][0]);
    rgb[i][2] = (GLubyte)(255 - rgb[i][2]);
  }
  glPushMatrix();
  glTranslatef(2 * PANEL + 20.0f, 12.0f, 0.0f);
  glCallList(list);
  glTranslatef(70.0f, 0.0f, 0.0f);
  glMultiDrawArrays(GL_POLYGON, first, count, 2);
  glPopMatrix();
  glDeleteLists(list, 1);
}

static void draw(void)
{
  glClearColor(0.12f, 0.12f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* Panel frames. */
  glColor3f(0.35f, 0.35f, 0.4f);
  glBegin(GL_LINES);
  glVertex2f(0.0f, PANEL + 0.5f);
  glVertex2f(WIDTH, PANEL + 0.5f);
  glVertex2f(PANEL + 0.5f, 0.0f);
  glVertex2f(PANEL + 0.5f, HEIGHT);
  glVertex2f(2 * PANEL + 0.5f, 0.0f);
  glVertex2f(2 * PANEL + 0.5f, HEIGHT);
  glEnd();

  stippledLoops();
  flatStrips();
  flatFans();
  gridStrips();
  rangeQuads();
  edgeFlagPolygons();
  compiledList();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
