/* Three-dimensional textures (OpenGL 1.2, sections 3.8.1 and 3.8.8): a 16 x 16 x 16 colour
 * volume (red along s, green along t, blue along r, with dark bands every fourth slice), sent in
 * two halves with glTexImage3D and glTexSubImage3D.
 *
 *   left:   six quads at r = 0.05 .. 0.95, GL_LINEAR (trilinear within the level: two slices
 *           mixed), the last one with r beyond 1 and GL_MIRRORED_REPEAT along r
 *   middle: a rotated cube in perspective textured by its object coordinates (OBJECT_LINEAR
 *           generation of s, t and r): solid texturing, the volume carved by the cube's faces
 *   right:  the same cube with GL_NEAREST and a texture matrix scaling r by 2 (GL_REPEAT)
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 200, N = 16 };

static void makeVolume(void)
{
  static GLubyte texels[N][N][N][3];
  for (int k = 0; k < N; ++k) {
    for (int j = 0; j < N; ++j) {
      for (int i = 0; i < N; ++i) {
        const int band = k % 4 == 0;
        texels[k][j][i][0] = (GLubyte)(band ? 40 : 30 + 14 * i);
        texels[k][j][i][1] = (GLubyte)(band ? 40 : 30 + 14 * j);
        texels[k][j][i][2] = (GLubyte)(band ? 40 : 30 + 14 * k);
      }
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, N, N, N, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, N, N, N / 2, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, N / 2, N, N, N / 2, GL_RGB, GL_UNSIGNED_BYTE,
                  texels[N / 2]);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void slices(void)
{
  glViewport(0, 0, CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 3.0, 0.0, 2.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int n = 0; n < 6; ++n) {
    const float x = (float)(n % 3), y = (float)(1 - n / 3);
    const float r = n == 5 ? 1.3f : 0.05f + 0.18f * n;
    if (n == 5) glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r);
    glVertex2f(x + 0.05f, y + 0.05f);
    glTexCoord3f(1.0f, 0.0f, r);
    glVertex2f(x + 0.95f, y + 0.05f);
    glTexCoord3f(1.0f, 1.0f, r);
    glVertex2f(x + 0.95f, y + 0.95f);
    glTexCoord3f(0.0f, 1.0f, r);
    glVertex2f(x + 0.05f, y + 0.95f);
    glEnd();
  }
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
}

static void cube(void)
{
  static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int faces[6][4] = {{1, 2, 6, 5}, {0, 4, 7, 3}, {3, 7, 6, 2},
                                  {0, 1, 5, 4}, {4, 5, 6, 7}, {0, 3, 2, 1}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) glVertex3fv(corners[faces[f][k]]);
  glEnd();
}

static void solidCube(int column)
{
  static const GLfloat planes[3][4] = {{0.5f, 0, 0, 0.5f}, {0, 0.5f, 0, 0.5f}, {0, 0, 0.5f, 0.5f}};
  glViewport(column * CELL, 0, CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.2f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(column == 1 ? -35.0f : 50.0f, 0.0f, 1.0f, 0.0f);
  for (int c = 0; c < 3; ++c) {
    glTexGeni(GL_S + c, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S + c, GL_OBJECT_PLANE, planes[c]);
  }
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  cube();
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
}

static void draw(void)
{
  GLuint volume;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glGenTextures(1, &volume);
  glBindTexture(GL_TEXTURE_3D, volume);
  makeVolume();
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  slices();
  solidCube(1);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glMatrixMode(GL_TEXTURE);
  glScalef(1.0f, 1.0f, 2.0f);
  solidCube(2);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 3 * CELL, CELL, draw);
}
