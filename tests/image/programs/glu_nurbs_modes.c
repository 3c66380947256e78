/* GLU NURBS properties and curves the glu_nurbs program leaves out (GLU 1.3, chapter 7), in four
 * viewports, all unlit and flat-coloured so that only where the samples fall can differ:
 *   top left: a bicubic surface with a circular hole cut by a rational quadratic trimming curve
 *     (GLU_MAP1_TRIM_3, the circle's nine homogeneous points), drawn with GLU_DISPLAY_MODE
 *     GLU_OUTLINE_PATCH: the patch boundary and the trimming curves only;
 *   top right: the same surface untrimmed, sampled by GLU_DOMAIN_DISTANCE (GLU_U_STEP 6,
 *     GLU_V_STEP 4 steps per unit of parameter) and drawn with GLU_OUTLINE_POLYGON;
 *   bottom left: NURBS curves of order 2, 3 and 4 whose interior knots repeat (a knot of
 *     multiplicity order - 1 is a corner, one of multiplicity order a break), the first sampled by
 *     GLU_DOMAIN_DISTANCE, the others by GLU_PARAMETRIC_ERROR with a tolerance of 0.5 pixel. GLU
 *     1.3 bounds that error by GLU_PARAMETRIC_TOLERANCE; SGI's GLU (Mesa's libGLU) takes
 *     GLU_SAMPLING_TOLERANCE for curves instead, so both are set to 0.5 to compare the sampling
 *     itself;
 *   bottom right: gluPartialDisk with sweeps over 360 degrees and negative, filled and in
 *     GLU_LINE, and a disk drawn GLU_POINT. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 320 };

static GLfloat surface[4][4][3];

static void makeSurface(void)
{
  for (int u = 0; u < 4; ++u)
    for (int v = 0; v < 4; ++v) {
      surface[u][v][0] = 2.0f * ((GLfloat)u - 1.5f) / 1.5f;
      surface[u][v][1] = 2.0f * ((GLfloat)v - 1.5f) / 1.5f;
      surface[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 1.5f : -0.5f;
    }
}

static void view(int column, int row)
{
  glViewport(column * WIDTH / 2, row * HEIGHT / 2, WIDTH / 2, HEIGHT / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, -6.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
}

static void ortho(int column, int row)
{
  glViewport(column * WIDTH / 2, row * HEIGHT / 2, WIDTH / 2, HEIGHT / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.5, 2.5, -2.0, 2.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void trimmedSurface(GLUnurbsObj *nurb, int trimmed)
{
  static GLfloat knots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  static GLfloat outer[5][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}};
  static GLfloat circleKnots[12] = {0.0f, 0.0f, 0.0f, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1.0f, 1.0f, 1.0f};
  /* A circle of radius 0.25 about (0.5, 0.5), clockwise (a hole), as w (s, t), w. */
  static GLfloat circle[9][3];
  const float h = (float)(sqrt(2.0) / 2.0);
  static const float corners[9][3] = {{1, 0, 1}, {1, -1, 0}, {0, -1, 1}, {-1, -1, 0}, {-1, 0, 1}, {-1, 1, 0}, {0, 1, 1}, {1, 1, 0}, {1, 0, 1}};
  for (int i = 0; i < 9; ++i) {
    const float w = corners[i][2] > 0.5f ? 1.0f : h;
    circle[i][0] = w * (0.5f + 0.25f * corners[i][0]);
    circle[i][1] = w * (0.5f + 0.25f * corners[i][1]);
    circle[i][2] = w;
  }
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &surface[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  if (trimmed) {
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluNurbsCurve(nurb, 12, circleKnots, 3, &circle[0][0], 3, GLU_MAP1_TRIM_3);
    gluEndTrim(nurb);
  }
  gluEndSurface(nurb);
}

static void curves(GLUnurbsObj *nurb)
{
  /* Order 2 (a polyline) with a doubled knot: a break, the segment from the third point to the
   * fourth is not drawn. */
  static GLfloat linearKnots[8] = {0.0f, 0.0f, 1.0f, 2.0f, 2.0f, 3.0f, 4.0f, 4.0f};
  static GLfloat linear[6][3] = {{-2.3f, 1.2f, 0}, {-1.5f, 1.9f, 0}, {-0.8f, 1.0f, 0}, {0.2f, 1.8f, 0}, {1.0f, 1.1f, 0}, {2.2f, 1.8f, 0}};
  /* Order 3 with a double interior knot: a corner at the third point. */
  static GLfloat quadraticKnots[9] = {0.0f, 0.0f, 0.0f, 1.0f, 2.0f, 2.0f, 3.0f, 3.0f, 3.0f};
  static GLfloat quadratic[6][3] = {{-2.3f, -0.2f, 0}, {-1.6f, 0.9f, 0}, {-0.5f, -0.5f, 0}, {0.4f, 0.7f, 0}, {1.3f, -0.6f, 0}, {2.3f, 0.6f, 0}};
  /* Order 4 with a triple interior knot (a corner) and a double one (a kink in curvature only). */
  static GLfloat cubicKnots[13] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 2.0f, 2.5f, 2.5f, 3.0f, 3.0f, 3.0f};
  static GLfloat cubic[10][3] = {{-2.3f, -1.9f, 0}, {-2.0f, -0.6f, 0}, {-1.4f, -0.8f, 0}, {-1.0f, -1.8f, 0},
                                 {-0.2f, -0.5f, 0}, {0.4f, -1.9f, 0}, {1.0f, -0.9f, 0}, {1.5f, -1.8f, 0},
                                 {2.0f, -0.7f, 0}, {2.3f, -1.6f, 0}};
  ortho(0, 0);
  glLineWidth(2.0f);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 3.0f);
  glColor3f(0.9f, 0.8f, 0.3f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 8, linearKnots, 3, &linear[0][0], 2, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_PARAMETRIC_ERROR);
  gluNurbsProperty(nurb, GLU_PARAMETRIC_TOLERANCE, 0.5f);
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 0.5f);
  glColor3f(0.4f, 0.9f, 0.5f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 9, quadraticKnots, 3, &quadratic[0][0], 3, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  glColor3f(0.5f, 0.7f, 1.0f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 13, cubicKnots, 3, &cubic[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  glLineWidth(1.0f);
}

static void disks(void)
{
  GLUquadricObj *quadric = gluNewQuadric();
  ortho(1, 0);
  glColor3f(0.9f, 0.4f, 0.3f);
  glPushMatrix();
  glTranslatef(-1.5f, 0.9f, 0.0f);
  gluPartialDisk(quadric, 0.3, 0.9, 20, 2, 30.0, 400.0);
  glTranslatef(1.6f, 0.0f, 0.0f);
  gluPartialDisk(quadric, 0.2, 0.9, 16, 3, 90.0, -120.0);
  glTranslatef(1.6f, 0.0f, 0.0f);
  gluPartialDisk(quadric, 0.0, 0.9, 12, 1, 45.0, -400.0);
  glPopMatrix();
  gluQuadricDrawStyle(quadric, GLU_LINE);
  glColor3f(0.4f, 0.8f, 0.9f);
  glPushMatrix();
  glTranslatef(-1.5f, -1.0f, 0.0f);
  gluPartialDisk(quadric, 0.3, 0.9, 10, 2, 0.0, -270.0);
  glTranslatef(1.6f, 0.0f, 0.0f);
  gluPartialDisk(quadric, 0.2, 0.9, 8, 2, 200.0, 370.0);
  glTranslatef(1.6f, 0.0f, 0.0f);
  gluQuadricDrawStyle(quadric, GLU_POINT);
  glPointSize(3.0f);
  gluPartialDisk(quadric, 0.2, 0.9, 10, 3, 0.0, -90.0);
  glPointSize(1.0f);
  glPopMatrix();
  gluDeleteQuadric(quadric);
}

static void draw(void)
{
  GLUnurbsObj *nurb = gluNewNurbsRenderer();
  makeSurface();
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  view(0, 1);
  glColor3f(1.0f, 0.85f, 0.4f);
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 20.0f);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);
  trimmedSurface(nurb, 1);

  view(1, 1);
  glColor3f(0.6f, 0.9f, 1.0f);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 6.0f);
  gluNurbsProperty(nurb, GLU_V_STEP, 4.0f);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
  trimmedSurface(nurb, 0);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);

  curves(nurb);
  disks();
  gluDeleteNurbsRenderer(nurb);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
