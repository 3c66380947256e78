/* Viewports and wide primitives at the window's edges. A viewport with a negative origin that
 * reaches past the window on every side (programs centre a square viewport this way); wide points
 * (size 9) whose centres lie just inside and just outside the view volume (a point is clipped by
 * its centre, spec 2.12, so the second row is not drawn); wide lines (width 7) whose endpoints lie
 * outside the window; and a teapot in a second viewport drawn with glFrontFace(GL_CW) and back-face
 * culling, as old GLUT programs had to draw it, next to one with the default winding. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void draw(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  int i;

  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* A 400 x 400 viewport centred on the left part of the window. */
  glViewport(-140, -80, 400, 400);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(-0.9f, -0.9f);
  glColor3f(0.0f, 1.0f, 0.0f); glVertex2f(0.9f, -0.7f);
  glColor3f(0.0f, 0.0f, 1.0f); glVertex2f(0.0f, 0.95f);
  glEnd();
  glPointSize(9.0f);
  glColor3f(1.0f, 1.0f, 0.0f);
  glBegin(GL_POINTS);
  for (i = 0; i < 5; ++i) {
    glVertex2f(-0.3f + 0.15f * (float)i, 0.99f);   /* inside: drawn, partly past the top */
    glVertex2f(-0.3f + 0.15f * (float)i, 1.01f);   /* centre outside: clipped */
    glVertex2f(0.999f, -0.5f + 0.1f * (float)i);   /* inside near the right edge */
  }
  glEnd();
  glPointSize(1.0f);
  glLineWidth(7.0f);
  glColor3f(0.0f, 1.0f, 1.0f);
  glBegin(GL_LINES);
  glVertex2f(-1.5f, 0.2f); glVertex2f(0.4f, 0.5f);
  glVertex2f(0.3f, -1.6f); glVertex2f(0.45f, 0.3f);
  glVertex2f(-0.8f, 0.6f); glVertex2f(-0.8f, 1.3f);
  glEnd();
  glLineWidth(1.0f);

  /* Teapots: CW front faces with culling (left), default winding (right). */
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_CULL_FACE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glTranslatef(0.0f, 0.0f, -3.5f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);

  glViewport(200, 120, 120, 120);
  glFrontFace(GL_CW);
  glutSolidTeapot(0.8);
  glFrontFace(GL_CCW);
  glViewport(200, 0, 120, 120);
  glutSolidTeapot(0.8);
  glDisable(GL_CULL_FACE);
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
