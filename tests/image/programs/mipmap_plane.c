/* Mipmaps, the two ways programs make them. Left: each level loaded by hand with glTexImage2D in
 * its own solid colour (32 x 32 yellow, 16 magenta, 8 red, 4 green, 2 blue, 1 white), so that the
 * level chosen shows as a colour band on a long plane receding from the viewer, under
 * GL_NEAREST_MIPMAP_NEAREST. Right: a brick-like pattern through gluBuild2DMipmaps from a
 * 64 x 48 image (GLU rescales it to a power of two first) with GL_LINEAR_MIPMAP_LINEAR, on
 * a plane tilted the other way. The view looks down a little so the planes fill the lower half. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void solidLevel(int level, int size, GLubyte r, GLubyte g, GLubyte b)
{
  static GLubyte image[32 * 32 * 4];
  int i;
  for (i = 0; i < size * size; ++i) {
    image[4 * i + 0] = r;
    image[4 * i + 1] = g;
    image[4 * i + 2] = b;
    image[4 * i + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
}

static void bricks(GLubyte image[48][64][3])
{
  int i, j;
  for (i = 0; i < 48; ++i) {
    for (j = 0; j < 64; ++j) {
      const int row = i / 8;
      const int shifted = (j + (row % 2) * 8) % 16;
      const int mortar = (i % 8) == 0 || shifted == 0;
      image[i][j][0] = mortar ? 200 : (GLubyte)(150 + (i * 7 + j * 3) % 40);
      image[i][j][1] = mortar ? 200 : 60;
      image[i][j][2] = mortar ? 190 : 40;
    }
  }
}

static void plane(float x0, float x1, float repeats)
{
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(x0, -1.0f, -1.0f);
  glTexCoord2f(repeats, 0.0f); glVertex3f(x1, -1.0f, -1.0f);
  glTexCoord2f(repeats, 40.0f * repeats); glVertex3f(x1, -1.0f, -60.0f);
  glTexCoord2f(0.0f, 40.0f * repeats); glVertex3f(x0, -1.0f, -60.0f);
  glEnd();
}

static void draw(void)
{
  static GLubyte brickImage[48][64][3];
  GLuint textures[2];

  glClearColor(0.3f, 0.3f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_FLAT);

  glGenTextures(2, textures);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  solidLevel(0, 32, 255, 255, 0);
  solidLevel(1, 16, 255, 0, 255);
  solidLevel(2, 8, 255, 0, 0);
  solidLevel(3, 4, 0, 255, 0);
  solidLevel(4, 2, 0, 0, 255);
  solidLevel(5, 1, 255, 255, 255);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);

  bricks(brickImage);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 64, 48, GL_RGB, GL_UNSIGNED_BYTE, brickImage);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (double)WIDTH / HEIGHT, 1.0, 80.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(8.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, -0.5f, -2.0f);

  glEnable(GL_TEXTURE_2D);
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  plane(-4.0f, -0.2f, 1.0f);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glPushMatrix();
  glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
  plane(0.2f, 4.5f, 2.0f);
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(2, textures);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
