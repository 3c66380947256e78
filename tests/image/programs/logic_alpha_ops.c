/* Fragment operations that older programs lean on. Top left: rubber-band rectangles drawn with
 * glLogicOp(GL_XOR) over a picture, twice for one of them (which erases it), and GL_INVERT and
 * GL_AND_REVERSE bands. Top right: cut-out sprites, an RGBA texture whose alpha is 0 outside a
 * shape, drawn with glAlphaFunc(GL_GREATER, 0.5) and the depth test, so that the cut-away parts
 * neither colour nor hide what is behind; and GL_LEQUAL, GL_EQUAL and GL_NOTEQUAL alpha tests on a
 * smooth alpha ramp. Bottom: destination alpha: a mask written to the alpha channel alone
 * (glColorMask(0, 0, 0, 1)), then a picture blended with GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA;
 * and GL_SRC_ALPHA_SATURATE blending of overlapping discs into a cleared alpha. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 320 };

static GLubyte sprite[32][32][4];

static void makeSprite(void)
{
  int i, j;
  for (i = 0; i < 32; ++i) {
    for (j = 0; j < 32; ++j) {
      const float dx = (float)j - 15.5f, dy = (float)i - 15.5f;
      const float r = sqrtf(dx * dx + dy * dy);
      const int star = r < 8.0f + 6.0f * (float)fabs(cos(2.5 * atan2(dy, dx)));
      sprite[i][j][0] = (GLubyte)(star ? 255 : 0);
      sprite[i][j][1] = (GLubyte)(star ? 200 - 4 * i : 0);
      sprite[i][j][2] = (GLubyte)(star ? 40 + 6 * j : 255);
      sprite[i][j][3] = (GLubyte)(star ? 255 : 0);
    }
  }
}

static void disc(float x, float y, float r, float red, float green, float blue, float alpha)
{
  int i;
  glColor4f(red, green, blue, alpha);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(x, y);
  for (i = 0; i <= 32; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 32.0;
    glVertex2f(x + r * (float)cos(a), y + r * (float)sin(a));
  }
  glEnd();
}

static void draw(void)
{
  GLuint texture;
  int i;

  makeSprite();
  glClearColor(0.2f, 0.2f, 0.25f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Top left: a picture, then XOR rubber bands. */
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.2f, 0.2f); glVertex2f(10.0f, 170.0f);
  glColor3f(0.2f, 1.0f, 0.2f); glVertex2f(190.0f, 170.0f);
  glColor3f(0.2f, 0.2f, 1.0f); glVertex2f(190.0f, 310.0f);
  glColor3f(1.0f, 1.0f, 0.2f); glVertex2f(10.0f, 310.0f);
  glEnd();
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glColor3f(1.0f, 1.0f, 1.0f);
  for (i = 0; i < 3; ++i) {
    glBegin(GL_LINE_LOOP);
    glVertex2f(20.5f + 10.0f * (float)i, 180.5f + 8.0f * (float)i);
    glVertex2f(150.5f - 5.0f * (float)i, 180.5f + 8.0f * (float)i);
    glVertex2f(150.5f - 5.0f * (float)i, 290.5f - 6.0f * (float)i);
    glVertex2f(20.5f + 10.0f * (float)i, 290.5f - 6.0f * (float)i);
    glEnd();
  }
  /* The second rectangle again: XOR twice restores the picture. */
  glBegin(GL_LINE_LOOP);
  glVertex2f(30.5f, 188.5f); glVertex2f(145.5f, 188.5f); glVertex2f(145.5f, 284.5f); glVertex2f(30.5f, 284.5f);
  glEnd();
  glLogicOp(GL_INVERT);
  glRectf(160.0f, 175.0f, 175.0f, 305.0f);
  glLogicOp(GL_AND_REVERSE);
  glColor3ub(0x0F, 0xF0, 0x3C);
  glRectf(176.0f, 175.0f, 188.0f, 305.0f);
  glDisable(GL_COLOR_LOGIC_OP);

  /* Top right: cut-out sprites with the alpha test and depth. */
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, sprite);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  for (i = 0; i < 4; ++i) {
    const float x = 215.0f + 35.0f * (float)i, y = 200.0f + 15.0f * (float)(i % 2);
    const float z = (float)i;  /* later sprites nearer */
    glBegin(GL_QUADS);
    glTexCoord2f(0.013f, 0.017f); glVertex3f(x, y, z);
    glTexCoord2f(1.013f, 0.017f); glVertex3f(x + 90.0f, y, z);
    glTexCoord2f(1.013f, 1.017f); glVertex3f(x + 90.0f, y + 90.0f, z);
    glTexCoord2f(0.013f, 1.017f); glVertex3f(x, y + 90.0f, z);
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_DEPTH_TEST);
  /* Alpha ramps under three alpha functions. */
  {
    static const GLenum functions[3] = {GL_LEQUAL, GL_EQUAL, GL_NOTEQUAL};
    for (i = 0; i < 3; ++i) {
      glAlphaFunc(functions[i], 0.6f);
      glBegin(GL_QUADS);
      glColor4f(1.0f, 1.0f, 1.0f, 0.0f); glVertex2f(215.0f, 175.0f - 10.0f * (float)i);
      glColor4f(1.0f, 1.0f, 1.0f, 1.0f); glVertex2f(390.0f, 175.0f - 10.0f * (float)i);
      glColor4f(1.0f, 1.0f, 1.0f, 1.0f); glVertex2f(390.0f, 183.0f - 10.0f * (float)i);
      glColor4f(1.0f, 1.0f, 1.0f, 0.0f); glVertex2f(215.0f, 183.0f - 10.0f * (float)i);
      glEnd();
    }
  }
  glDisable(GL_ALPHA_TEST);

  /* Bottom left: destination alpha. The mask: alpha 1 in a ring, 0.5 in a square, 0 elsewhere. */
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glColor4f(0.0f, 0.0f, 0.0f, 0.0f);
  glRectf(10.0f, 10.0f, 190.0f, 140.0f);
  disc(100.0f, 75.0f, 60.0f, 0.0f, 0.0f, 0.0f, 1.0f);
  disc(100.0f, 75.0f, 35.0f, 0.0f, 0.0f, 0.0f, 0.0f);
  glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
  glRectf(20.0f, 20.0f, 60.0f, 60.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.5f, 0.0f); glVertex2f(10.0f, 10.0f);
  glColor3f(0.0f, 1.0f, 0.5f); glVertex2f(190.0f, 10.0f);
  glColor3f(0.5f, 0.0f, 1.0f); glVertex2f(190.0f, 140.0f);
  glColor3f(1.0f, 1.0f, 1.0f); glVertex2f(10.0f, 140.0f);
  glEnd();

  /* Bottom right: alpha-saturate blending of overlapping translucent discs (front to back). */
  glColor4f(0.0f, 0.0f, 0.0f, 0.0f);
  glDisable(GL_BLEND);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glRectf(210.0f, 10.0f, 390.0f, 140.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
  disc(270.0f, 80.0f, 45.0f, 1.0f, 0.2f, 0.2f, 0.6f);
  disc(320.0f, 80.0f, 45.0f, 0.2f, 1.0f, 0.2f, 0.6f);
  disc(295.0f, 45.0f, 45.0f, 0.2f, 0.2f, 1.0f, 0.6f);
  glDisable(GL_BLEND);
  glDeleteTextures(1, &texture);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
