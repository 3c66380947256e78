/* GL_COMBINE (OpenGL 1.3 section 3.8.13, tables 3.24 and 3.25, with the 1.4 crossbar): every
 * combiner function on RGB and alpha, every source and every operand, and the scales. Each cell
 * is blended (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) onto a grey checkerboard, so the alpha
 * result shows as well.
 *
 *   rows (top to bottom), the RGB function: REPLACE, MODULATE, ADD, ADD_SIGNED, INTERPOLATE,
 *     SUBTRACT, DOT3_RGB, DOT3_RGBA; the alpha function is the same for the first six, and
 *     INTERPOLATE with DOT3_RGB (DOT3_RGBA writes alpha itself)
 *   columns:
 *     0. sources TEXTURE, PRIMARY_COLOR, CONSTANT; operands SRC_COLOR, SRC_COLOR, SRC_ALPHA
 *     1. the same sources; operands ONE_MINUS_SRC_COLOR, SRC_ALPHA, ONE_MINUS_SRC_ALPHA (alpha:
 *        ONE_MINUS_SRC_ALPHA, SRC_ALPHA, ONE_MINUS_SRC_ALPHA)
 *     2. sources CONSTANT, TEXTURE, PRIMARY_COLOR, GL_RGB_SCALE 2 and GL_ALPHA_SCALE 2
 *     3. unit 0 MODULATE; unit 1 combines PREVIOUS, TEXTURE (its own) and TEXTURE0 (the
 *        crossbar), GL_ALPHA_SCALE 4
 *     4. unit 0 combines TEXTURE1 (a later unit's texel), PRIMARY_COLOR and TEXTURE; unit 1
 *        combines REPLACE of PREVIOUS (it passes unit 0's result on); GL_RGB_SCALE 4
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "checkerboard.h"
#include "gl_program.h"

enum { CELL = 64, COLUMNS = 5, ROWS = 8, TEX = 16 };

static const GLenum functions[ROWS] = {GL_REPLACE,     GL_MODULATE, GL_ADD,      GL_ADD_SIGNED,
                                       GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
static GLuint textures[2];

static void makeTextures(void)
{
  static GLubyte a[TEX][TEX][4], b[TEX][TEX][4];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      const int dx = 2 * i - (TEX - 1), dy = 2 * j - (TEX - 1);
      a[j][i][0] = (GLubyte)(16 * i);
      a[j][i][1] = (GLubyte)(16 * j);
      a[j][i][2] = (GLubyte)(255 - 8 * (i + j));
      a[j][i][3] = (GLubyte)(dx * dx + dy * dy < TEX * TEX / 2 ? 230 : 90);
      b[j][i][0] = (GLubyte)(((i / 4 + j / 4) % 2) ? 220 : 60);
      b[j][i][1] = (GLubyte)(128 + 7 * (i - j));
      b[j][i][2] = (GLubyte)(40 + 12 * j);
      b[j][i][3] = (GLubyte)(255 - 12 * i);
    }
  }
  glGenTextures(2, textures);
  for (int k = 0; k < 2; ++k) {
    glBindTexture(GL_TEXTURE_2D, textures[k]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE, k ? b : a);
  }
}

static void checkerboard(float x0, float y0)
{
  draw_checkerboard(x0, y0, (float)CELL, 4, 0.3f, 0.8f);
}

/* A quad with a different primary colour (and alpha) at each corner. */
static void square(float x0, float y0)
{
  static const float colors[4][4] = {
      {0.9f, 0.2f, 0.1f, 1.0f}, {0.2f, 0.9f, 0.3f, 0.7f}, {0.3f, 0.4f, 1.0f, 0.4f}, {1.0f, 1.0f, 0.6f, 0.9f}};
  static const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const float size = CELL - 8;
  glBegin(GL_QUADS);
  for (int k = 0; k < 4; ++k) {
    glColor4fv(colors[k]);
    glMultiTexCoord2f(GL_TEXTURE0, corners[k][0], corners[k][1]);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f - corners[k][1], corners[k][0]);
    glVertex2f(x0 + 4 + size * corners[k][0], y0 + 4 + size * corners[k][1]);
  }
  glEnd();
}

static void combine(GLenum rgbFunction, const GLenum sources[3], const GLenum rgbOperands[3],
                    const GLenum alphaOperands[3], float rgbScale, float alphaScale)
{
  const GLenum alphaFunction = rgbFunction == GL_DOT3_RGB    ? GL_INTERPOLATE
                               : rgbFunction == GL_DOT3_RGBA ? GL_REPLACE
                                                             : rgbFunction;
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)rgbFunction);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)alphaFunction);
  for (int n = 0; n < 3; ++n) {
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + n, (GLint)sources[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + n, (GLint)sources[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + n, (GLint)rgbOperands[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + n, (GLint)alphaOperands[n]);
  }
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, rgbScale);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, alphaScale);
}

static void useUnit(GLenum unit, GLuint texture)
{
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glEnable(GL_TEXTURE_2D);
}

static void cell(int row, int column)
{
  static const GLenum plain[3] = {GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT};
  static const GLenum rotated[3] = {GL_CONSTANT, GL_TEXTURE, GL_PRIMARY_COLOR};
  static const GLenum chained[3] = {GL_PREVIOUS, GL_TEXTURE, GL_TEXTURE0};
  static const GLenum crossbar[3] = {GL_TEXTURE1, GL_PRIMARY_COLOR, GL_TEXTURE};
  static const GLenum passOn[3] = {GL_PREVIOUS, GL_PREVIOUS, GL_PREVIOUS};
  static const GLenum colorOps[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  static const GLenum inverseOps[3] = {GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
  static const GLenum alphaOps[3] = {GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  static const GLenum inverseAlphaOps[3] = {GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
  const GLenum f = functions[row];
  switch (column) {
    case 0:
      useUnit(GL_TEXTURE0, textures[0]);
      combine(f, plain, colorOps, alphaOps, 1.0f, 1.0f);
      break;
    case 1:
      useUnit(GL_TEXTURE0, textures[0]);
      combine(f, plain, inverseOps, inverseAlphaOps, 1.0f, 1.0f);
      break;
    case 2:
      useUnit(GL_TEXTURE0, textures[0]);
      combine(f, rotated, colorOps, alphaOps, 2.0f, 2.0f);
      break;
    case 3:
      useUnit(GL_TEXTURE0, textures[0]);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      useUnit(GL_TEXTURE1, textures[1]);
      combine(f, chained, colorOps, alphaOps, 1.0f, 4.0f);
      break;
    default:
      useUnit(GL_TEXTURE0, textures[0]);
      combine(f, crossbar, colorOps, alphaOps, 4.0f, 1.0f);
      useUnit(GL_TEXTURE1, textures[1]);
      combine(GL_REPLACE, passOn, colorOps, alphaOps, 1.0f, 1.0f);
      break;
  }
}

static void draw(void)
{
  const GLfloat constant[4] = {0.3f, 0.6f, 0.9f, 0.5f};
  const GLfloat constant1[4] = {0.8f, 0.5f, 0.2f, 0.75f};
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  makeTextures();
  glActiveTexture(GL_TEXTURE1);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant1);
  glActiveTexture(GL_TEXTURE0);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  for (int row = 0; row < ROWS; ++row) {
    for (int column = 0; column < COLUMNS; ++column) {
      const float x0 = (float)(column * CELL), y0 = (float)((ROWS - 1 - row) * CELL);
      glDisable(GL_BLEND);
      checkerboard(x0, y0);
      cell(row, column);
      glEnable(GL_BLEND);
      square(x0, y0);
      glActiveTexture(GL_TEXTURE1);
      glDisable(GL_TEXTURE_2D);
      glActiveTexture(GL_TEXTURE0);
      glDisable(GL_TEXTURE_2D);
    }
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
