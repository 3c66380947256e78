/* glInterleavedArrays, with the formats programs reach for: GL_C3F_V3F (a smooth-shaded
 * hexagon fan), GL_N3F_V3F (a lit pyramid), GL_T2F_V3F (a textured quad), GL_C4UB_V2F (a strip
 * of translucent quads, blended), GL_T2F_C4F_N3F_V3F (a lit, textured, coloured triangle pair)
 * and GL_V2F with a stride (every second vertex of a buffer). Each call sets and enables the
 * arrays the format names and disables the others. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void draw(void)
{
  static GLfloat hexagon[8][6];
  static const GLfloat pyramid[] = {
      0.0f, 0.447f, 0.894f, 0.0f, 1.0f, 0.0f,  0.0f, 0.447f, 0.894f, -1.0f, -0.5f, 1.0f,
      0.0f, 0.447f, 0.894f, 1.0f, -0.5f, 1.0f, 0.894f, 0.447f, 0.0f, 0.0f, 1.0f, 0.0f,
      0.894f, 0.447f, 0.0f, 1.0f, -0.5f, 1.0f, 0.894f, 0.447f, 0.0f, 1.0f, -0.5f, -1.0f,
      -0.894f, 0.447f, 0.0f, 0.0f, 1.0f, 0.0f, -0.894f, 0.447f, 0.0f, -1.0f, -0.5f, -1.0f,
      -0.894f, 0.447f, 0.0f, -1.0f, -0.5f, 1.0f};
  /* Placed so that no pixel centre falls on a texel boundary, where GL_NEAREST may pick either
   * texel (the choice then rests on the last bit of the interpolated coordinate). */
  static const GLfloat texturedQuad[] = {0, 0, -0.987f, -0.987f, 0, 2, 0, 1.013f, -0.987f, 0,
                                         2, 2, 1.013f, 1.013f, 0, 0, 2, -0.987f, 1.013f, 0};
  struct Translucent {
    GLubyte colour[4];
    GLfloat position[2];
  } strip[10];
  /* s t, r g b a, nx ny nz, x y z */
  static const GLfloat everything[] = {
      0, 0, 1.0f, 0.3f, 0.3f, 1, 0, 0, 1, -1, -1, 0,
      1, 0, 0.3f, 1.0f, 0.3f, 1, 0, 0, 1, 1,  -1, 0,
      1, 1, 0.3f, 0.3f, 1.0f, 1, 0, 0, 1, 1,  1,  0,
      0, 1, 1.0f, 1.0f, 1.0f, 1, 0, 0, 1, -1, 1,  0};
  static const GLuint quadIndices[6] = {0, 1, 2, 0, 2, 3};
  static GLfloat spaced[16][2];
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 2.0f, 0.0f};
  static GLubyte texels[4][4][3];
  GLuint texture;
  int i;

  for (i = 0; i < 8; ++i) {
    const double angle = i == 0 ? 0.0 : 2.0 * 3.14159265358979 * (i - 1) / 6.0;
    const float radius = i == 0 ? 0.0f : 1.0f;
    hexagon[i][0] = 0.5f + 0.5f * (float)cos(angle * 1.0 + i);
    hexagon[i][1] = 0.5f + 0.5f * (float)sin(angle + i);
    hexagon[i][2] = i == 0 ? 1.0f : 0.2f;
    hexagon[i][3] = radius * (float)cos(angle);
    hexagon[i][4] = radius * (float)sin(angle);
    hexagon[i][5] = 0.0f;
  }
  for (i = 0; i < 10; ++i) {
    strip[i].colour[0] = (GLubyte)(25 * i);
    strip[i].colour[1] = 200;
    strip[i].colour[2] = (GLubyte)(255 - 25 * i);
    strip[i].colour[3] = (GLubyte)(60 + 15 * i);
    strip[i].position[0] = -2.0f + 0.5f * (float)(i / 2);
    strip[i].position[1] = (i % 2) ? 0.4f : -0.4f;
  }
  for (i = 0; i < 16; ++i) {
    spaced[i][0] = (i % 2) ? 100.0f : -1.8f + 0.25f * (float)(i / 2);
    spaced[i][1] = (i % 2) ? 100.0f : 0.5f * (float)sin(i);
  }
  for (i = 0; i < 16; ++i) {
    texels[i / 4][i % 4][0] = (GLubyte)((i % 3) * 120);
    texels[i / 4][i % 4][1] = (GLubyte)(((i / 4) % 2) * 200 + 40);
    texels[i / 4][i % 4][2] = (GLubyte)((i % 2) * 220);
  }

  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.0, 4.0, -3.0, 3.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);

  glPushMatrix();
  glTranslatef(-2.6f, 1.6f, 0.0f);
  glInterleavedArrays(GL_C3F_V3F, 0, hexagon);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 8);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.0f, 1.6f, 0.0f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glInterleavedArrays(GL_N3F_V3F, 0, pyramid);
  glDrawArrays(GL_TRIANGLES, 0, 9);
  glDisable(GL_LIGHTING);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.6f, 1.6f, 0.0f);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glInterleavedArrays(GL_T2F_V3F, 0, texturedQuad);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, quadIndices);
  glDisable(GL_TEXTURE_2D);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-0.5f, -0.6f, 0.5f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glInterleavedArrays(GL_C4UB_V2F, sizeof strip[0], strip);
  glDrawArrays(GL_QUAD_STRIP, 0, 10);
  glDisable(GL_BLEND);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.6f, -0.6f, 0.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glInterleavedArrays(GL_T2F_C4F_N3F_V3F, 0, everything);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-1.0f, -2.2f, 0.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glLineWidth(2.0f);
  glInterleavedArrays(GL_V2F, 2 * 2 * sizeof(GLfloat), spaced);
  glDrawArrays(GL_LINE_STRIP, 0, 8);
  glLineWidth(1.0f);
  glPopMatrix();

  glDisableClientState(GL_VERTEX_ARRAY);
  glDeleteTextures(1, &texture);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
