/* glDrawPixels (GL 1.5 specification, sections 3.6.4 and 3.6.5) in many formats and types, with
 * the unpack parameters of glPixelStore, glPixelZoom and the pixel transfer operations of
 * glPixelTransfer and glPixelMap, over a background of smooth triangles. A 4 x 3 grid of
 * 100-pixel cells, each with one image:
 *   row 3: RGB unsigned bytes (the Red Book's checkerboard) at zoom 1; the same zoomed by 2 x 1;
 *          flipped by zoom (-1, -1); mirrored and enlarged by zoom (-2, 2)
 *   row 2: LUMINANCE floats; ALPHA bytes blended over the background; BGRA unsigned shorts;
 *          UNSIGNED_SHORT_5_6_5 RGB
 *   row 1: a sub-image picked out by GL_UNPACK_ROW_LENGTH, SKIP_PIXELS, SKIP_ROWS and alignment
 *          1; RED_SCALE / GREEN_BIAS transfer; RGBA floats outside [0, 1] (clamped) blended by
 *          their alpha; COLOR_INDEX through the I_TO_R/G/B/A maps
 * (GL_MAP_COLOR's RGBA-to-RGBA lookups are left to the unit tests: Mesa's gallium drivers look up
 * blue and alpha wrongly and index the maps by truncation.)
 * Zoom factors are whole numbers: with a fractional zoom, a pixel centre can fall exactly on the
 * edge between two image pixels' rectangles, where glass takes the upper one and Mesa's texture
 * interpolation rounds either way.
 * Raster positions come from glRasterPos under an orthographic projection, and from glWindowPos
 * for the last row. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 100, COLUMNS = 4, ROWS = 3, W = 40, H = 32 };

static GLubyte checker[H][W][3];
static GLfloat luminance[H][W];
static GLubyte alpha[H][W];
static GLushort bgra[H][W][4];
static GLushort rgb565[H][W];
static GLubyte big[64][61][4]; /* a larger RGBA image whose middle is drawn via the skips */
static GLubyte indices[H][W];
static GLfloat wide[H][W][4]; /* components below 0 and above 1 */

static void makeImages(void)
{
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < W; ++j) {
      const int c = (((i & 0x8) == 0) ^ ((j & 0x8) == 0)) * 255;
      checker[i][j][0] = (GLubyte)c;
      checker[i][j][1] = (GLubyte)(c ? 200 : 40 + 4 * i);
      checker[i][j][2] = (GLubyte)(6 * j);
      luminance[i][j] = (float)(i * W + j) / (float)(W * H - 1);
      alpha[i][j] = (GLubyte)((i * 8) ^ (j * 6));
      bgra[i][j][0] = (GLushort)(j * 1600);          /* B */
      bgra[i][j][1] = (GLushort)(i * 2000);          /* G */
      bgra[i][j][2] = (GLushort)(65535 - j * 1600);  /* R */
      bgra[i][j][3] = 65535;
      rgb565[i][j] = (GLushort)(((j * 31 / (W - 1)) << 11) | ((i * 63 / (H - 1)) << 5) | ((i + j) % 32));
      indices[i][j] = (GLubyte)((i / 4 + j / 5) % 4);
      wide[i][j][0] = 1.6f * (float)j / (W - 1) - 0.3f;
      wide[i][j][1] = 1.4f - 1.8f * (float)i / (H - 1);
      wide[i][j][2] = 0.5f;
      wide[i][j][3] = (float)(j + i) / (W + H - 2);
    }
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 61; ++j) {
      big[i][j][0] = (GLubyte)(4 * i);
      big[i][j][1] = (GLubyte)(4 * j);
      big[i][j][2] = (GLubyte)(((i / 6) + (j / 6)) % 2 ? 255 : 0);
      big[i][j][3] = 255;
    }
}

static void background(void)
{
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < COLUMNS * ROWS; ++i) {
    const float x = (float)(i % COLUMNS * CELL), y = (float)(i / COLUMNS * CELL);
    glColor3f(0.2f, 0.2f, 0.5f);
    glVertex2f(x, y);
    glColor3f(0.6f, 0.3f, 0.2f);
    glVertex2f(x + CELL, y);
    glColor3f(0.2f, 0.5f, 0.3f);
    glVertex2f(x, y + CELL);
  }
  glEnd();
}

/* The raster position for cell (column, row), row 0 at the bottom. */
static void cell(int column, int row, int dx, int dy)
{
  glRasterPos2i(column * CELL + dx, row * CELL + dy);
}

static void draw(void)
{
  makeImages();
  glViewport(0, 0, COLUMNS * CELL, ROWS * CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  background();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* Row 3 (top): zoom. */
  cell(0, 2, 10, 10);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, checker);
  cell(1, 2, 10, 10);
  glPixelZoom(2.0f, 1.0f);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, checker);
  cell(2, 2, 80, 90);
  glPixelZoom(-1.0f, -1.0f);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, checker);
  cell(3, 2, 90, 10);
  glPixelZoom(-2.0f, 2.0f);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, checker);
  glPixelZoom(1.0f, 1.0f);

  /* Row 2: formats and types. */
  cell(0, 1, 10, 10);
  glDrawPixels(W, H, GL_LUMINANCE, GL_FLOAT, luminance);
  cell(1, 1, 10, 10);
  glColor3f(1.0f, 0.9f, 0.2f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawPixels(W, H, GL_ALPHA, GL_UNSIGNED_BYTE, alpha);
  glDisable(GL_BLEND);
  cell(2, 1, 10, 10);
  glDrawPixels(W, H, GL_BGRA, GL_UNSIGNED_SHORT, bgra);
  cell(3, 1, 10, 10);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, rgb565);

  /* Row 1: unpack parameters and the transfer operations. */
  glWindowPos2i(10, 10);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 61);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 11);
  glDrawPixels(45, 40, GL_RGBA, GL_UNSIGNED_BYTE, big);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);

  glWindowPos2i(CELL + 10, 10);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, checker);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);

  glWindowPos2i(2 * CELL + 10, 10);
  glEnable(GL_BLEND);
  glDrawPixels(W, H, GL_RGBA, GL_FLOAT, wide);
  glDisable(GL_BLEND);
  {
    const GLfloat r[4] = {1.0f, 0.0f, 0.2f, 0.9f}, g[4] = {0.0f, 1.0f, 0.4f, 0.9f},
                  b[4] = {0.0f, 0.0f, 1.0f, 0.1f}, a[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
    glWindowPos2i(3 * CELL + 10, 10);
    glDrawPixels(W, H, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
