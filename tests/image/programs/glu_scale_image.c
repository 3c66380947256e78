/* gluScaleImage (GLU 1.3, section 3.1) against Mesa's libGLU, drawn with glDrawPixels so that the
 * picture is the scaled bytes themselves. A 4 x 2 grid of 100-pixel cells, one scaled image each:
 *   row 2: RGB bytes enlarged 5 x 7 -> 90 x 80 (GLU interpolates between the two nearest texels,
 *          its boxes wrapping round the image's edges); reduced 97 x 91 -> 37 x 23 (box filter);
 *          halved exactly 64 x 64 -> 32 x 32; RGBA bytes 3 x 3 -> 90 x 90
 *   row 1: LUMINANCE floats 30 x 20 -> 87 x 59, written as bytes; unsigned shorts 17 x 13 ->
 *          61 x 88, as bytes; bytes 40 x 40 -> 41 x 39 (almost the same size); one row 64 x 1 ->
 *          80 x 8
 * GLU computes in 16-bit values and single precision; the pictures must be identical. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>

#include <stdlib.h>

#include "gl_program.h"
#include "lcg.h"

enum { CELL = 100, COLUMNS = 4, ROWS = 2 };

static Lcg random_bytes = {2024u};

static void *randomImage(int width, int height, int components, GLenum type)
{
  const size_t count = (size_t)width * (size_t)height * (size_t)components;
  void *image = malloc(count * 4);
  for (size_t i = 0; i < count; ++i) {
    const unsigned value = lcg_below(&random_bytes, 65536);
    if (type == GL_FLOAT)
      ((GLfloat *)image)[i] = (GLfloat)value / 65535.0f;
    else if (type == GL_UNSIGNED_SHORT)
      ((GLushort *)image)[i] = (GLushort)value;
    else
      ((GLubyte *)image)[i] = (GLubyte)(value >> 8);
  }
  return image;
}

/* Scales a random image and draws the result at the lower left of cell (column, row). */
static void scaledCell(int column, int row, GLenum format, GLenum typeIn, int widthIn, int heightIn,
                       int widthOut, int heightOut)
{
  const int components = format == GL_RGBA ? 4 : format == GL_RGB ? 3 : 1;
  void *in = randomImage(widthIn, heightIn, components, typeIn);
  GLubyte *out = malloc((size_t)widthOut * (size_t)heightOut * (size_t)components);
  gluScaleImage(format, widthIn, heightIn, typeIn, in, widthOut, heightOut, GL_UNSIGNED_BYTE, out);
  glWindowPos2i(column * CELL + 5, row * CELL + 5);
  glDrawPixels(widthOut, heightOut, format, GL_UNSIGNED_BYTE, out);
  free(in);
  free(out);
}

static void draw(void)
{
  glClearColor(0.2f, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  scaledCell(0, 1, GL_RGB, GL_UNSIGNED_BYTE, 5, 7, 90, 80);
  scaledCell(1, 1, GL_RGB, GL_UNSIGNED_BYTE, 97, 91, 37, 23);
  scaledCell(2, 1, GL_RGB, GL_UNSIGNED_BYTE, 64, 64, 32, 32);
  scaledCell(3, 1, GL_RGBA, GL_UNSIGNED_BYTE, 3, 3, 90, 90);
  scaledCell(0, 0, GL_LUMINANCE, GL_FLOAT, 30, 20, 87, 59);
  scaledCell(1, 0, GL_RGB, GL_UNSIGNED_SHORT, 17, 13, 61, 88);
  scaledCell(2, 0, GL_RGB, GL_UNSIGNED_BYTE, 40, 40, 41, 39);
  scaledCell(3, 0, GL_RGB, GL_UNSIGNED_BYTE, 64, 1, 80, 8);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
