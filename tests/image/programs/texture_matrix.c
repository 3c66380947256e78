/* The texture matrix (spec 2.11.4: texture coordinates are transformed by the top of the
 * GL_TEXTURE stack) on six squares with texture coordinates 0..1:
 *
 *   identity                 rotated 30 degrees about the centre   scaled 3 x 2 (repeats)
 *   translated (0.25, 0.1)   projective (q = 1 + s, then divided)   pushed and popped
 *
 * The texture is an asymmetric "F" on a gradient, so every rotation, mirror and shift shows. The
 * last square pushes a scale, draws nothing, pops it, and must look like the first. */
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 150, COLUMNS = 3, ROWS = 2, TEX = 32 };

static void makeTexture(void)
{
  static GLubyte texels[TEX][TEX][3];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      /* An "F": a vertical bar and two arms, drawn with texel rows counted from the bottom. */
      const int bar = i >= 8 && i < 13 && j >= 4 && j < 28;
      const int top = j >= 23 && j < 28 && i >= 8 && i < 26;
      const int middle = j >= 14 && j < 18 && i >= 8 && i < 21;
      const int ink = bar || top || middle;
      texels[j][i][0] = ink ? 20 : (GLubyte)(120 + 4 * i);
      texels[j][i][1] = ink ? 20 : (GLubyte)(100 + 4 * j);
      texels[j][i][2] = ink ? 60 : 160;
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

static void square(int index)
{
  const float x0 = (float)((index % COLUMNS) * CELL) + 10.0f;
  const float y0 = (float)((ROWS - 1 - index / COLUMNS) * CELL) + 10.0f;
  const float size = CELL - 20.0f;
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

static void draw(void)
{
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  makeTexture();
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

  glMatrixMode(GL_TEXTURE);

  glLoadIdentity();
  square(0);

  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  square(1);

  glLoadIdentity();
  glScalef(3.0f, 2.0f, 1.0f);
  square(2);

  glLoadIdentity();
  glTranslatef(0.25f, 0.1f, 0.0f);
  square(3);

  /* q' = s + q: the square's texture coordinates become (s, t) / (1 + s), a perspective
   * foreshortening of the texture towards the right. */
  {
    const GLfloat projective[16] = {1.0f, 0.0f, 0.0f, 1.0f,  /* column 0: s feeds q' too */
                                    0.0f, 1.0f, 0.0f, 0.0f,
                                    0.0f, 0.0f, 1.0f, 0.0f,
                                    0.0f, 0.0f, 0.0f, 1.0f};
    glLoadMatrixf(projective);
    glScalef(2.0f, 2.0f, 1.0f);
    square(4);
  }

  glLoadIdentity();
  glPushMatrix();
  glScalef(5.0f, 5.0f, 1.0f);
  glPopMatrix();
  square(5);

  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
