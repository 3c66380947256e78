/* Mipmap level selection made visible (spec 3.8.8 to 3.8.10): each level of the texture has its
 * own colour (level 0 red, 1 orange, 2 yellow, 3 green, 4 cyan, 5 blue, 6 magenta), so the
 * bands on a receding floor show lambda and the level choice.
 *
 *   LINEAR_MIPMAP_LINEAR            NEAREST_MIPMAP_NEAREST          BASE_LEVEL 2, MAX_LEVEL 4
 *   MIN_LOD 1.5, MAX_LOD 3          GENERATE_MIPMAP of a 1-texel    an incomplete texture (level 3
 *                                   checkerboard (greys), patched   missing): texturing is off, the
 *                                   with glTexSubImage2D            fragment colour shows */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { PANEL_W = 200, PANEL_H = 150, COLUMNS = 3, ROWS = 2, LEVELS = 7 };

static const GLubyte levelColors[LEVELS][3] = {{230, 40, 40},  {240, 140, 30}, {240, 230, 40},
                                               {60, 200, 60},  {40, 210, 220}, {50, 80, 230},
                                               {200, 60, 210}};

static void solidLevel(int level, int size, const GLubyte color[3])
{
  static GLubyte texels[64 * 64][3];
  for (int k = 0; k < size * size; ++k) {
    texels[k][0] = color[0];
    texels[k][1] = color[1];
    texels[k][2] = color[2];
  }
  glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
}

static GLuint coloredLevels(int skipLevel)
{
  GLuint name;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  for (int level = 0; level < LEVELS; ++level)
    if (level != skipLevel) solidLevel(level, 64 >> level, levelColors[level]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  return name;
}

static GLuint generatedLevels(void)
{
  static GLubyte checks[64][64];
  static GLubyte patch[16][16];
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) checks[j][i] = (GLubyte)((i + j) % 2 ? 255 : 0);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) patch[j][i] = 255;
  GLuint name;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 64, 64, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, checks);
  /* Changing the base level regenerates the levels below it: a white square appears in all. */
  glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 16, 16, GL_LUMINANCE, GL_UNSIGNED_BYTE, patch);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  return name;
}

static void floorPanel(int index)
{
  glViewport((index % COLUMNS) * PANEL_W, (ROWS - 1 - index / COLUMNS) * PANEL_H, PANEL_W, PANEL_H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)PANEL_W / PANEL_H, 0.5, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(10.0f, 1.0f, 0.0f, 0.0f);
  glColor3f(1.0f, 0.55f, 0.1f);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(-3.0f, -1.0f, -1.0f);
  glTexCoord2f(3.0f, 0.0f);
  glVertex3f(3.0f, -1.0f, -1.0f);
  glTexCoord2f(3.0f, 40.0f);
  glVertex3f(3.0f, -1.0f, -41.0f);
  glTexCoord2f(0.0f, 40.0f);
  glVertex3f(-3.0f, -1.0f, -41.0f);
  glEnd();
}

static void draw(void)
{
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  const GLuint levels = coloredLevels(-1);
  floorPanel(0);

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  floorPanel(1);

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
  floorPanel(2);

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.0f);
  floorPanel(3);
  (void)levels;

  generatedLevels();
  floorPanel(4);

  coloredLevels(3);
  floorPanel(5);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * PANEL_W, ROWS * PANEL_H, draw);
}
