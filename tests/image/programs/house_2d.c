/* A first-homework 2D picture in window coordinates (gluOrtho2D(0, w, 0, h)): a house from
 * glRecti walls and a GL_TRIANGLES roof, windows as GL_QUADS with GL_LINE_LOOP frames, a sun as a
 * GL_TRIANGLE_FAN with smooth colours and GL_LINES rays, a tree from a GL_POLYGON crown on a
 * rectangle trunk, a pie chart of GL_TRIANGLE_FANs with flat colours, a stippled fence, a line
 * graph with a GL_LINE_STRIP and GL_POINTS markers, and glPushAttrib/glPopAttrib around the
 * state changes of each part, as course code does. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 320 };

static void circleFan(float cx, float cy, float r, int n, float a0, float a1)
{
  int i;
  glVertex2f(cx, cy);
  for (i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    glVertex2f(cx + r * (float)cos(a), cy + r * (float)sin(a));
  }
}

static void draw(void)
{
  static const float slices[5] = {0.3f, 0.15f, 0.25f, 0.1f, 0.2f};
  static const float sliceColours[5][3] = {
      {0.9f, 0.3f, 0.3f}, {0.3f, 0.8f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f}, {0.7f, 0.3f, 0.8f}};
  const double pi = 3.14159265358979;
  float start = 0.0f;
  int i;

  glClearColor(0.6f, 0.8f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, (GLdouble)WIDTH, 0.0, (GLdouble)HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Ground. */
  glColor3f(0.3f, 0.6f, 0.2f);
  glRecti(0, 0, WIDTH, 90);

  /* House. */
  glPushAttrib(GL_CURRENT_BIT | GL_LINE_BIT);
  glColor3ub(200, 160, 120);
  glRecti(60, 60, 200, 160);
  glColor3ub(150, 40, 30);
  glBegin(GL_TRIANGLES);
  glVertex2i(50, 160);
  glVertex2i(210, 160);
  glVertex2i(130, 220);
  glEnd();
  glColor3f(0.4f, 0.25f, 0.1f);
  glRecti(115, 60, 145, 115);
  glColor3f(0.8f, 0.9f, 1.0f);
  glBegin(GL_QUADS);
  glVertex2i(75, 120); glVertex2i(105, 120); glVertex2i(105, 145); glVertex2i(75, 145);
  glVertex2i(155, 120); glVertex2i(185, 120); glVertex2i(185, 145); glVertex2i(155, 145);
  glEnd();
  glLineWidth(2.0f);
  glColor3f(0.2f, 0.2f, 0.2f);
  glBegin(GL_LINE_LOOP);
  glVertex2i(75, 120); glVertex2i(105, 120); glVertex2i(105, 145); glVertex2i(75, 145);
  glEnd();
  glBegin(GL_LINE_LOOP);
  glVertex2i(155, 120); glVertex2i(185, 120); glVertex2i(185, 145); glVertex2i(155, 145);
  glEnd();
  glPopAttrib();

  /* Sun. */
  glPushAttrib(GL_CURRENT_BIT | GL_LIGHTING_BIT);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 0.6f);
  glVertex2f(410.0f, 270.0f);
  glColor3f(1.0f, 0.7f, 0.1f);
  for (i = 0; i <= 24; ++i) {
    const double a = 2.0 * pi * i / 24.0;
    glVertex2f(410.0f + 28.0f * (float)cos(a), 270.0f + 28.0f * (float)sin(a));
  }
  glEnd();
  glBegin(GL_LINES);
  for (i = 0; i < 12; ++i) {
    const double a = 2.0 * pi * i / 12.0 + 0.1;
    glVertex2f(410.0f + 34.0f * (float)cos(a), 270.0f + 34.0f * (float)sin(a));
    glVertex2f(410.0f + 46.0f * (float)cos(a), 270.0f + 46.0f * (float)sin(a));
  }
  glEnd();
  glPopAttrib();

  /* Tree. */
  glColor3f(0.45f, 0.3f, 0.15f);
  glRectf(262.0f, 60.0f, 276.0f, 120.0f);
  glColor3f(0.1f, 0.5f, 0.15f);
  glBegin(GL_POLYGON);
  for (i = 0; i < 9; ++i) {
    const double a = 2.0 * pi * i / 9.0;
    glVertex2f(269.0f + 35.0f * (float)cos(a), 150.0f + 40.0f * (float)sin(a));
  }
  glEnd();

  /* Pie chart, flat shaded. */
  glPushAttrib(GL_LIGHTING_BIT);
  glShadeModel(GL_FLAT);
  for (i = 0; i < 5; ++i) {
    const float end = start + slices[i] * 2.0f * (float)pi;
    glColor3fv(sliceColours[i]);
    glBegin(GL_TRIANGLE_FAN);
    circleFan(400.0f, 160.0f, 45.0f, 16, start, end);
    glEnd();
    start = end;
  }
  glPopAttrib();

  /* Fence. */
  glPushAttrib(GL_LINE_BIT | GL_CURRENT_BIT);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(3, 0x3F3F);
  glLineWidth(2.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINES);
  glVertex2i(0, 75); glVertex2i(WIDTH, 75);
  glVertex2i(0, 55); glVertex2i(WIDTH, 55);
  glEnd();
  glPopAttrib();

  /* Line graph with markers. */
  glColor3f(0.1f, 0.1f, 0.4f);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 12; ++i) glVertex2f(300.0f + 14.0f * (float)i, 15.0f + 20.0f * (float)fabs(sin(i * 0.7)));
  glEnd();
  glPointSize(5.0f);
  glColor3f(0.9f, 0.1f, 0.1f);
  glBegin(GL_POINTS);
  for (i = 0; i < 12; ++i) glVertex2f(300.0f + 14.0f * (float)i, 15.0f + 20.0f * (float)fabs(sin(i * 0.7)));
  glEnd();
  glPointSize(1.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
