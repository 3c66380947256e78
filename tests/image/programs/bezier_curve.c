/* One-dimensional evaluators (glMap1, section 5.1 of the GL 1.5 specification) drawing curves
 * with their control polygons:
 *   - a cubic Bezier curve, GL_MAP1_VERTEX_3, by glEvalMesh1(GL_LINE) over a 40-step grid, its
 *     control points as points and its control polygon as a line strip;
 *   - the exam's arc of the unit circle from 0 to 2 pi / 3 as a rational quadratic,
 *     GL_MAP1_VERTEX_4 (control points (1, 0), (1, sqrt 3), (-1/2, sqrt 3 / 2), weights 1, 1/2,
 *     1, given as w (x, y), w), by glEvalCoord1f in a line strip, coloured along its length by a
 *     GL_MAP1_COLOR_4 map with a domain of its own;
 *   - a quartic by glEvalMesh1(GL_POINT) on a grid whose domain runs backwards (u from 1 to 0),
 *     and by glEvalPoint1 for every fourth grid point, drawn larger. */
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 360, HEIGHT = 240 };

static void controlPolygon(const GLfloat *points, int count, int stride)
{
  glColor3f(0.45f, 0.45f, 0.5f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < count; ++i) glVertex3fv(points + i * stride);
  glEnd();
  glColor3f(1.0f, 0.9f, 0.3f);
  glBegin(GL_POINTS);
  for (int i = 0; i < count; ++i) glVertex3fv(points + i * stride);
  glEnd();
}

static void cubic(void)
{
  static const GLfloat points[4][3] = {{0.3f, 0.3f, 0.0f}, {0.9f, 2.3f, 0.0f}, {2.6f, -0.1f, 0.0f}, {3.3f, 2.1f, 0.0f}};
  controlPolygon(&points[0][0], 4, 3);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &points[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glColor3f(0.3f, 0.9f, 0.5f);
  glMapGrid1f(40, 0.0f, 1.0f);
  glEvalMesh1(GL_LINE, 0, 40);
  glDisable(GL_MAP1_VERTEX_3);
}

static void examArc(void)
{
  const float s3 = (float)sqrt(3.0);
  /* Homogeneous: the middle point (1, sqrt 3) with weight 1/2. */
  const GLfloat points[3][4] = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.5f, 0.5f * s3, 0.0f, 0.5f}, {-0.5f, 0.5f * s3, 0.0f, 1.0f}};
  const GLfloat colors[2][4] = {{1.0f, 0.3f, 0.2f, 1.0f}, {0.3f, 0.5f, 1.0f, 1.0f}};
  const GLfloat polygon[3][3] = {{1.0f, 0.0f, 0.0f}, {1.0f, s3, 0.0f}, {-0.5f, 0.5f * s3, 0.0f}};
  glPushMatrix();
  glTranslatef(5.3f, 0.2f, 0.0f);
  glScalef(1.15f, 1.15f, 1.0f);
  controlPolygon(&polygon[0][0], 3, 3);
  glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 4, 3, &points[0][0]);
  /* The colour map's domain is [0, 2]: halfway along the arc it is a quarter of the way. */
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 2.0f, 4, 2, &colors[0][0]);
  glEnable(GL_MAP1_VERTEX_4);
  glEnable(GL_MAP1_COLOR_4);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 30; ++i) glEvalCoord1f((float)i / 30.0f);
  glEnd();
  glDisable(GL_MAP1_COLOR_4);
  glDisable(GL_MAP1_VERTEX_4);
  glPopMatrix();
}

static void quartic(void)
{
  static const GLfloat points[5][3] = {{0.4f, -1.9f, 0.0f}, {1.6f, -0.3f, 0.0f}, {3.2f, -2.3f, 0.0f}, {5.0f, -0.4f, 0.0f}, {6.7f, -1.7f, 0.0f}};
  controlPolygon(&points[0][0], 5, 3);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 5, &points[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glColor3f(0.95f, 0.55f, 0.9f);
  glMapGrid1f(48, 1.0f, 0.0f);
  glEvalMesh1(GL_POINT, 0, 48);
  glPointSize(5.0f);
  glColor3f(0.4f, 0.9f, 0.95f);
  glBegin(GL_POINTS);
  for (int i = 0; i <= 48; i += 4) glEvalPoint1(i);
  glEnd();
  glDisable(GL_MAP1_VERTEX_3);
}

static void draw(void)
{
  glClearColor(0.06f, 0.07f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 7.2, -2.4, 2.4, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPointSize(4.0f);
  cubic();
  examArc();
  glPointSize(2.0f);
  quartic();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
