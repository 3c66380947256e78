/* Point sizes and line widths that are not whole numbers, as programs set them
 * (glPointSize(2.5f), glLineWidth(1.5f)): non-antialiased points and lines round them to an
 * integer (spec 3.3, 3.4.2), and the specification leaves the halves open. A row of points for
 * sizes 0.5 to 6.5 in steps of 0.5 at three subpixel positions, and lines of the same widths,
 * x-major and y-major, some stippled. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void draw(void)
{
  int i;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  for (i = 1; i <= 13; ++i) {
    const float size = 0.5f * (float)i;
    const float x = 10.0f + 23.0f * (float)(i - 1);
    glPointSize(size);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 0.8f, 0.2f);
    glVertex2f(x + 0.3f, 225.6f);
    glColor3f(0.4f, 1.0f, 0.4f);
    glVertex2f(x + 0.5f, 205.5f);
    glColor3f(0.4f, 0.7f, 1.0f);
    glVertex2f(x + 0.9f, 185.1f);
    glEnd();

    glLineWidth(size);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINES);
    glVertex2f(x, 170.3f);
    glVertex2f(x + 18.7f, 120.6f);
    glVertex2f(x + 0.2f, 105.5f);
    glVertex2f(x + 20.1f, 98.2f);
    glEnd();
    if (i % 2 == 1) {
      glEnable(GL_LINE_STIPPLE);
      glLineStipple(1 + i % 3, 0x33FF);
    }
    glColor3f(1.0f, 0.4f, 0.4f);
    glBegin(GL_LINE_STRIP);
    glVertex2f(x + 2.0f, 85.0f);
    glVertex2f(x + 15.0f, 60.0f);
    glVertex2f(x + 4.0f, 20.0f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
  }
  glPointSize(1.0f);
  glLineWidth(1.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
