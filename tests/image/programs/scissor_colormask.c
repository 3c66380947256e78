/* glScissor and glColorMask as programs use them: a red-cyan anaglyph (the scene drawn twice
 * from two eye positions, the left eye with only the red channel writable, the right with green
 * and blue, the depth buffer cleared between); scissored clears painting a frame of coloured
 * bands; drawing clipped by a scissor box that is smaller than the viewport and partly outside
 * the window; and glColorMask on single channels over a white background. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void scene(void)
{
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
  glPushMatrix();
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glutSolidTorus(0.3, 0.9, 16, 32);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -2.0f);
  glutSolidCube(0.8);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {0.0f, 1.0f, 1.0f, 0.0f};

  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);

  /* Left half: the anaglyph. */
  glViewport(0, 0, 200, 300);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 200.0 / 300.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);

  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  gluLookAt(-0.15, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
  scene();
  glClear(GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  gluLookAt(0.15, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
  scene();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_LIGHTING);

  /* Right half: bands by scissored clears. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(200, 0, 200, 300);
  glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(210, 250, 180, 40);
  glClearColor(0.8f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(210, 200, 90, 40);
  glClearColor(0.2f, 0.7f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  /* A scissor box partly outside the window. */
  glScissor(330, 150, 200, 90);
  glClearColor(0.2f, 0.2f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* Drawing clipped by a scissor smaller than the viewport. */
  glViewport(200, 0, 200, 150);
  glScissor(230, 20, 100, 80);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -0.75, 0.75, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.5f, 0.0f); glVertex2f(-0.9f, -0.7f);
  glColor3f(0.0f, 0.5f, 1.0f); glVertex2f(0.9f, -0.7f);
  glColor3f(0.5f, 1.0f, 0.5f); glVertex2f(0.0f, 0.7f);
  glEnd();
  glDisable(GL_SCISSOR_TEST);

  /* Channel masks over the light background: white quads with one channel write each. */
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  glColor3f(0.0f, 0.0f, 0.0f);
  glRectf(0.4f, 0.1f, 0.6f, 0.3f);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
  glRectf(0.65f, 0.1f, 0.85f, 0.3f);
  glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
  glRectf(0.4f, -0.4f, 0.6f, -0.2f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
