/* 2D drawing with glOrtho (gluOrtho2D in window units, as course homework sets it up): lines of
 * widths 1 to 6, horizontal, vertical and slanted; stippled lines with the classic patterns
 * (0x0101 dotted, 0x00FF dashed, 0x1C47 dash-dot) and repeat factors 1, 2 and 5, on single lines,
 * a strip (where the pattern continues across segments) and a loop; smooth-coloured line strips;
 * line loops forming polygons; points of sizes 1 to 8 at integer and half-integer positions;
 * and a star polygon drawn with GL_LINE_LOOP. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 400 };

static void line(float x0, float y0, float x1, float y1)
{
  glBegin(GL_LINES);
  glVertex2f(x0, y0);
  glVertex2f(x1, y1);
  glEnd();
}

static void draw(void)
{
  static const GLushort patterns[3] = {0x0101, 0x00FF, 0x1C47};
  static const GLint factors[3] = {1, 2, 5};
  int i, j;

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, (GLdouble)WIDTH, 0.0, (GLdouble)HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Wide lines: horizontal, vertical, slanted. */
  glColor3f(1.0f, 1.0f, 1.0f);
  for (i = 1; i <= 6; ++i) {
    glLineWidth((GLfloat)i);
    line(10.0f, 390.0f - 12.0f * (float)i, 120.0f, 390.0f - 12.0f * (float)i);
    line(130.0f + 12.0f * (float)i, 380.0f, 130.0f + 12.0f * (float)i, 310.0f);
    line(220.0f + 14.0f * (float)i, 310.0f, 250.0f + 14.0f * (float)i, 385.0f);
    line(320.0f, 390.0f - 12.0f * (float)i, 395.0f, 370.0f - 12.0f * (float)i);
  }
  glLineWidth(1.0f);

  /* Stipple: rows of single lines with each pattern and factor. */
  glEnable(GL_LINE_STIPPLE);
  glColor3f(0.3f, 1.0f, 0.3f);
  for (i = 0; i < 3; ++i) {
    for (j = 0; j < 3; ++j) {
      const float y = 290.0f - 10.0f * (float)(i * 3 + j);
      glLineStipple(factors[j], patterns[i]);
      line(10.0f, y, 190.0f, y + 4.0f);
    }
  }
  /* A stippled strip and loop: the pattern runs on across vertices. */
  glLineStipple(2, 0x0F0F);
  glColor3f(1.0f, 0.6f, 0.2f);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 8; ++i) glVertex2f(210.0f + 22.0f * (float)i, (i % 2) ? 290.0f : 220.0f);
  glEnd();
  glLineWidth(3.0f);
  glLineStipple(3, 0xAAAA);
  glBegin(GL_LINE_LOOP);
  glVertex2f(20.0f, 120.0f);
  glVertex2f(110.0f, 120.0f);
  glVertex2f(110.0f, 190.0f);
  glVertex2f(20.0f, 190.0f);
  glEnd();
  glLineWidth(1.0f);
  glDisable(GL_LINE_STIPPLE);

  /* Smooth-coloured strip. */
  glShadeModel(GL_SMOOTH);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i <= 20; ++i) {
    glColor3f((float)i / 20.0f, 1.0f - (float)i / 20.0f, 0.5f);
    glVertex2f(130.0f + 12.0f * (float)i, 150.0f + 40.0f * (float)sin(i * 0.6));
  }
  glEnd();

  /* A star by GL_LINE_LOOP and a hexagon outline drawn with width 2. */
  glColor3f(1.0f, 1.0f, 0.0f);
  glBegin(GL_LINE_LOOP);
  for (i = 0; i < 5; ++i) {
    const double angle = 3.14159265358979 / 2.0 + i * 4.0 * 3.14159265358979 / 5.0;
    glVertex2f(330.0f + 55.0f * (float)cos(angle), 140.0f + 55.0f * (float)sin(angle));
  }
  glEnd();
  glLineWidth(2.0f);
  glColor3f(0.4f, 0.7f, 1.0f);
  glBegin(GL_LINE_LOOP);
  for (i = 0; i < 6; ++i) {
    const double angle = i * 3.14159265358979 / 3.0;
    glVertex2f(330.0f + 30.0f * (float)cos(angle), 140.0f + 30.0f * (float)sin(angle));
  }
  glEnd();
  glLineWidth(1.0f);

  /* Points: sizes 1 to 8 on integer positions (top row) and at pixel centres (bottom row). */
  glColor3f(1.0f, 0.3f, 0.3f);
  for (i = 1; i <= 8; ++i) {
    glPointSize((GLfloat)i);
    glBegin(GL_POINTS);
    glVertex2f(20.0f + 22.0f * (float)i, 70.0f);
    glVertex2f(20.5f + 22.0f * (float)i, 40.5f);
    glVertex2f(20.25f + 22.0f * (float)i, 15.7f);
    glEnd();
  }
  glPointSize(1.0f);
  glColor3f(0.8f, 0.8f, 1.0f);
  glBegin(GL_POINTS);
  for (i = 0; i < 30; ++i) glVertex2i(220 + 6 * i, 20 + (i * 7) % 60);
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
