/* Fog over a textured, lit scene, as a walk-through homework draws it: a grass-like floor with a
 * mipmapped texture (gluBuild2DMipmaps, trilinear) repeated 20 times, receding to the horizon
 * under GL_LINEAR fog whose colour is the clear colour; textured crates (GL_MODULATE with
 * lighting) along a path; and unlit fence posts drawn as wide GL_LINES that take the fog too.
 * The texture coordinates are offset so that no pixel centre falls on a texel boundary of the
 * magnified crates. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 260 };

static GLubyte grass[64][64][3];
static GLubyte planks[32][32][3];

static void makeTextures(void)
{
  int i, j;
  for (i = 0; i < 64; ++i) {
    for (j = 0; j < 64; ++j) {
      const int n = (i * 37 + j * 91 + (i * j) % 13) % 41;
      grass[i][j][0] = (GLubyte)(40 + n);
      grass[i][j][1] = (GLubyte)(110 + 2 * n);
      grass[i][j][2] = (GLubyte)(30 + n / 2);
    }
  }
  for (i = 0; i < 32; ++i) {
    for (j = 0; j < 32; ++j) {
      const int seam = (i % 8 == 0) || j == 0 || j == 31;
      planks[i][j][0] = (GLubyte)(seam ? 70 : 170 + (j * 5) % 30);
      planks[i][j][1] = (GLubyte)(seam ? 45 : 120 + (j * 3) % 20);
      planks[i][j][2] = (GLubyte)(seam ? 20 : 60);
    }
  }
}

static void crate(float x, float z, float size)
{
  static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  static const float c[6][4][3] = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
      {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
      {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
      {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
      {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
      {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}};
  static const float t[4][2] = {{0.013f, 0.017f}, {1.013f, 0.017f}, {1.013f, 1.017f}, {0.013f, 1.017f}};
  int f, k;
  glPushMatrix();
  glTranslatef(x, size, z);
  glScalef(size, size, size);
  glBegin(GL_QUADS);
  for (f = 0; f < 6; ++f) {
    glNormal3fv(n[f]);
    for (k = 0; k < 4; ++k) {
      glTexCoord2fv(t[k]);
      glVertex3fv(c[f][k]);
    }
  }
  glEnd();
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat fogColour[4] = {0.7f, 0.75f, 0.8f, 1.0f};
  static const GLfloat sun[4] = {0.4f, 1.0f, 0.6f, 0.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLuint textures[2];
  int i;

  makeTextures();
  glClearColor(fogColour[0], fogColour[1], fogColour[2], fogColour[3]);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glGenTextures(2, textures);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 64, 64, GL_RGB, GL_UNSIGNED_BYTE, grass);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, planks);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(55.0, (double)WIDTH / HEIGHT, 0.3, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.6, 6.0, 0.0, 1.0, -10.0, 0.0, 1.0, 0.0);
  glLightfv(GL_LIGHT0, GL_POSITION, sun);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glEnable(GL_LIGHT0);

  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogfv(GL_FOG_COLOR, fogColour);
  glFogf(GL_FOG_START, 4.0f);
  glFogf(GL_FOG_END, 40.0f);
  glEnable(GL_FOG);

  /* Floor, unlit, texture replaced. */
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-30.0f, 0.0f, 8.0f);
  glTexCoord2f(20.0f, 0.0f); glVertex3f(30.0f, 0.0f, 8.0f);
  glTexCoord2f(20.0f, 20.0f); glVertex3f(30.0f, 0.0f, -52.0f);
  glTexCoord2f(0.0f, 20.0f); glVertex3f(-30.0f, 0.0f, -52.0f);
  glEnd();

  /* Crates, lit and modulated. */
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  for (i = 0; i < 6; ++i) crate(-2.0f + 1.3f * (float)(i % 2) * 3.0f, 2.0f - 6.0f * (float)i, 0.5f + 0.1f * (float)i);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);

  /* Fence posts. */
  glLineWidth(3.0f);
  glColor3f(0.35f, 0.25f, 0.15f);
  glBegin(GL_LINES);
  for (i = 0; i < 12; ++i) {
    glVertex3f(3.5f, 0.0f, 4.0f - 4.0f * (float)i);
    glVertex3f(3.5f, 1.2f, 4.0f - 4.0f * (float)i);
  }
  glEnd();
  glLineWidth(1.0f);
  glDisable(GL_FOG);
  glDeleteTextures(2, textures);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
