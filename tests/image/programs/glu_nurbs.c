/* GLU NURBS (GLU 1.3, chapter 7) as the red book draws them, in four panels.
 *
 * Top left: the red book's hill, a bicubic surface of 4 x 4 control points with a bump in the
 * middle, lit with GL_AUTO_NORMAL, sampling tolerance 25 pixels. Top right: the same surface
 * trimmed: an outer piecewise linear loop and a hole made of a NURBS curve and a piecewise linear
 * curve (the red book's trim program). Bottom left: a NURBS curve of 7 control points with
 * interior knots, and a rational quadratic NURBS circle of 9 points (weights 1 and sqrt(2)/2).
 * Bottom right: a rational surface (a quarter of a cylinder, weights sqrt(2)/2 in the middle row)
 * built from two knot spans in each direction, lit. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

#include <math.h>

enum { WIDTH = 500, HEIGHT = 500 };

static GLfloat hill[4][4][3];

static void initHill(void)
{
  int u, v;
  for (u = 0; u < 4; u++) {
    for (v = 0; v < 4; v++) {
      hill[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
      hill[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
      hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
    }
  }
}

static void light(void)
{
  static const GLfloat diffuse[] = {0.7f, 0.7f, 0.7f, 1.0f};
  static const GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat shininess[] = {100.0f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialfv(GL_FRONT, GL_SHININESS, shininess);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
}

static void panel(int column, int row)
{
  glViewport(column * WIDTH / 2, HEIGHT / 2 - row * HEIGHT / 2, WIDTH / 2, HEIGHT / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 1.0, 3.0, 8.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
}

static void hillSurface(GLUnurbsObj *nurb, int trimmed)
{
  static GLfloat knots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  static GLfloat edge[5][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f},
                               {0.0f, 0.0f}};
  static GLfloat curvePoints[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f},
                                      {0.75f, 0.5f}};
  static GLfloat curveKnots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  static GLfloat pwl[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
  glPushMatrix();
  glRotatef(330.0f, 1.0f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  if (trimmed) {
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluNurbsCurve(nurb, 8, curveKnots, 2, &curvePoints[0][0], 4, GLU_MAP1_TRIM_2);
    gluPwlCurve(nurb, 3, &pwl[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
  }
  gluEndSurface(nurb);
  glPopMatrix();
}

static void curves(GLUnurbsObj *nurb)
{
  static GLfloat wave[7][3] = {{-1.6f, -0.8f, 0}, {-1.2f, 0.8f, 0}, {-0.6f, -1.2f, 0},
                               {0.0f, 1.0f, 0},   {0.6f, -0.6f, 0}, {1.2f, 1.2f, 0},
                               {1.6f, -0.4f, 0}};
  static GLfloat waveKnots[11] = {0, 0, 0, 0, 1, 2, 2.5f, 4, 4, 4, 4};
  const GLfloat h = 0.70710678f;
  GLfloat circle[9][4] = {{1, 0, 0, 1}, {h, h, 0, h},   {0, 1, 0, 1},   {-h, h, 0, h},
                          {-1, 0, 0, 1}, {-h, -h, 0, h}, {0, -1, 0, 1}, {h, -h, 0, h},
                          {1, 0, 0, 1}};
  static GLfloat circleKnots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  glDisable(GL_LIGHTING);
  glLineWidth(2.0f);
  glColor3f(1.0f, 0.9f, 0.3f);
  glPushMatrix();
  glTranslatef(0.0f, 0.6f, 0.0f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 11, waveKnots, 3, &wave[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  glPopMatrix();
  glColor3f(0.3f, 0.9f, 1.0f);
  glPushMatrix();
  glTranslatef(0.0f, -0.9f, 0.0f);
  glScalef(0.8f, 0.8f, 0.8f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 12, circleKnots, 4, &circle[0][0], 3, GL_MAP1_VERTEX_4);
  gluEndCurve(nurb);
  glPopMatrix();
  glLineWidth(1.0f);
  glEnable(GL_LIGHTING);
}

static void quarterCylinder(GLUnurbsObj *nurb)
{
  /* Rows along u go around the quarter circle (3 points, the middle one of weight sqrt(2)/2,
   * stored homogeneous), columns along v go along the axis (4 points, two cubic spans). */
  const GLfloat h = 0.70710678f;
  static GLfloat uKnots[6] = {0, 0, 0, 1, 1, 1};
  static GLfloat vKnots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
  GLfloat net[3][5][4];
  const GLfloat arc[3][3] = {{1, 0, 1}, {1, 1, h}, {0, 1, 1}};
  int i, j;
  for (i = 0; i < 3; ++i) {
    for (j = 0; j < 5; ++j) {
      const GLfloat w = arc[i][2];
      const GLfloat z = -1.2f + 0.6f * (GLfloat)j;
      const GLfloat bulge = (j == 2) ? 1.3f : 1.0f;
      net[i][j][0] = arc[i][0] * bulge * w;
      net[i][j][1] = arc[i][1] * bulge * w;
      net[i][j][2] = z * w;
      net[i][j][3] = w;
    }
  }
  glPushMatrix();
  glRotatef(-60.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 6, uKnots, 9, vKnots, 5 * 4, 4, &net[0][0][0], 3, 4, GL_MAP2_VERTEX_4);
  gluEndSurface(nurb);
  glPopMatrix();
}

static void draw(void)
{
  GLUnurbsObj *nurb = gluNewNurbsRenderer();
  initHill();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  light();
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 25.0f);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);

  panel(0, 0);
  hillSurface(nurb, 0);
  panel(1, 0);
  hillSurface(nurb, 1);
  panel(0, 1);
  curves(nurb);
  panel(1, 1);
  quarterCylinder(nurb);

  gluDeleteNurbsRenderer(nurb);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
