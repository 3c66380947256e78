/* glPolygonMode and culling together: a ring of polygons, half of them facing away, with front
 * faces GL_FILL and back faces GL_LINE; then front GL_LINE and back GL_POINT; glFrontFace(GL_CW)
 * flipping which faces are front; glCullFace(GL_FRONT) and GL_FRONT_AND_BACK; and glEdgeFlag
 * hiding the inner edges of a concave-looking outline drawn as one GL_POLYGON in GL_LINE mode,
 * smooth-shaded outlines (line colours interpolated along polygon edges) and a flat-shaded
 * outlined quad strip. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void ring(float cx, float cy)
{
  int i;
  for (i = 0; i < 8; ++i) {
    const double a0 = i * 3.14159265358979 / 4.0, a1 = a0 + 0.6;
    const int flipped = i % 2;
    glColor3f(0.2f + 0.1f * (float)i, 0.9f - 0.1f * (float)i, 0.6f);
    glBegin(GL_TRIANGLES);
    glVertex2f(cx, cy);
    if (flipped) {
      glVertex2f(cx + 45.0f * (float)cos(a1), cy + 45.0f * (float)sin(a1));
      glVertex2f(cx + 45.0f * (float)cos(a0), cy + 45.0f * (float)sin(a0));
    } else {
      glVertex2f(cx + 45.0f * (float)cos(a0), cy + 45.0f * (float)sin(a0));
      glVertex2f(cx + 45.0f * (float)cos(a1), cy + 45.0f * (float)sin(a1));
    }
    glEnd();
  }
}

static void draw(void)
{
  int i;
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  ring(60.0f, 240.0f);

  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glPointSize(3.0f);
  ring(160.0f, 240.0f);
  glPointSize(1.0f);

  glFrontFace(GL_CW);
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  ring(260.0f, 240.0f);
  glFrontFace(GL_CCW);

  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  ring(350.0f, 240.0f);
  glCullFace(GL_FRONT_AND_BACK);
  ring(350.0f, 140.0f);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);

  /* One polygon, edge flags off on the edges that should not show. */
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_POLYGON);
  glEdgeFlag(GL_TRUE);
  glVertex2f(20.0f, 120.0f);
  glVertex2f(100.0f, 120.0f);
  glEdgeFlag(GL_FALSE);
  glVertex2f(110.0f, 170.0f);
  glEdgeFlag(GL_TRUE);
  glVertex2f(60.0f, 190.0f);
  glVertex2f(15.0f, 165.0f);
  glEnd();

  /* Smooth-shaded outline: colours interpolate along each edge. */
  glLineWidth(2.0f);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(140.0f, 110.0f);
  glColor3f(0.0f, 1.0f, 0.0f); glVertex2f(250.0f, 120.0f);
  glColor3f(0.0f, 0.0f, 1.0f); glVertex2f(190.0f, 190.0f);
  glEnd();
  glLineWidth(1.0f);

  /* Flat-shaded quad strip outlined, then a filled copy below. */
  glShadeModel(GL_FLAT);
  for (i = 0; i < 2; ++i) {
    int k;
    glPolygonMode(GL_FRONT_AND_BACK, i == 0 ? GL_LINE : GL_FILL);
    glBegin(GL_QUAD_STRIP);
    for (k = 0; k <= 6; ++k) {
      glColor3f((float)(k % 3) * 0.5f, (float)((k + 1) % 3) * 0.5f, (float)((k + 2) % 3) * 0.5f);
      glVertex2f(20.0f + 50.0f * (float)k, 80.0f - 40.0f * (float)i);
      glVertex2f(20.0f + 50.0f * (float)k, 100.0f - 40.0f * (float)i + (float)(k % 2) * 8.0f);
    }
    glEnd();
  }
  glShadeModel(GL_SMOOTH);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
