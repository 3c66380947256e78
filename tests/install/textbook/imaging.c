/* A textbook-style tour of the imaging subset, in the manner of the classic colour table,
 * colour matrix, convolution and histogram examples: it first looks for GL_ARB_imaging in
 * GL_EXTENSIONS, as such programs do before calling any of it, then draws a small image with
 * glDrawPixels through each stage and, with the stage switched off again (glReadPixels goes
 * through the same stages), reads back what it can work out by hand. Built unchanged
 * against an installed glass by the install test, which checks the line it prints. */
#include <GL/gl.h>
#include <glass/context.h>

#include <stdio.h>
#include <string.h>

enum { SIZE = 8 };

/* A 4 x 3 luminance image, row 0 first. */
static const GLubyte image[12] = {8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96};

static void draw_image(void)
{
  glClear(GL_COLOR_BUFFER_BIT);
  glRasterPos2i(0, 0);
  glDrawPixels(4, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, image);
}

static GLubyte red_at(int x, int y)
{
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return p[0];
}

static GLubyte blue_at(int x, int y)
{
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return p[2];
}

int main(void)
{
  GlassContext *ctx = glassCreateContext(SIZE, SIZE);
  const char *extensions;
  GLubyte invert[256][3];
  GLfloat swap_red_blue[16] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  GLfloat cross[9] = {0, 0.25f, 0, 0.25f, 0, 0.25f, 0, 0.25f, 0};
  GLuint counts[4];
  GLubyte extremes[2];
  int i, inverted, swapped, convolved, counted, ok;

  if (!ctx || !glassMakeCurrent(ctx)) return 1;
  extensions = (const char *)glGetString(GL_EXTENSIONS);
  if (!extensions || !strstr(extensions, "GL_ARB_imaging")) {
    printf("imaging: GL_ARB_imaging is not supported\n");
    return 1;
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, SIZE, 0, SIZE, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* A colour table that inverts every component. */
  for (i = 0; i < 256; ++i) invert[i][0] = invert[i][1] = invert[i][2] = (GLubyte)(255 - i);
  glColorTable(GL_COLOR_TABLE, GL_RGB, 256, GL_RGB, GL_UNSIGNED_BYTE, invert);
  glEnable(GL_COLOR_TABLE);
  draw_image();
  glDisable(GL_COLOR_TABLE); /* before reading back: glReadPixels would apply the table too */
  inverted = red_at(1, 0) == 255 - 16 && red_at(3, 2) == 255 - 96;

  /* The colour matrix, with a post-colour-matrix scale: red becomes blue, halved. */
  glMatrixMode(GL_COLOR);
  glLoadMatrixf(swap_red_blue);
  glMatrixMode(GL_MODELVIEW);
  glPixelTransferf(GL_POST_COLOR_MATRIX_BLUE_SCALE, 0.5f);
  glClearColor(0.8f, 0, 0, 1); /* red 204 */
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glMatrixMode(GL_COLOR);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPixelTransferf(GL_POST_COLOR_MATRIX_BLUE_SCALE, 1.0f);
  swapped = blue_at(0, 0) == 102 && red_at(0, 0) == 0;
  glClearColor(0, 0, 0, 1);

  /* A 3 x 3 convolution that averages the four neighbours; GL_REDUCE leaves 2 x 1 pixels. */
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, cross);
  glEnable(GL_CONVOLUTION_2D);
  draw_image();
  glDisable(GL_CONVOLUTION_2D);
  convolved = red_at(0, 0) == (16 + 40 + 56 + 80) / 4 && red_at(1, 0) == (24 + 48 + 64 + 88) / 4 &&
              red_at(2, 0) == 0;

  /* A histogram of 4 bins and the minmax of the image, both sinks: nothing is drawn. */
  glHistogram(GL_HISTOGRAM, 4, GL_LUMINANCE, GL_TRUE);
  glMinmax(GL_MINMAX, GL_LUMINANCE, GL_FALSE);
  glEnable(GL_HISTOGRAM);
  glEnable(GL_MINMAX);
  draw_image();
  glGetHistogram(GL_HISTOGRAM, GL_TRUE, GL_LUMINANCE, GL_UNSIGNED_INT, counts);
  glDisable(GL_HISTOGRAM);
  draw_image();
  glGetMinmax(GL_MINMAX, GL_TRUE, GL_LUMINANCE, GL_UNSIGNED_BYTE, extremes);
  glDisable(GL_MINMAX);
  /* Bin round(l * 3): values up to 42 in bin 0, 43-127 in bin 1. */
  counted = counts[0] == 5 && counts[1] == 7 && counts[2] == 0 && counts[3] == 0 &&
            extremes[0] == 8 && extremes[1] == 96 && red_at(0, 0) == 8;

  ok = inverted && swapped && convolved && counted && glGetError() == GL_NO_ERROR;
  printf("imaging: colour table %s, colour matrix %s, convolution %s, histogram and minmax %s: %s\n",
         inverted ? "ok" : "wrong", swapped ? "ok" : "wrong", convolved ? "ok" : "wrong",
         counted ? "ok" : "wrong", ok ? "ok" : "FAILED");
  glassDestroyContext(ctx);
  return ok ? 0 : 1;
}
