/* The Sierpinski gasket by the chaos game, as in the first homework of every graphics course:
 * start inside a triangle, and 60,000 times move halfway towards a randomly chosen corner and
 * draw a GL_POINT there. The window is set up with gluOrtho2D(0, 500, 0, 500) and the points
 * are floats, so they fall anywhere in a pixel. The random corners come from the shared linear
 * congruential generator (lcg.h) so that glass and Mesa draw the same points. A second gasket in
 * 3D (a tetrahedron, points coloured by position) is drawn in perspective in the upper right. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"
#include "lcg.h"

enum { WIDTH = 500, HEIGHT = 500 };

static void draw(void)
{
  static const GLfloat corners[3][2] = {{0.0f, 0.0f}, {250.0f, 433.0f}, {500.0f, 0.0f}};
  static const GLfloat tetra[4][3] = {
      {0.0f, 0.0f, 1.0f}, {0.0f, 0.94f, -0.33f}, {-0.82f, -0.47f, -0.33f}, {0.82f, -0.47f, -0.33f}};
  GLfloat p[2] = {75.0f, 50.0f};
  GLfloat q[3] = {0.0f, 0.0f, 0.0f};
  Lcg random = {12345u};
  int i;

  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, 500.0, 0.0, 500.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glColor3f(1.0f, 0.0f, 0.0f);
  glBegin(GL_POINTS);
  for (i = 0; i < 60000; ++i) {
    const int k = lcg_below(&random, 3);
    p[0] = (p[0] + corners[k][0]) / 2.0f;
    p[1] = (p[1] + corners[k][1]) / 2.0f;
    glVertex2fv(p);
  }
  glEnd();

  glViewport(300, 260, 200, 200);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(1.5, 1.2, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_POINTS);
  for (i = 0; i < 40000; ++i) {
    const int k = lcg_below(&random, 4);
    q[0] = (q[0] + tetra[k][0]) * 0.5f;
    q[1] = (q[1] + tetra[k][1]) * 0.5f;
    q[2] = (q[2] + tetra[k][2]) * 0.5f;
    glColor3f(0.5f + q[0] * 0.6f, 0.5f + q[1] * 0.6f, 0.5f + q[2] * 0.6f);
    glVertex3fv(q);
  }
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
