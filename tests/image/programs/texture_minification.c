/* A checkerboard floor receding to the horizon, once per minification filter (spec 3.8.8):
 *
 *   NEAREST                  LINEAR                   NEAREST_MIPMAP_NEAREST
 *   LINEAR_MIPMAP_NEAREST    NEAREST_MIPMAP_LINEAR    LINEAR_MIPMAP_LINEAR
 *
 * Near the viewer the texture is magnified (GL_LINEAR); towards the horizon one pixel covers
 * more and more texels, so the level of detail lambda grows and the mipmapped filters move down
 * the pyramid that gluBuild2DMipmaps built. Without mipmaps the far checks alias into moire. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { PANEL_W = 200, PANEL_H = 150, COLUMNS = 3, ROWS = 2, TEX = 64, CHECK = 8 };

static const GLenum filters[6] = {GL_NEAREST,
                                  GL_LINEAR,
                                  GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST,
                                  GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR};

static void makeTexture(void)
{
  static GLubyte texels[TEX][TEX][3];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      const int light = ((i / CHECK) + (j / CHECK)) % 2;
      texels[j][i][0] = light ? 240 : 30;
      texels[j][i][1] = light ? 230 : 60;
      texels[j][i][2] = light ? 200 : 140;
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX, TEX, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

static void floorQuad(void)
{
  /* 8 units wide and 60 deep, one texture repeat every 2 units: s across, t into the distance. */
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(-4.0f, -1.0f, -1.0f);
  glTexCoord2f(4.0f, 0.0f);
  glVertex3f(4.0f, -1.0f, -1.0f);
  glTexCoord2f(4.0f, 30.0f);
  glVertex3f(4.0f, -1.0f, -61.0f);
  glTexCoord2f(0.0f, 30.0f);
  glVertex3f(-4.0f, -1.0f, -61.0f);
  glEnd();
}

static void draw(void)
{
  glClearColor(0.55f, 0.7f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  makeTexture();
  glEnable(GL_TEXTURE_2D);
  for (int k = 0; k < 6; ++k) {
    glViewport((k % COLUMNS) * PANEL_W, (ROWS - 1 - k / COLUMNS) * PANEL_H, PANEL_W, PANEL_H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)PANEL_W / PANEL_H, 0.5, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(8.0f, 1.0f, 0.0f, 0.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filters[k]);
    floorQuad();
  }
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * PANEL_W, ROWS * PANEL_H, draw);
}
