/* Polygon stipple (GL 1.5 specification, section 3.5.2) and line stipple (section 3.4.2), as the
 * Red Book's polys.c and lines.c use them:
 *   left half: a plain rectangle, and stippled polygons of two patterns (a fly and a halftone),
 *     a triangle fan and a rotated quad whose edges cut the pattern, all drawn over a smooth
 *     background; the pattern stays fixed to the window, whatever the polygon
 *   right half: lines with the stipple patterns and repeat factors of lines.c, a stippled line
 *     strip (the pattern runs on across vertices) and separate segments (it restarts), and a wide
 *     stippled line
 * The stipple patterns are built here from a rule, not copied. */
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 200 };

static GLubyte fly[128], halftone[128];

static void makePatterns(void)
{
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      /* A rounded shape with wings: a circle of radius 9 and two ellipses beside it. */
      const int dx = x - 16, dy = y - 14;
      const int body = dx * dx + dy * dy < 81;
      const int wing = (dx + 9) * (dx + 9) + 3 * (dy - 8) * (dy - 8) < 60 ||
                       (dx - 9) * (dx - 9) + 3 * (dy - 8) * (dy - 8) < 60;
      if (body || wing) fly[y * 4 + x / 8] |= (GLubyte)(0x80u >> (x % 8));
      if ((x + 2 * y) % 4 == 0 || (x % 8 == 0 && y % 2 == 0))
        halftone[y * 4 + x / 8] |= (GLubyte)(0x80u >> (x % 8));
    }
}

static void background(void)
{
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUADS);
  glColor3f(0.15f, 0.15f, 0.3f);
  glVertex2f(0.0f, 0.0f);
  glColor3f(0.3f, 0.15f, 0.15f);
  glVertex2f(200.0f, 0.0f);
  glColor3f(0.15f, 0.3f, 0.15f);
  glVertex2f(200.0f, 200.0f);
  glColor3f(0.3f, 0.3f, 0.3f);
  glVertex2f(0.0f, 200.0f);
  glEnd();
}

static void stippledPolygons(void)
{
  glColor3f(1.0f, 1.0f, 1.0f);
  glRectf(10.0f, 110.0f, 60.0f, 190.0f);
  glEnable(GL_POLYGON_STIPPLE);
  glPolygonStipple(fly);
  glColor3f(1.0f, 0.8f, 0.2f);
  glRectf(70.0f, 110.0f, 190.0f, 190.0f);
  glPolygonStipple(halftone);
  glColor3f(0.3f, 0.9f, 1.0f);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(50.0f, 55.0f);
  for (int i = 0; i <= 7; ++i) {
    const float a = 0.9f * (float)i;
    glColor3f(0.3f + 0.1f * (float)i, 0.9f, 1.0f - 0.1f * (float)i);
    glVertex2f(50.0f + 42.0f * cosf(a), 55.0f + 42.0f * sinf(a));
  }
  glEnd();
  glPolygonStipple(fly);
  glPushMatrix();
  glTranslatef(150.0f, 55.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glColor3f(1.0f, 0.4f, 0.6f);
  glRectf(-35.0f, -35.0f, 35.0f, 35.0f);
  glPopMatrix();
  glDisable(GL_POLYGON_STIPPLE);
}

static void segment(float x0, float y0, float x1, float y1)
{
  glBegin(GL_LINES);
  glVertex2f(x0, y0);
  glVertex2f(x1, y1);
  glEnd();
}

static void stippledLines(void)
{
  glEnable(GL_LINE_STIPPLE);
  glColor3f(1.0f, 1.0f, 1.0f);
  glLineStipple(1, 0x0101); /* dotted */
  segment(210.5f, 190.5f, 390.5f, 190.5f);
  glLineStipple(1, 0x00FF); /* dashed */
  segment(210.5f, 180.5f, 390.5f, 180.5f);
  glLineStipple(1, 0x1C47); /* dash, dot, dash */
  segment(210.5f, 170.5f, 390.5f, 170.5f);
  glLineStipple(5, 0x1C47); /* the same, stretched */
  segment(210.5f, 160.5f, 390.5f, 160.5f);

  /* A strip continues its pattern through its vertices; GL_LINES restart it per segment. */
  glColor3f(1.0f, 0.7f, 0.3f);
  glLineStipple(2, 0x0F0F);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 7; ++i) glVertex2f(215.0f + 28.0f * (float)i, (i % 2) ? 145.0f : 120.0f);
  glEnd();
  glColor3f(0.4f, 1.0f, 0.5f);
  glBegin(GL_LINES);
  for (int i = 0; i < 6; ++i) {
    glVertex2f(215.0f + 28.0f * (float)i, (i % 2) ? 110.0f : 85.0f);
    glVertex2f(215.0f + 28.0f * (float)(i + 1), (i % 2) ? 85.0f : 110.0f);
  }
  glEnd();

  /* Wide and diagonal stippled lines. */
  glColor3f(0.7f, 0.6f, 1.0f);
  glLineWidth(3.0f);
  glLineStipple(1, 0x3F07);
  segment(215.0f, 20.0f, 390.0f, 70.0f);
  glLineWidth(1.0f);
  glLineStipple(3, 0xAAAA);
  segment(215.0f, 70.0f, 300.0f, 10.0f);
  glDisable(GL_LINE_STIPPLE);
}

static void draw(void)
{
  makePatterns();
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  background();
  stippledPolygons();
  stippledLines();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
