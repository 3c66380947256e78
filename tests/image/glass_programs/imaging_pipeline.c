/* The imaging subset (GL_ARB_imaging, OpenGL 1.4 sections 3.6.3 and 3.6.5) in the style of the
 * Red Book's colormatrix.c, convolution.c, colortable.c and histogram.c: one 64 x 64 image drawn
 * with glDrawPixels (zoomed 2x) six times through different stages of the pixel transfer path.
 *
 *   top row     the image as it is; through a colour matrix that swaps red and blue; through a
 *               colour table that inverts every component
 *   bottom row  a 3 x 3 sharpen filter (GL_REPLICATE_BORDER); a 3 x 3 box blur in GL_REDUCE mode
 *               (the picture comes out 62 x 62, two zoomed pixels smaller at the top and right);
 *               the histogram of the image's red, green and blue (256 bins, taken with the sink
 *               on, so that nothing is drawn), plotted as three line strips, and the minmax of
 *               the same pass as two grey bars marking the least and greatest red
 * glass-only: Mesa's llvmpipe has no imaging subset, so the reference image is a reviewed glass
 * render (reference_images/README.md); the stages are checked value by value in
 * tests/unit/pixels_imaging_test.cpp. */
#include <GL/gl.h>

#include "gl_program.h"

enum { WIDTH = 424, HEIGHT = 288, SIZE = 64, ZOOM = 2, BINS = 256 };

static GLubyte image[SIZE][SIZE][3];

/* A vertical red-to-blue gradient with a white disc, a dark checkered corner and a green
 * diagonal: edges of every direction for the filters, distinct colours for the matrix and tables. */
static void makeImage(void)
{
  for (int y = 0; y < SIZE; ++y) {
    for (int x = 0; x < SIZE; ++x) {
      GLubyte *p = image[y][x];
      p[0] = (GLubyte)(255 - y * 4);
      p[1] = (GLubyte)(x * 2);
      p[2] = (GLubyte)(y * 4);
      const int dx = x - 38, dy = y - 36;
      if (dx * dx + dy * dy < 14 * 14) p[0] = p[1] = p[2] = 240;
      if (x < 20 && y < 20 && ((x / 5 + y / 5) & 1)) p[0] = p[1] = p[2] = 30;
      if (x == y || x == y + 1) {
        p[0] = 20;
        p[1] = 220;
        p[2] = 40;
      }
    }
  }
}

static void drawImageAt(int x, int y)
{
  glWindowPos2i(x, y);
  glDrawPixels(SIZE, SIZE, GL_RGB, GL_UNSIGNED_BYTE, image);
}

static void colorMatrixPanel(int x, int y)
{
  static const GLfloat swapRedBlue[16] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  glMatrixMode(GL_COLOR);
  glLoadMatrixf(swapRedBlue);
  drawImageAt(x, y);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
}

static void colorTablePanel(int x, int y)
{
  GLubyte invert[256][3];
  for (int i = 0; i < 256; ++i) invert[i][0] = invert[i][1] = invert[i][2] = (GLubyte)(255 - i);
  glColorTable(GL_COLOR_TABLE, GL_RGB, 256, GL_RGB, GL_UNSIGNED_BYTE, invert);
  glEnable(GL_COLOR_TABLE);
  drawImageAt(x, y);
  glDisable(GL_COLOR_TABLE);
}

static void convolutionPanel(int x, int y, const GLfloat *filter, GLenum borderMode)
{
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, filter);
  glConvolutionParameteri(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, borderMode);
  glEnable(GL_CONVOLUTION_2D);
  drawImageAt(x, y);
  glDisable(GL_CONVOLUTION_2D);
}

static void histogramPanel(int x, int y)
{
  GLushort counts[BINS][3];
  GLfloat minmax[2][3];
  glHistogram(GL_HISTOGRAM, BINS, GL_RGB, GL_TRUE);
  glMinmax(GL_MINMAX, GL_RGB, GL_FALSE);
  glEnable(GL_HISTOGRAM);
  glEnable(GL_MINMAX);
  drawImageAt(x, y);  /* counted, then discarded by the sink: nothing is drawn */
  glDisable(GL_HISTOGRAM);
  glDisable(GL_MINMAX);
  glGetHistogram(GL_HISTOGRAM, GL_TRUE, GL_RGB, GL_UNSIGNED_SHORT, counts);
  glGetMinmax(GL_MINMAX, GL_TRUE, GL_RGB, GL_FLOAT, minmax);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, WIDTH, 0, HEIGHT, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(0.25f, 0.25f, 0.25f);
  glRectf((GLfloat)x, (GLfloat)y, (GLfloat)(x + SIZE * ZOOM), (GLfloat)(y + SIZE * ZOOM));
  /* The least and greatest red of the image (minmax), as two grey bars. */
  glColor3f(0.55f, 0.55f, 0.55f);
  for (int k = 0; k < 2; ++k) {
    const GLfloat at = (GLfloat)x + minmax[k][0] * (GLfloat)(SIZE * ZOOM - 1);
    glRectf(at, (GLfloat)y, at + 2.0f, (GLfloat)(y + SIZE * ZOOM));
  }
  for (int c = 0; c < 3; ++c) {
    glColor3f(c == 0 ? 1.0f : 0.2f, c == 1 ? 1.0f : 0.2f, c == 2 ? 1.0f : 0.2f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < BINS; ++i) {
      /* 128 pixels wide for 256 bins; a count of 160 reaches the top. */
      const GLfloat h = counts[i][c] > 160 ? 160.0f : (GLfloat)counts[i][c];
      glVertex2f((GLfloat)x + 0.5f + (GLfloat)i * 0.5f, (GLfloat)y + 0.5f + h * (SIZE * ZOOM - 1) / 160.0f);
    }
    glEnd();
  }
}

static void draw(void)
{
  static const GLfloat sharpen[9] = {0, -1, 0, -1, 5, -1, 0, -1, 0};
  static const GLfloat blur[9] = {1 / 9.0f, 1 / 9.0f, 1 / 9.0f, 1 / 9.0f, 1 / 9.0f,
                                  1 / 9.0f, 1 / 9.0f, 1 / 9.0f, 1 / 9.0f};
  const int left = 8, middle = 148, right = 288, top = 152, bottom = 8;
  makeImage();
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelZoom(ZOOM, ZOOM);
  drawImageAt(left, top);
  colorMatrixPanel(middle, top);
  colorTablePanel(right, top);
  convolutionPanel(left, bottom, sharpen, GL_REPLICATE_BORDER);
  convolutionPanel(middle, bottom, blur, GL_REDUCE);
  histogramPanel(right, bottom);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
