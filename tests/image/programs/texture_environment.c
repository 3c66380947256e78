/* Every texture environment mode (spec 3.8.13, tables 3.22 and 3.23) on every base format, over
 * a lit surface, blended onto a checkerboard so that the resulting alpha shows:
 *
 *   columns: MODULATE  DECAL  REPLACE  BLEND  ADD
 *   rows (top to bottom): RGB, RGBA, LUMINANCE, LUMINANCE_ALPHA, ALPHA, INTENSITY
 *
 * The surface is lit per vertex (a positional light, material alpha 0.8), so the fragment colour
 * Cf varies across each square. DECAL is undefined for the last four formats; those squares show
 * the checkerboard alone. BLEND uses the environment colour (0.2, 0.9, 0.3, 0.6). */
#include <GL/gl.h>

#include "checkerboard.h"
#include "gl_program.h"

enum { CELL = 96, COLUMNS = 5, ROWS = 6, TEX = 16, GRID = 8 };

static const GLenum modes[COLUMNS] = {GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND, GL_ADD};
static const GLenum formats[ROWS] = {GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA,
                                     GL_INTENSITY};
static GLuint textures[ROWS];

/* A texture with colour gradients and a disc of high alpha; each format keeps what it has. */
static void makeTexture(int row)
{
  static GLubyte rgba[TEX][TEX][4];
  static GLubyte la[TEX][TEX][2];
  static GLubyte single[TEX][TEX];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      const int dx = 2 * i - (TEX - 1), dy = 2 * j - (TEX - 1);
      const GLubyte alpha = (GLubyte)(dx * dx + dy * dy < TEX * TEX / 2 ? 230 : 60);
      const GLubyte luminance = (GLubyte)(255 - 14 * i);
      rgba[j][i][0] = (GLubyte)(16 * i);
      rgba[j][i][1] = (GLubyte)(16 * j);
      rgba[j][i][2] = (GLubyte)(255 - 8 * (i + j));
      rgba[j][i][3] = alpha;
      la[j][i][0] = luminance;
      la[j][i][1] = alpha;
      single[j][i] = formats[row] == GL_ALPHA ? alpha : luminance;
    }
  }
  glBindTexture(GL_TEXTURE_2D, textures[row]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  switch (formats[row]) {
    case GL_RGB:
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
      break;
    case GL_RGBA:
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
      break;
    case GL_LUMINANCE_ALPHA:
      glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, TEX, TEX, 0, GL_LUMINANCE_ALPHA,
                   GL_UNSIGNED_BYTE, la);
      break;
    case GL_ALPHA:
      glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, TEX, TEX, 0, GL_ALPHA, GL_UNSIGNED_BYTE, single);
      break;
    default: /* LUMINANCE and INTENSITY take the single value as L or I */
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[row], TEX, TEX, 0, GL_LUMINANCE,
                   GL_UNSIGNED_BYTE, single);
      break;
  }
}

static void checkerboard(float x0, float y0)
{
  draw_checkerboard(x0, y0, (float)CELL, 6, 0.35f, 0.85f);
}

/* A lit square, GRID x GRID quads, texture coordinates 0..1. */
static void litSquare(float x0, float y0, float size)
{
  const float step = size / GRID;
  glNormal3f(0.0f, 0.0f, 1.0f);
  for (int j = 0; j < GRID; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= GRID; ++i) {
      glTexCoord2f((float)i / GRID, (float)(j + 1) / GRID);
      glVertex2f(x0 + i * step, y0 + (j + 1) * step);
      glTexCoord2f((float)i / GRID, (float)j / GRID);
      glVertex2f(x0 + i * step, y0 + j * step);
    }
    glEnd();
  }
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -200.0, 200.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glGenTextures(ROWS, textures);
  for (int row = 0; row < ROWS; ++row) makeTexture(row);

  const GLfloat envColor[4] = {0.2f, 0.9f, 0.3f, 0.6f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
  const GLfloat diffuse[4] = {0.9f, 0.75f, 0.55f, 0.8f};
  const GLfloat ambient[4] = {0.25f, 0.25f, 0.3f, 0.8f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  for (int row = 0; row < ROWS; ++row) {
    for (int column = 0; column < COLUMNS; ++column) {
      const float x0 = (float)(column * CELL), y0 = (float)((ROWS - 1 - row) * CELL);
      glDisable(GL_LIGHTING);
      glDisable(GL_TEXTURE_2D);
      glDisable(GL_BLEND);
      checkerboard(x0, y0);
      if (modes[column] == GL_DECAL && row >= 2) continue;  /* undefined in the specification */

      /* The light sits above the square's lower left quarter. */
      const GLfloat position[4] = {x0 + 30.0f, y0 + 30.0f, 60.0f, 1.0f};
      glLightfv(GL_LIGHT0, GL_POSITION, position);
      glEnable(GL_LIGHTING);
      glEnable(GL_LIGHT0);
      glEnable(GL_BLEND);
      glEnable(GL_TEXTURE_2D);
      glBindTexture(GL_TEXTURE_2D, textures[row]);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[column]);
      litSquare(x0 + 6.0f, y0 + 6.0f, CELL - 12.0f);
    }
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
