/* glShadeModel(GL_FLAT) on all ten primitive types: each primitive takes the colour of the one
 * vertex the specification names for its type (GL 1.5 specification, 2.14.7 "Flatshading"):
 *   points: the point; lines: vertex 2i; line strip and loop: vertex i + 1 (the loop's closing
 *   segment: vertex 1); triangles: 3i; triangle strip and fan: i + 2; quads: 4i; quad strip:
 *   2i + 2; polygon: vertex 1.
 * Every vertex has its own colour, so a primitive that takes another vertex's colour shows.
 * A 5 x 2 grid of 100-pixel cells, one type per cell, in the order of the list above. */
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { CELL = 100, COLUMNS = 5, ROWS = 2 };

static const float PI = 3.14159265358979f;

/* Vertex k's colour: eight well-separated colours in turn. */
static void vertexColor(int k)
{
  static const float colors[8][3] = {{1.0f, 0.2f, 0.2f}, {0.2f, 0.9f, 0.2f}, {0.25f, 0.4f, 1.0f},
                                     {1.0f, 0.9f, 0.2f}, {0.9f, 0.3f, 0.9f}, {0.2f, 0.9f, 0.9f},
                                     {1.0f, 0.6f, 0.2f}, {0.95f, 0.95f, 0.95f}};
  glColor3fv(colors[k % 8]);
}

/* n vertices on a circle of radius 0.4 around the cell's centre, starting at `start` radians. */
static void circleVertex(int k, int n, float start)
{
  const float angle = start + 2.0f * PI * (float)k / (float)n;
  vertexColor(k);
  glVertex2f(0.5f + 0.4f * cosf(angle), 0.5f + 0.4f * sinf(angle));
}

static void primitive(GLenum mode)
{
  glBegin(mode);
  switch (mode) {
  case GL_POINTS:
  case GL_LINE_LOOP:
  case GL_POLYGON:
  case GL_TRIANGLE_FAN:
    if (mode == GL_TRIANGLE_FAN) {
      vertexColor(0);
      glVertex2f(0.5f, 0.5f);
      for (int k = 1; k <= 6; ++k) circleVertex(k, 6, 0.3f);
    } else {
      for (int k = 0; k < 6; ++k) circleVertex(k, 6, 0.3f);
    }
    break;
  case GL_LINES:
    for (int k = 0; k < 8; ++k) {
      vertexColor(k);
      glVertex2f(k % 2 ? 0.9f : 0.1f, 0.12f + 0.25f * (float)(k / 2) + (k % 2 ? 0.05f : 0.0f));
    }
    break;
  case GL_LINE_STRIP:
  case GL_TRIANGLE_STRIP:
  case GL_QUAD_STRIP:
    for (int k = 0; k < 8; ++k) {
      vertexColor(k);
      glVertex2f(0.1f + 0.8f * (float)(k / 2) / 3.0f, k % 2 ? 0.8f : 0.2f);
    }
    break;
  case GL_TRIANGLES:
    for (int k = 0; k < 6; ++k) {
      const float x = k < 3 ? 0.08f : 0.52f;
      vertexColor(k);
      glVertex2f(x + (k % 3 == 1 ? 0.4f : 0.0f), k % 3 == 2 ? 0.85f : 0.15f);
    }
    break;
  case GL_QUADS:
    for (int k = 0; k < 8; ++k) {
      const float x = k < 4 ? 0.08f : 0.52f;
      vertexColor(k);
      glVertex2f(x + (k % 4 == 1 || k % 4 == 2 ? 0.4f : 0.0f), k % 4 >= 2 ? 0.85f : 0.15f);
    }
    break;
  }
  glEnd();
}

static void draw(void)
{
  static const GLenum modes[COLUMNS * ROWS] = {
      GL_POINTS,         GL_LINES,        GL_LINE_STRIP, GL_LINE_LOOP,   GL_TRIANGLES,
      GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,      GL_QUAD_STRIP, GL_POLYGON};

  glViewport(0, 0, COLUMNS * CELL, ROWS * CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS, 0.0, ROWS, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);
  glPointSize(6.0f);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  for (int i = 0; i < COLUMNS * ROWS; ++i) {
    glPushMatrix();
    glTranslatef((float)(i % COLUMNS), (float)(ROWS - 1 - i / COLUMNS), 0.0f);
    primitive(modes[i]);
    glPopMatrix();
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
