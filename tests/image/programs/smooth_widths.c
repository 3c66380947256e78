/* Antialiased points and lines (GL_POINT_SMOOTH, GL_LINE_SMOOTH with glHint(GL_NICEST)) blended
 * over a striped background with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: smooth points of sizes 1
 * to 10 at whole, half and arbitrary sub-pixel positions; fans of smooth lines of widths 1 to 5,
 * fractional widths among them, at 24 angles each; short segments (under a pixel to a few
 * pixels); smooth-shaded smooth lines; and stippled smooth lines, whose dashes are drawn as
 * smooth segments of their own. The coverage is the implementation's choice (spec
 * 3.3.2, 3.4.3); this measures how far glass's is from Mesa's. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void background(void)
{
  int i;
  glBegin(GL_QUADS);
  for (i = 0; i < WIDTH / 20; ++i) {
    const float x = 20.0f * (float)i;
    if (i % 2) glColor3f(0.15f, 0.2f, 0.35f);
    else glColor3f(0.3f, 0.25f, 0.2f);
    glVertex2f(x, 0.0f);
    glVertex2f(x + 20.0f, 0.0f);
    glVertex2f(x + 20.0f, (float)HEIGHT);
    glVertex2f(x, (float)HEIGHT);
  }
  glEnd();
}

static void points(void)
{
  static const float offsets[3][2] = {{0.0f, 0.0f}, {0.5f, 0.5f}, {0.3f, 0.7f}};
  int size, row;
  for (row = 0; row < 3; ++row) {
    for (size = 1; size <= 10; ++size) {
      glPointSize((float)size);
      glBegin(GL_POINTS);
      glColor4f(1.0f, 0.95f - 0.05f * (float)size, 0.4f, 1.0f);
      glVertex2f(12.0f + 18.0f * (float)(size - 1) + offsets[row][0],
                 280.0f - 18.0f * (float)row + offsets[row][1]);
      glEnd();
    }
  }
  /* Half sizes and a translucent colour. */
  for (size = 1; size <= 8; ++size) {
    glPointSize(0.5f + (float)size);
    glBegin(GL_POINTS);
    glColor4f(0.4f, 1.0f, 0.6f, 0.7f);
    glVertex2f(200.0f + 22.0f * (float)(size - 1) + 0.25f, 280.3f);
    glEnd();
  }
}

static void fan(float cx, float cy, float width)
{
  int i;
  glLineWidth(width);
  glBegin(GL_LINES);
  for (i = 0; i < 24; ++i) {
    const double angle = i * 2.0 * 3.14159265358979 / 24.0 + 0.03;
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(cx + 6.0f * (float)cos(angle), cy + 6.0f * (float)sin(angle));
    glColor3f(0.3f + 0.7f * (float)(i % 2), 0.9f, 0.2f);
    glVertex2f(cx + 36.0f * (float)cos(angle), cy + 36.0f * (float)sin(angle));
  }
  glEnd();
}

static void draw(void)
{
  static const float widths[6] = {1.0f, 1.5f, 2.0f, 3.0f, 4.0f, 5.0f};
  int i;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  background();

  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  points();
  for (i = 0; i < 6; ++i)
    fan(45.0f + 78.0f * (float)(i % 5), 180.0f - 80.0f * (float)(i / 5), widths[i]);

  /* Short segments: lengths 0.3 to 4 pixels, widths 1 and 3. */
  for (i = 0; i < 12; ++i) {
    const float length = 0.3f + 0.35f * (float)i;
    glLineWidth(i % 2 ? 3.0f : 1.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.6f, 0.9f);
    glVertex2f(120.0f + 14.0f * (float)i, 60.3f);
    glVertex2f(120.0f + 14.0f * (float)i + length * 0.8f, 60.3f + length * 0.6f);
    glEnd();
  }
  /* A smooth-shaded strip at width 2.5. */
  glLineWidth(2.5f);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i <= 10; ++i) {
    glColor3f(0.1f * (float)i, 0.4f, 1.0f - 0.1f * (float)i);
    glVertex2f(130.0f + 24.0f * (float)i, 30.0f + 12.0f * (float)(i % 2) + 0.2f * (float)i);
  }
  glEnd();

  /* Stippled: a strip (the pattern carries on across its segments) and separate lines. */
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0F0F);
  glLineWidth(2.0f);
  glColor3f(0.9f, 0.9f, 1.0f);
  glBegin(GL_LINE_STRIP);
  glVertex2f(100.0f, 130.0f);
  glVertex2f(180.0f, 135.5f);
  glVertex2f(250.0f, 105.0f);
  glVertex2f(390.0f, 128.0f);
  glEnd();
  glLineStipple(1, 0x33FF);
  glLineWidth(1.0f);
  glBegin(GL_LINES);
  for (i = 0; i < 6; ++i) {
    glColor3f(1.0f, 0.5f + 0.1f * (float)i, 0.3f);
    glVertex2f(110.0f + 45.0f * (float)i, 75.0f);
    glVertex2f(140.0f + 45.0f * (float)i + 3.0f * (float)i, 98.0f - 4.0f * (float)i);
  }
  glEnd();
  glDisable(GL_LINE_STIPPLE);

  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_POINT_SMOOTH);
  glLineWidth(1.0f);
  glPointSize(1.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
