/* Every wrap mode (spec 3.8.7), with NEAREST (top row) and LINEAR (bottom row) filtering:
 *
 *   REPEAT   MIRRORED_REPEAT   CLAMP   CLAMP_TO_EDGE   CLAMP_TO_BORDER
 *
 * Each square shows texture coordinates from -1 to 2 in s and t, so the 8 x 8 texture appears
 * three times across: repeated, mirrored, or clamped to its edge texels or to the border colour
 * (magenta). A red frame marks the texture's edge texels. With LINEAR filtering, CLAMP blends the
 * edge texels half-way into the border colour at s = 0 and s = 1, CLAMP_TO_EDGE never reaches the
 * border, and CLAMP_TO_BORDER fades into it over half a texel. Each square is 104 pixels wide, so
 * no pixel centre falls exactly on a texel boundary, where NEAREST could pick either texel. */
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 116, COLUMNS = 5, ROWS = 2, TEX = 8 };

static const GLenum modes[COLUMNS] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE,
                                      GL_CLAMP_TO_BORDER};

static void makeTexture(void)
{
  static GLubyte texels[TEX][TEX][4];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      GLubyte *t = texels[j][i];
      if (i == 0 || j == 0 || i == TEX - 1 || j == TEX - 1) {
        t[0] = 220; t[1] = 30; t[2] = 30;          /* the edge texels */
      } else {
        /* A gradient, so the direction of each copy is visible. */
        t[0] = (GLubyte)(40 + 25 * i);
        t[1] = (GLubyte)(40 + 25 * j);
        t[2] = 200;
      }
      t[3] = 255;
    }
  }
  /* A black texel near the origin shows orientation (mirroring flips it). */
  texels[1][1][0] = texels[1][1][1] = texels[1][1][2] = 0;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  const GLfloat border[4] = {1.0f, 0.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

static void draw(void)
{
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  makeTexture();
  glEnable(GL_TEXTURE_2D);
  for (int row = 0; row < ROWS; ++row) {
    const GLint filter = row == 0 ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    for (int column = 0; column < COLUMNS; ++column) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)modes[column]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)modes[column]);
      const float x0 = column * CELL + 6.0f, y0 = row * CELL + 6.0f, size = CELL - 12.0f;
      glBegin(GL_QUADS);
      glTexCoord2f(-1.0f, -1.0f);
      glVertex2f(x0, y0);
      glTexCoord2f(2.0f, -1.0f);
      glVertex2f(x0 + size, y0);
      glTexCoord2f(2.0f, 2.0f);
      glVertex2f(x0 + size, y0 + size);
      glTexCoord2f(-1.0f, 2.0f);
      glVertex2f(x0, y0 + size);
      glEnd();
    }
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
