/* The checkerboard texture program: a 64 x 64 RGBA checkerboard made in memory (8 x 8 texel
 * squares, by the exclusive-or of the texel's column and row bits), loaded with glTexImage2D
 * under GL_UNPACK_ALIGNMENT 1, GL_REPEAT wrapping and GL_NEAREST filters, and the environment
 * GL_DECAL. One quad faces the viewer, the other is turned away at 45 degrees in perspective,
 * with texture coordinates 0..1 on the first and 0..3 (repeated) on the second. A third,
 * smaller quad below uses GL_LINEAR filters and GL_MODULATE with a glColor. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240, CHECKER = 64 };

static GLubyte checker[CHECKER][CHECKER][4];

static void makeChecker(void)
{
  int i, j;
  for (i = 0; i < CHECKER; ++i) {
    for (j = 0; j < CHECKER; ++j) {
      const GLubyte c = (((i & 0x8) == 0) ^ ((j & 0x8) == 0)) ? 255 : 0;
      checker[i][j][0] = c;
      checker[i][j][1] = c;
      checker[i][j][2] = c;
      checker[i][j][3] = 255;
    }
  }
}

static void draw(void)
{
  GLuint texture;
  makeChecker();

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_FLAT);
  glEnable(GL_DEPTH_TEST);

  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, CHECKER, CHECKER, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               checker);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (GLfloat)WIDTH / (GLfloat)HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.6f);

  glEnable(GL_TEXTURE_2D);
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-2.0f, -0.6f, 0.0f);
  glTexCoord2f(0.0f, 1.0f); glVertex3f(-2.0f, 1.4f, 0.0f);
  glTexCoord2f(1.0f, 1.0f); glVertex3f(0.0f, 1.4f, 0.0f);
  glTexCoord2f(1.0f, 0.0f); glVertex3f(0.0f, -0.6f, 0.0f);

  glTexCoord2f(0.0f, 0.0f); glVertex3f(1.0f, -0.6f, 0.0f);
  glTexCoord2f(0.0f, 3.0f); glVertex3f(1.0f, 1.4f, 0.0f);
  glTexCoord2f(3.0f, 3.0f); glVertex3f(2.41421f, 1.4f, -1.41421f);
  glTexCoord2f(3.0f, 0.0f); glVertex3f(2.41421f, -0.6f, -1.41421f);
  glEnd();

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1.0f, 0.6f, 0.2f);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-1.5f, -1.6f, 0.0f);
  glTexCoord2f(2.0f, 0.0f); glVertex3f(0.5f, -1.6f, 0.0f);
  glTexCoord2f(2.0f, 0.5f); glVertex3f(0.5f, -0.8f, 0.0f);
  glTexCoord2f(0.0f, 0.5f); glVertex3f(-1.5f, -0.8f, 0.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &texture);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
