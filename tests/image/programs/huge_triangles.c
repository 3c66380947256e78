/* Huge primitives mostly off screen, which a rasterizer must clip rather than walk: in an ortho
 * view, triangles with vertices 10^4 and 10^6 units away whose edges still cross the window at
 * known places; a "sky" quad far larger than the view; a ground plane in perspective that
 * extends 10^5 units in front and behind the eye (crossing the eye plane, w < 0 on the far side);
 * long lines from far off screen to near the centre; and a triangle with one vertex behind the
 * eye at the same depth as the near plane's other side. Smooth colours show whether the colour
 * at the visible part is interpolated from the far vertices correctly. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void draw(void)
{
  int i;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* Top half, ortho: the window is [0, 320] x [0, 240]. */
  glViewport(0, 120, WIDTH, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 320.0, 0.0, 120.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glBegin(GL_TRIANGLES);
  /* Its edge from (-10000, -9900) to (10000, 10100) passes through (0, 100) ... (20, 120). */
  glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(-10000.0f, -9900.0f);
  glColor3f(0.0f, 1.0f, 0.0f); glVertex2f(10000.0f, 10100.0f);
  glColor3f(0.0f, 0.0f, 1.0f); glVertex2f(10000.0f, -9900.0f);
  glEnd();
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 1.0f, 0.0f); glVertex2f(-1.0e6f, 120.0f);
  glColor3f(1.0f, 0.0f, 1.0f); glVertex2f(1.0e6f, 120.0f);
  glColor3f(0.0f, 1.0f, 1.0f); glVertex2f(160.0f, 90.0f);
  glEnd();
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINES);
  for (i = 0; i < 8; ++i) {
    glVertex2f(-5.0e4f, -3.0e4f + 1.0e4f * (float)i);
    glVertex2f(200.0f + 10.0f * (float)i, 60.0f);
  }
  glEnd();

  /* Bottom half, perspective. */
  glViewport(0, 0, WIDTH, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (double)WIDTH / 120.0, 0.5, 1000.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.0, 0.0, 0.0, 0.8, -1.0, 0.0, 1.0, 0.0);
  glEnable(GL_DEPTH_TEST);

  /* Sky: a quad far beyond everything, larger than the view. */
  glBegin(GL_QUADS);
  glColor3f(0.1f, 0.2f, 0.6f); glVertex3f(-1.0e4f, -10.0f, -900.0f);
  glColor3f(0.1f, 0.2f, 0.6f); glVertex3f(1.0e4f, -10.0f, -900.0f);
  glColor3f(0.6f, 0.8f, 1.0f); glVertex3f(1.0e4f, 2.0e3f, -900.0f);
  glColor3f(0.6f, 0.8f, 1.0f); glVertex3f(-1.0e4f, 2.0e3f, -900.0f);
  glEnd();

  /* Ground, from far in front to far behind the eye. */
  glBegin(GL_TRIANGLES);
  glColor3f(0.2f, 0.6f, 0.1f); glVertex3f(-1.0e5f, 0.0f, -1.0e5f);
  glColor3f(0.6f, 0.4f, 0.1f); glVertex3f(1.0e5f, 0.0f, -1.0e5f);
  glColor3f(0.9f, 0.9f, 0.3f); glVertex3f(0.0f, 0.0f, 1.0e5f);
  glEnd();

  /* A triangle with one vertex behind the eye. */
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.2f, 0.2f); glVertex3f(-1.0f, 0.6f, -4.0f);
  glColor3f(0.2f, 0.2f, 1.0f); glVertex3f(1.5f, 0.9f, -3.0f);
  glColor3f(1.0f, 1.0f, 1.0f); glVertex3f(0.5f, 0.7f, 3.0f);
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
