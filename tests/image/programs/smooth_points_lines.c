/* Antialiased points and lines, as programs turn them on: glEnable(GL_POINT_SMOOTH) and
 * GL_LINE_SMOOTH with blending (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) and glHint(GL_NICEST): round
 * points of sizes 1 to 10, smooth lines of widths 1 to 4 at several angles, a smooth wire
 * icosahedron-like star, and the same without smoothing for comparison. Coverage is
 * implementation-defined in detail; this measures how far glass's is from Mesa's. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void figure(float x0)
{
  int i;
  for (i = 1; i <= 10; i += 1) {
    glPointSize((GLfloat)i);
    glBegin(GL_POINTS);
    glVertex2f(x0 + 10.0f + 14.0f * (float)((i - 1) % 5), 220.0f - 20.0f * (float)((i - 1) / 5));
    glEnd();
  }
  glPointSize(1.0f);
  for (i = 0; i < 12; ++i) {
    const double angle = i * 3.14159265358979 / 12.0 + 0.05;
    glLineWidth(1.0f + (float)(i % 4));
    glBegin(GL_LINES);
    glVertex2f(x0 + 80.0f, 90.0f);
    glVertex2f(x0 + 80.0f + 70.0f * (float)cos(angle), 90.0f + 70.0f * (float)sin(angle));
    glEnd();
  }
  glLineWidth(1.0f);
  glBegin(GL_LINE_LOOP);
  for (i = 0; i < 7; ++i) {
    const double angle = i * 3.0 * 2.0 * 3.14159265358979 / 7.0;
    glVertex2f(x0 + 80.0f + 30.0f * (float)cos(angle), 40.0f + 30.0f * (float)sin(angle));
  }
  glEnd();
}

static void draw(void)
{
  glClearColor(0.05f, 0.05f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glColor3f(1.0f, 0.9f, 0.5f);
  figure(0.0f);

  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  figure(160.0f);
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_POINT_SMOOTH);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
