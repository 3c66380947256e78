/* GLU quadrics' texture coordinates with GLU_INSIDE orientation (GLU 1.3, section 6.3: the
 * orientation reverses the normals and the faces' winding; the texture coordinates GLU gives each
 * vertex must stay those of Mesa's libGLU). Top row GLU_OUTSIDE, bottom row GLU_INSIDE; columns
 * gluSphere, gluCylinder (a cone frustum), gluDisk with a hole and gluPartialDisk, all unlit,
 * with a lettered checkerboard in GL_REPLACE so that a mirrored or shifted coordinate shows.
 * Back faces are culled, so each inside-oriented shape shows only the faces turned towards the
 * viewer by the reversed orientation (the far half of the sphere and cylinder). The disks sit a
 * fraction of a pixel off the pixel grid, so that no texel boundary passes through pixel centres,
 * where float rounding would pick either texel. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 200, TEXTURE = 32 };

static void texture(void)
{
  static GLubyte texels[TEXTURE][TEXTURE][3];
  for (int t = 0; t < TEXTURE; ++t)
    for (int s = 0; s < TEXTURE; ++s) {
      const int dark = ((s / 4) + (t / 4)) % 2;
      texels[t][s][0] = (GLubyte)(dark ? 40 : 60 + 6 * s);
      texels[t][s][1] = (GLubyte)(dark ? 40 : 60 + 6 * t);
      texels[t][s][2] = (GLubyte)(dark ? 90 : 120);
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEXTURE, TEXTURE, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
}

static void draw(void)
{
  GLUquadricObj *quadric = gluNewQuadric();
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  texture();
  gluQuadricTexture(quadric, GL_TRUE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.0, 4.0, -2.0, 2.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  for (int row = 0; row < 2; ++row) {
    gluQuadricOrientation(quadric, row == 0 ? GLU_OUTSIDE : GLU_INSIDE);
    const float y = row == 0 ? 1.0f : -1.0f;
    glLoadIdentity();
    glTranslatef(-3.0f, y, 0.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    gluSphere(quadric, 0.9, 12, 8);
    glLoadIdentity();
    glTranslatef(-1.0f, y - 0.6f, 0.0f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(quadric, 0.8, 0.5, 1.3, 10, 3);
    glLoadIdentity();
    glTranslatef(1.013f, y + 0.007f, 0.0f);
    glRotatef(row == 0 ? 0.0f : 180.0f, 0.0f, 1.0f, 0.0f);
    gluDisk(quadric, 0.3, 0.9, 14, 3);
    glLoadIdentity();
    glTranslatef(3.013f, y + 0.007f, 0.0f);
    glRotatef(row == 0 ? 0.0f : 180.0f, 0.0f, 1.0f, 0.0f);
    gluPartialDisk(quadric, 0.2, 0.9, 10, 2, 20.0, 250.0);
  }
  gluDeleteQuadric(quadric);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
