/* Mipmaps of textures that are not square (OpenGL 1.5 sections 3.8.8 to 3.8.10): each level has
 * its own colour (0 red, 1 orange, 2 yellow, 3 green, 4 cyan, 5 blue, 6 magenta) and a dark grid
 * line on its first texel row and column, so the bands on a receding floor show which level each
 * pixel read. Four floors side by side:
 *
 *   1. a 1D texture of 64 texels (7 levels) with s running across the floor and repeated 8 times:
 *      rho takes only du/dx and du/dy, so the level follows the floor's width in texels;
 *   2. the same 1D texture with s running along the floor, into the distance;
 *   3. a 2D texture of 64 x 8 texels: its levels go on after the height reaches 1 (32 x 4 ... 8 x
 *      1, 4 x 1, 2 x 1, 1 x 1), and the long side decides rho, the short side clamps at 1;
 *   4. a 2D texture of 8 x 64 turned the other way, filtered with GL_LINEAR within a level
 *      (GL_LINEAR magnification, GL_LINEAR_MIPMAP_NEAREST), down to its 1 x 2 and 1 x 1 levels.
 * The others use GL_NEAREST_MIPMAP_NEAREST; all use GL_REPEAT and GL_REPLACE. (LINEAR
 * magnification with a NEAREST_MIPMAP minification filter, where spec 3.8.9 moves the switch
 * between magnification and minification to lambda = 1/2 and llvmpipe does not, is
 * texture_minification's.) */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 240, LEVELS = 7 };

static const GLubyte levelColours[LEVELS][3] = {{230, 40, 40},  {240, 140, 30}, {235, 225, 40},
                                                {60, 200, 60},  {50, 210, 220}, {50, 80, 230},
                                                {220, 60, 220}};

/* Fills a w x h level image with the level's colour and a dark first row and column. */
static void fillLevel(GLubyte *texels, int w, int h, int level)
{
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      GLubyte *t = texels + 3 * (j * w + i);
      const int line = (i == 0 && w > 1) || (j == 0 && h > 1);
      for (int c = 0; c < 3; ++c)
        t[c] = (GLubyte)(line ? levelColours[level][c] / 3 : levelColours[level][c]);
    }
  }
}

static void loadLevels(GLenum target, int width, int height)
{
  static GLubyte texels[64 * 64 * 3];
  for (int level = 0; level < LEVELS; ++level) {
    const int w = width >> level > 0 ? width >> level : 1;
    const int h = height >> level > 0 ? height >> level : 1;
    fillLevel(texels, w, h, level);
    if (target == GL_TEXTURE_1D)
      glTexImage1D(GL_TEXTURE_1D, level, GL_RGB, w, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    else
      glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, w, h, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

/* A floor from z = -1 to z = -40 under the current viewport; (s, t) at its four corners. */
static void floorQuad(const GLfloat st[4][2])
{
  glBegin(GL_QUADS);
  glTexCoord2fv(st[0]);
  glVertex3f(-2.0f, 0.0f, -1.0f);
  glTexCoord2fv(st[1]);
  glVertex3f(2.0f, 0.0f, -1.0f);
  glTexCoord2fv(st[2]);
  glVertex3f(2.0f, 0.0f, -40.0f);
  glTexCoord2fv(st[3]);
  glVertex3f(-2.0f, 0.0f, -40.0f);
  glEnd();
}

static void viewport(int panel)
{
  glViewport(panel * (WIDTH / 4) + 2, 2, WIDTH / 4 - 4, HEIGHT - 4);
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (WIDTH / 4 - 4) / (double)(HEIGHT - 4), 0.5, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.0, 0.0, 0.0, 0.2, -10.0, 0.0, 1.0, 0.0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  GLuint textures[3];
  glGenTextures(3, textures);

  /* 1 and 2: the 1D texture. */
  glBindTexture(GL_TEXTURE_1D, textures[0]);
  loadLevels(GL_TEXTURE_1D, 64, 1);
  glEnable(GL_TEXTURE_1D);
  viewport(0);
  const GLfloat across[4][2] = {{0.0f, 0.0f}, {8.0f, 0.0f}, {8.0f, 0.0f}, {0.0f, 0.0f}};
  floorQuad(across);
  viewport(1);
  const GLfloat along[4][2] = {{0.0f, 0.0f}, {0.0f, 0.0f}, {6.0f, 0.0f}, {6.0f, 0.0f}};
  floorQuad(along);
  glDisable(GL_TEXTURE_1D);

  /* 3: 64 x 8, s across (twice), t along (12 times). */
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  loadLevels(GL_TEXTURE_2D, 64, 8);
  glEnable(GL_TEXTURE_2D);
  viewport(2);
  const GLfloat wide[4][2] = {{0.0f, 0.0f}, {2.0f, 0.0f}, {2.0f, 12.0f}, {0.0f, 12.0f}};
  floorQuad(wide);

  /* 4: 8 x 64, s across (8 times), t along (3 times), LINEAR within each level. */
  glBindTexture(GL_TEXTURE_2D, textures[2]);
  loadLevels(GL_TEXTURE_2D, 8, 64);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  viewport(3);
  const GLfloat tall[4][2] = {{0.0f, 0.0f}, {8.0f, 0.0f}, {8.0f, 3.0f}, {0.0f, 3.0f}};
  floorQuad(tall);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(3, textures);
  glViewport(0, 0, WIDTH, HEIGHT);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
