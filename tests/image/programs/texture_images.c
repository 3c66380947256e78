/* Specifying texture images (spec 3.8.1 to 3.8.3), one square per way, magnified with NEAREST:
 *
 *   row 1: RGB bytes 13 x 7 with the default 4-byte row alignment (rows padded to 40 bytes);
 *          RGBA floats 10 x 6; LUMINANCE cut out of a larger image with GL_UNPACK_ROW_LENGTH,
 *          SKIP_ROWS and SKIP_PIXELS; LUMINANCE_ALPHA floats
 *   row 2: BGRA bytes; RGB as UNSIGNED_SHORT_5_6_5; ALPHA bytes over the fragment colour;
 *          a 1D texture with glTexSubImage1D
 *   row 3: glTexSubImage2D patching the middle of a texture; glCopyTexImage2D of a picture drawn
 *          into the colour buffer; glCopyTexSubImage2D of it into a corner; a texture read back
 *          with glGetTexImage and specified again from what came back
 * Non-power-of-two sizes throughout. Each square is 96 pixels wide: no texture here is 64 texels
 * wide or high, so no pixel centre falls exactly on a texel boundary (where NEAREST could pick
 * either texel). */
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 112, COLUMNS = 4, ROWS = 3 };

static void quad(int index, float r, float g, float b)
{
  const float x0 = (float)((index % COLUMNS) * CELL) + 8.0f;
  const float y0 = (float)((ROWS - 1 - index / COLUMNS) * CELL) + 8.0f;
  const float size = CELL - 16.0f;
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(x0, y0);
  glTexCoord2f(1.0f, 0.0f);
  glVertex2f(x0 + size, y0);
  glTexCoord2f(1.0f, 1.0f);
  glVertex2f(x0 + size, y0 + size);
  glTexCoord2f(0.0f, 1.0f);
  glVertex2f(x0, y0 + size);
  glEnd();
}

static void nearest(GLenum target)
{
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static GLuint newTexture(GLenum target)
{
  GLuint name;
  glGenTextures(1, &name);
  glBindTexture(target, name);
  nearest(target);
  return name;
}

static void rgbAligned(void)
{
  /* 13 texels of 3 bytes = 39 bytes per row, padded to 40 by GL_UNPACK_ALIGNMENT 4. */
  static GLubyte data[7][40];
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 13; ++i) {
      data[j][3 * i + 0] = (GLubyte)(20 * i);
      data[j][3 * i + 1] = (GLubyte)(36 * j);
      data[j][3 * i + 2] = (GLubyte)((i + j) % 2 ? 200 : 60);
    }
  newTexture(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 13, 7, 0, GL_RGB, GL_UNSIGNED_BYTE, data);
}

static void rgbaFloat(void)
{
  static GLfloat data[6][10][4];
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 10; ++i) {
      data[j][i][0] = (float)i / 9.0f;
      data[j][i][1] = 0.3f + 0.1f * (float)j;
      data[j][i][2] = (i + j) % 3 == 0 ? 1.0f : 0.2f;
      data[j][i][3] = 1.0f;
    }
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 6, 0, GL_RGBA, GL_FLOAT, data);
}

static void luminanceSubregion(void)
{
  /* A 20 x 12 image; the texture is its 9 x 5 part starting at column 6, row 4. */
  static GLubyte big[12][20];
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 20; ++i) big[j][i] = (GLubyte)((i >= 6 && i < 15 && j >= 4 && j < 9) ? 25 * (i - 6) + 30 * (j - 4) % 60 : 255);
  newTexture(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 4);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 6);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 9, 5, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, big);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
}

static void luminanceAlphaFloat(void)
{
  static GLfloat data[5][7][2];
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 7; ++i) {
      data[j][i][0] = (float)(i + j) / 10.0f;
      data[j][i][1] = (i + j) % 2 ? 1.0f : 0.35f;
    }
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 7, 5, 0, GL_LUMINANCE_ALPHA, GL_FLOAT, data);
}

static void bgra(void)
{
  static GLubyte data[6][6][4];
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      data[j][i][0] = (GLubyte)(40 * i); /* blue */
      data[j][i][1] = 100;               /* green */
      data[j][i][2] = (GLubyte)(40 * j); /* red */
      data[j][i][3] = 255;
    }
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 0, GL_BGRA, GL_UNSIGNED_BYTE, data);
}

static void packed565(void)
{
  static GLushort data[5][6];
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 6; ++i) data[j][i] = (GLushort)(((6 * i) << 11) | ((15 * j) << 5) | (31 - 5 * i));
  newTexture(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 6, 5, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, data);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

static void alphaOnly(void)
{
  static GLubyte data[9][9];
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i) data[j][i] = (GLubyte)((i - 4) * (i - 4) + (j - 4) * (j - 4) < 12 ? 255 : 40);
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 9, 9, 0, GL_ALPHA, GL_UNSIGNED_BYTE, data);
}

static void oneDimensional(void)
{
  static GLubyte ramp[11][3];
  static const GLubyte patch[3][3] = {{255, 255, 255}, {0, 0, 0}, {255, 255, 255}};
  for (int i = 0; i < 11; ++i) {
    ramp[i][0] = (GLubyte)(25 * i);
    ramp[i][1] = (GLubyte)(250 - 25 * i);
    ramp[i][2] = 120;
  }
  newTexture(GL_TEXTURE_1D);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 11, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 4, 3, GL_RGB, GL_UNSIGNED_BYTE, patch);
}

static void subImage(void)
{
  static GLubyte base[8][12][3];
  static GLubyte patch[3][5][3];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 12; ++i) {
      base[j][i][0] = 40;
      base[j][i][1] = (GLubyte)(100 + 15 * j);
      base[j][i][2] = (GLubyte)(100 + 10 * i);
    }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) {
      patch[j][i][0] = 250;
      patch[j][i][1] = (GLubyte)(60 * j);
      patch[j][i][2] = (GLubyte)(50 * i);
    }
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 12, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, base);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 3, 5, 3, GL_RGB, GL_UNSIGNED_BYTE, patch);
}

/* Draws a small picture at the window's lower left corner for the copies to read. */
static void pictureToCopy(void)
{
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.9f, 0.1f);
  glVertex2f(0.0f, 0.0f);
  glColor3f(0.1f, 0.4f, 1.0f);
  glVertex2f(23.0f, 0.0f);
  glColor3f(0.9f, 0.1f, 0.5f);
  glVertex2f(0.0f, 17.0f);
  glEnd();
}

static void readBackAndRespecify(void)
{
  static GLubyte data[7][9][4];
  static GLubyte back[7][9][4];
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 9; ++i) {
      data[j][i][0] = (GLubyte)(28 * i);
      data[j][i][1] = (GLubyte)((i * j) % 5 * 60);
      data[j][i][2] = (GLubyte)(36 * j);
      data[j][i][3] = 255;
    }
  newTexture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 9, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 9, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
}

static void draw(void)
{
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* The copies come first, while the corner they read holds only the picture. */
  pictureToCopy();
  GLuint copied = newTexture(GL_TEXTURE_2D);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 23, 17, 0);
  GLuint copiedSub = newTexture(GL_TEXTURE_2D);
  {
    static GLubyte grey[10][14][3];
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 14; ++i) grey[j][i][0] = grey[j][i][1] = grey[j][i][2] = (GLubyte)(90 + 10 * ((i + j) % 2));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 14, 10, 0, GL_RGB, GL_UNSIGNED_BYTE, grey);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 7, 4, 2, 1, 6, 5);
  }
  glClear(GL_COLOR_BUFFER_BIT);

  glEnable(GL_TEXTURE_2D);
  rgbAligned();
  quad(0, 1, 1, 1);
  rgbaFloat();
  quad(1, 1, 1, 1);
  luminanceSubregion();
  quad(2, 1, 1, 1);
  luminanceAlphaFloat();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  quad(3, 1, 1, 1);
  bgra();
  quad(4, 1, 1, 1);
  packed565();
  quad(5, 1, 1, 1);
  alphaOnly();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  quad(6, 1.0f, 0.6f, 0.1f);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  oneDimensional();
  quad(7, 1, 1, 1);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);
  subImage();
  quad(8, 1, 1, 1);
  glBindTexture(GL_TEXTURE_2D, copied);
  quad(9, 1, 1, 1);
  glBindTexture(GL_TEXTURE_2D, copiedSub);
  quad(10, 1, 1, 1);
  readBackAndRespecify();
  quad(11, 1, 1, 1);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
