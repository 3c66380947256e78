/* Degenerate and tiny primitives, which real meshes are full of: zero-area triangles (repeated
 * vertices, collinear vertices) between normal ones in strips (the strip-stitching trick that
 * joins strips with degenerate triangles); sub-pixel triangles that cover a pixel centre or
 * none; slivers one pixel thick at many angles; a fan of 360 thin triangles around a point;
 * quads collapsed to lines and points; a GL_POLYGON with collinear and repeated vertices; and
 * lines and points of zero length. Flat colours, so any pixel drawn differently shows. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"
#include "lcg.h"

enum { WIDTH = 320, HEIGHT = 320 };

static void draw(void)
{
  Lcg random = {2024u};
  int i;

  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);

  /* Two strips joined by degenerate triangles (repeat the last vertex of one and the first of
   * the next). */
  glColor3f(0.2f, 0.8f, 0.2f);
  glBegin(GL_TRIANGLE_STRIP);
  for (i = 0; i < 6; ++i) glVertex2f(10.0f + 20.0f * (float)(i / 2), (i % 2) ? 310.0f : 280.0f);
  glVertex2f(50.0f, 310.0f);
  glVertex2f(80.0f, 280.0f);
  for (i = 0; i < 6; ++i) glVertex2f(80.0f + 20.0f * (float)(i / 2), (i % 2) ? 310.0f : 280.0f);
  glEnd();

  /* Zero-area triangles: repeated and collinear vertices; nothing may be drawn. */
  glColor3f(1.0f, 0.0f, 0.0f);
  glBegin(GL_TRIANGLES);
  glVertex2f(170.0f, 290.0f); glVertex2f(170.0f, 290.0f); glVertex2f(200.0f, 300.0f);
  glVertex2f(170.0f, 280.0f); glVertex2f(200.0f, 290.0f); glVertex2f(230.0f, 300.0f);
  glVertex2f(240.5f, 280.5f); glVertex2f(240.5f, 310.5f); glVertex2f(240.5f, 295.5f);
  glEnd();

  /* Sub-pixel triangles scattered over a band, random sizes below 1.5 pixels. */
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_TRIANGLES);
  for (i = 0; i < 600; ++i) {
    const float x = lcg_range(&random, 10.0f, 310.0f);
    const float y = lcg_range(&random, 210.0f, 270.0f);
    const float s = lcg_range(&random, 0.1f, 1.5f);
    glVertex2f(x, y);
    glVertex2f(x + s * lcg_range(&random, 0.2f, 1.0f), y + s * lcg_range(&random, -0.3f, 0.3f));
    glVertex2f(x + s * lcg_range(&random, -0.3f, 0.3f), y + s * lcg_range(&random, 0.2f, 1.0f));
  }
  glEnd();

  /* Slivers: long triangles a fraction of a pixel to two pixels thick at many angles. */
  glColor3f(0.4f, 0.6f, 1.0f);
  glBegin(GL_TRIANGLES);
  for (i = 0; i < 24; ++i) {
    const double angle = i * 3.14159265358979 / 24.0;
    const float cx = 80.0f, cy = 130.0f;
    const float dx = 65.0f * (float)cos(angle), dy = 65.0f * (float)sin(angle);
    const float thickness = 0.25f + 0.08f * (float)i;
    const float nx = -(float)sin(angle) * thickness, ny = (float)cos(angle) * thickness;
    glVertex2f(cx + 0.2f * dx, cy + 0.2f * dy);
    glVertex2f(cx + dx, cy + dy);
    glVertex2f(cx + dx + nx, cy + dy + ny);
  }
  glEnd();

  /* A fan of 360 triangles around a point: every pixel once, no gaps. */
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 0.8f, 0.2f);
  glVertex2f(230.3f, 130.6f);
  for (i = 0; i <= 360; ++i) {
    const double angle = i * 3.14159265358979 / 180.0;
    glColor3f((i % 3) == 0 ? 1.0f : 0.3f, (i % 3) == 1 ? 1.0f : 0.3f, (i % 3) == 2 ? 1.0f : 0.3f);
    glVertex2f(230.3f + 60.0f * (float)cos(angle), 130.6f + 60.0f * (float)sin(angle));
  }
  glEnd();

  /* Collapsed quads, a polygon with collinear and repeated vertices, zero-length lines and
   * points. */
  glColor3f(1.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);
  glVertex2f(20.0f, 40.0f); glVertex2f(60.0f, 40.0f); glVertex2f(60.0f, 40.0f); glVertex2f(20.0f, 40.0f);
  glVertex2f(70.0f, 40.0f); glVertex2f(70.0f, 40.0f); glVertex2f(70.0f, 40.0f); glVertex2f(70.0f, 40.0f);
  glEnd();
  glColor3f(0.0f, 1.0f, 1.0f);
  glBegin(GL_POLYGON);
  glVertex2f(100.0f, 20.0f);
  glVertex2f(130.0f, 20.0f);
  glVertex2f(160.0f, 20.0f);
  glVertex2f(160.0f, 20.0f);
  glVertex2f(160.0f, 50.0f);
  glVertex2f(130.0f, 60.0f);
  glVertex2f(100.0f, 50.0f);
  glEnd();
  glColor3f(1.0f, 1.0f, 0.0f);
  glBegin(GL_LINES);
  glVertex2f(200.5f, 40.5f); glVertex2f(200.5f, 40.5f);
  glVertex2f(210.2f, 40.7f); glVertex2f(210.6f, 40.9f);
  glEnd();
  glPointSize(2.0f);
  glBegin(GL_POINTS);
  glVertex2f(230.0f, 40.0f);
  glVertex2f(240.5f, 40.5f);
  glEnd();
  glPointSize(1.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
