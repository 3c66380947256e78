/* The exam question on texture coordinates (study guide, section 4.1, item 3): a brick texture
 * on the rectangular wall (-1, 0, 0) .. (3, 2, 0); make every brick four times narrower.
 *
 * Top: the texture once across the wall, s and t from 0 to 1.
 * Bottom: the answer. The wall keeps its shape and the texture repeats (GL_REPEAT), so dividing
 * the width of each brick by 4 means s must run four times as far across the wall, 0 to 4, while
 * t stays 0 to 1:
 *   glTexCoord2f(0.0, 0.0); glVertex3f(-1.0, 0.0, 0.0);
 *   glTexCoord2f(4.0, 0.0); glVertex3f( 3.0, 0.0, 0.0);
 *   glTexCoord2f(4.0, 1.0); glVertex3f( 3.0, 2.0, 0.0);
 *   glTexCoord2f(0.0, 1.0); glVertex3f(-1.0, 2.0, 0.0);
 * Mipmaps keep the narrower bricks from aliasing. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 420, HEIGHT = 440, TEX_W = 128, TEX_H = 64 };

/* Two courses of bricks, the upper one shifted by half a brick, with mortar lines. */
static void makeBrickTexture(void)
{
  static GLubyte texels[TEX_H][TEX_W][3];
  for (int j = 0; j < TEX_H; ++j) {
    for (int i = 0; i < TEX_W; ++i) {
      const int course = j / 32;
      const int x = (i + course * 32) % 64, y = j % 32;
      const int mortar = y < 3 || x < 3;
      /* A little variation between the four bricks of the tile (a brick cut by the tile's edge
       * continues in the next repeat, so it keeps one colour). */
      const int brick = ((i + course * 32) % TEX_W) / 64 + 2 * course;
      GLubyte *t = texels[j][i];
      if (mortar) {
        t[0] = 200; t[1] = 195; t[2] = 185;
      } else {
        t[0] = (GLubyte)(140 + 20 * brick);
        t[1] = (GLubyte)(50 + 8 * ((brick + 1) % 3));
        t[2] = 40;
      }
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX_W, TEX_H, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

static void wall(float sMax)
{
  glBegin(GL_POLYGON);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(-1.0f, 0.0f, 0.0f);
  glTexCoord2f(sMax, 0.0f);
  glVertex3f(3.0f, 0.0f, 0.0f);
  glTexCoord2f(sMax, 1.0f);
  glVertex3f(3.0f, 2.0f, 0.0f);
  glTexCoord2f(0.0f, 1.0f);
  glVertex3f(-1.0f, 2.0f, 0.0f);
  glEnd();
}

static void draw(void)
{
  glClearColor(0.25f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  makeBrickTexture();
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.1, 3.1, -0.1, 2.1, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glViewport(0, HEIGHT / 2, WIDTH, HEIGHT / 2);
  wall(1.0f);
  glViewport(0, 0, WIDTH, HEIGHT / 2);
  wall(4.0f);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
