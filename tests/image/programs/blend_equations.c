/* Blend equations and factors beyond GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA (OpenGL 1.4 section
 * 4.1.7, with the imaging subset's glBlendEquation and glBlendColor), as the Red Book's
 * blendeqn.c and course exercises on compositing use them. Every cell has the same destination,
 * a smooth-shaded quad (yellow to blue, bottom dark) whose alpha runs from 0 on the left to 1 on
 * the right, and the same source, a smooth triangle (red, green, white corners) whose alpha runs
 * from 1 at the bottom to 0.25 at the top.
 *
 *   row 4: glBlendFunc(GL_ONE, GL_ONE) with GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT
 *          (results below 0 clamp to 0, above 1 to 1), GL_MIN, GL_MAX
 *   row 3: GL_MIN and GL_MAX with glBlendFunc(GL_ZERO, GL_ZERO): the factors do not apply to
 *          them (the picture is row 4's); GL_CONSTANT_COLOR / GL_ONE_MINUS_CONSTANT_COLOR and
 *          GL_CONSTANT_ALPHA / GL_ONE_MINUS_CONSTANT_ALPHA with glBlendColor(0.2, 0.7, 1, 0.3);
 *          GL_SRC_COLOR as the source factor and GL_DST_COLOR as the destination factor (allowed
 *          since OpenGL 1.4)
 *   row 2: GL_SRC_ALPHA_SATURATE (f = min(As, 1 - Ad)) with GL_ONE, against the destination's
 *          alpha ramp; GL_DST_ALPHA / GL_ONE_MINUS_DST_ALPHA; GL_ONE_MINUS_DST_COLOR / GL_ZERO
 *          (an inverse); glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO,
 *          GL_ONE) keeping the destination's alpha, then shown by a white quad blended with
 *          GL_DST_ALPHA; glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO)
 *          writing 1 - As as alpha, shown the same way
 *   row 1: the blend colour changed between draws (three triangles, three colours);
 *          GL_FUNC_SUBTRACT with GL_SRC_ALPHA / GL_ONE (darkening by a fraction); GL_COLOR_LOGIC_OP
 *          enabled with blending (the logic op replaces blending: XOR); blending with colour writes
 *          to red and green only; a blended wide line and points with the constant alpha
 * The window is 5 x 4 cells of 96 pixels. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 96, COLUMNS = 5, ROWS = 4 };

/* The destination of every cell, drawn with blending off. Its alpha is written too, so the
 * factors that read the destination's alpha have a ramp to read. */
static void destination(float x, float y)
{
  const float s = CELL - 8.0f;
  glDisable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor4f(0.1f, 0.1f, 0.3f, 0.0f);
  glVertex2f(x, y);
  glColor4f(0.2f, 0.2f, 0.9f, 1.0f);
  glVertex2f(x + s, y);
  glColor4f(0.1f, 0.3f, 1.0f, 1.0f);
  glVertex2f(x + s, y + s);
  glColor4f(1.0f, 0.9f, 0.1f, 0.0f);
  glVertex2f(x, y + s);
  glEnd();
}

/* The source of every cell, drawn with whatever blending the cell sets up. */
static void source(float x, float y)
{
  const float s = CELL - 8.0f;
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.1f, 0.1f, 1.0f);
  glVertex2f(x - 3.0f, y + 5.0f);
  glColor4f(0.1f, 1.0f, 0.2f, 1.0f);
  glVertex2f(x + s + 3.0f, y + 11.0f);
  glColor4f(0.9f, 0.9f, 0.9f, 0.25f);
  glVertex2f(x + 0.45f * s, y + s + 2.0f);
  glEnd();
}

/* A white quad over the cell's middle blended with GL_DST_ALPHA / GL_ONE_MINUS_DST_ALPHA: it is
 * as white as the alpha the cell's blend left in the colour buffer. */
static void showDestinationAlpha(float x, float y)
{
  glBlendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glRectf(x + 24.0f, y + 4.0f, x + 64.0f, y + 84.0f);
}

static void cellOrigin(int column, int row, float *x, float *y)
{
  *x = column * CELL + 4.0f;
  *y = row * CELL + 4.0f;
}

/* One cell: the destination, then the source under the given equation and factors. */
static void blendCell(int column, int row, GLenum equation, GLenum sfactor, GLenum dfactor)
{
  float x, y;
  cellOrigin(column, row, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendEquation(equation);
  glBlendFunc(sfactor, dfactor);
  source(x, y);
  glBlendEquation(GL_FUNC_ADD);
}

static void separateCell(int column, int row, GLenum srgb, GLenum drgb, GLenum sa, GLenum da)
{
  float x, y;
  cellOrigin(column, row, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(srgb, drgb, sa, da);
  source(x, y);
  showDestinationAlpha(x, y);
}

static void draw(void)
{
  glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_SMOOTH);

  /* Row 4: the five equations with factors ONE, ONE. */
  const GLenum equations[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN,
                               GL_MAX};
  for (int i = 0; i < 5; ++i) blendCell(i, 3, equations[i], GL_ONE, GL_ONE);

  /* Row 3. */
  blendCell(0, 2, GL_MIN, GL_ZERO, GL_ZERO);
  blendCell(1, 2, GL_MAX, GL_ZERO, GL_ZERO);
  glBlendColor(0.2f, 0.7f, 1.0f, 0.3f);
  blendCell(2, 2, GL_FUNC_ADD, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
  blendCell(3, 2, GL_FUNC_ADD, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  blendCell(4, 2, GL_FUNC_ADD, GL_SRC_COLOR, GL_DST_COLOR);

  /* Row 2. */
  blendCell(0, 1, GL_FUNC_ADD, GL_SRC_ALPHA_SATURATE, GL_ONE);
  blendCell(1, 1, GL_FUNC_ADD, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
  blendCell(2, 1, GL_FUNC_ADD, GL_ONE_MINUS_DST_COLOR, GL_ZERO);
  separateCell(3, 1, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  separateCell(4, 1, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO);

  /* Row 1. */
  float x, y;
  cellOrigin(0, 0, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendFunc(GL_CONSTANT_COLOR, GL_ONE);
  const GLfloat tints[3][3] = {{0.5f, 0.0f, 0.0f}, {0.0f, 0.5f, 0.0f}, {0.0f, 0.0f, 0.5f}};
  for (int i = 0; i < 3; ++i) {
    glBlendColor(tints[i][0], tints[i][1], tints[i][2], 1.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(x + 8.0f + 26.0f * i, y + 10.0f);
    glVertex2f(x + 32.0f + 26.0f * i, y + 10.0f);
    glVertex2f(x + 20.0f + 26.0f * i, y + 78.0f);
    glEnd();
  }

  cellOrigin(1, 0, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_SUBTRACT);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  source(x, y);
  glBlendEquation(GL_FUNC_ADD);

  cellOrigin(2, 0, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  source(x, y);
  glDisable(GL_COLOR_LOGIC_OP);

  cellOrigin(3, 0, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE);
  source(x, y);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  cellOrigin(4, 0, &x, &y);
  destination(x, y);
  glEnable(GL_BLEND);
  glBlendColor(0.0f, 0.0f, 0.0f, 0.6f);
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  glColor3f(1.0f, 0.2f, 0.6f);
  glLineWidth(5.0f);
  glBegin(GL_LINES);
  glVertex2f(x + 6.0f, y + 10.0f);
  glVertex2f(x + 80.0f, y + 74.0f);
  glEnd();
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 4; ++i) {
    glColor3f(0.2f * i, 1.0f, 1.0f - 0.2f * i);
    glVertex2f(x + 20.5f + 16.0f * i, y + 60.5f - 12.0f * i);
  }
  glEnd();
  glDisable(GL_BLEND);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
