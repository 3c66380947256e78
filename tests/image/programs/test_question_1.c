/* The study guide's test question 1 (section 3.1, Listing 6): sketch what this code draws when
 * drawTriangle() draws the triangle (0,0,0), (1,0,0), (0,2,0).
 *
 * Listing 6 runs as printed. Around it, for reading the picture: a grid of unit squares, the x
 * and y axes, and the untransformed triangle as an outline. The first triangle Listing 6 draws
 * is red, the second blue. The answer (Fig. 3.2): the red triangle has corners
 * (2.83, 0), (3.54, 0.71), (1.41, 1.41); the blue one (0, 2.83), (-0.71, 2.12), (1.41, 1.41). */
#include <GL/gl.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 480 };

static void drawTriangle(void)
{
  glBegin(GL_TRIANGLES);
  glVertex3f(0.0f, 0.0f, 0.0f);
  glVertex3f(1.0f, 0.0f, 0.0f);
  glVertex3f(0.0f, 2.0f, 0.0f);
  glEnd();
}

/* Unit grid over the visible square, and the axes over it. */
static void drawGridAndAxes(void)
{
  glColor3f(0.22f, 0.22f, 0.26f);
  glBegin(GL_LINES);
  for (int i = -1; i <= 4; ++i) {
    glVertex2f((float)i, -2.0f);
    glVertex2f((float)i, 4.0f);
  }
  for (int i = -2; i <= 4; ++i) {
    glVertex2f(-1.5f, (float)i);
    glVertex2f(4.5f, (float)i);
  }
  glEnd();
  glColor3f(0.85f, 0.85f, 0.85f);
  glBegin(GL_LINES);
  glVertex2f(-1.5f, 0.0f);
  glVertex2f(4.5f, 0.0f);
  glVertex2f(0.0f, -2.0f);
  glVertex2f(0.0f, 4.0f);
  glEnd();
}

static void draw(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  /* 80 pixels a unit over [-1.5, 4.5] x [-2, 4], shifted by half a pixel so that the grid lines
   * at whole coordinates run through pixel centres rather than along pixel edges. */
  glOrtho(-1.5 - 0.5 / 80, 4.5 - 0.5 / 80, -2.0 - 0.5 / 80, 4.0 - 0.5 / 80, -1.0, 1.0);
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  drawGridAndAxes();

  /* Listing 6, with a colour before each drawTriangle(). */
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(45.0, 0.0, 0.0, 1.0);
  glTranslatef(2.0, 0.0, 0.0);
  glPushMatrix();
  glTranslatef(0.0, -2.0, 0.0);
  glColor3f(0.9f, 0.2f, 0.2f);
  drawTriangle();
  glPopMatrix();
  glRotatef(180.0, 0.0, 0.0, 1.0);
  glTranslatef(0.0, -2.0, 0.0);
  glColor3f(0.25f, 0.45f, 0.95f);
  drawTriangle();

  /* drawTriangle()'s triangle with no transformation, as an outline on top. */
  glLoadIdentity();
  glColor3f(0.95f, 0.8f, 0.2f);
  glBegin(GL_LINE_LOOP);
  glVertex3f(0.0f, 0.0f, 0.0f);
  glVertex3f(1.0f, 0.0f, 0.0f);
  glVertex3f(0.0f, 2.0f, 0.0f);
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
