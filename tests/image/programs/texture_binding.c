/* Several texture objects, switched with glBindTexture between primitives: a checkerboard with
 * NEAREST filters and REPEAT, a striped RGB texture (GL_RGB, unpack alignment 1, odd width 7 x 8
 * padded) with LINEAR filters and CLAMP, and a luminance-alpha ring texture blended over the
 * scene. Part of the checkerboard is replaced with glTexSubImage2D after it is bound. A lit cube
 * wears the checkerboard on three faces and the stripes on three (GL_MODULATE with the lit
 * colour); a quad shows the ring with alpha blending, and texture 0 (the default texture,
 * never loaded) is bound for a last quad, which is then drawn untextured. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static GLubyte checker[32][32][4];
static GLubyte patch[8][8][4];
static GLubyte stripes[8][7][3];
static GLubyte ring[32][32][2];

static void makeImages(void)
{
  int i, j;
  for (i = 0; i < 32; ++i) {
    for (j = 0; j < 32; ++j) {
      const int on = ((i / 4) + (j / 4)) % 2;
      const int di = i - 16, dj = j - 16;
      const int r2 = di * di + dj * dj;
      checker[i][j][0] = on ? 240 : 30;
      checker[i][j][1] = on ? 240 : 60;
      checker[i][j][2] = on ? 240 : 160;
      checker[i][j][3] = 255;
      ring[i][j][0] = (GLubyte)(128 + 4 * dj);
      ring[i][j][1] = (r2 > 64 && r2 < 196) ? 200 : 0;
    }
  }
  for (i = 0; i < 8; ++i) {
    for (j = 0; j < 8; ++j) {
      patch[i][j][0] = 255;
      patch[i][j][1] = (GLubyte)(i * 32);
      patch[i][j][2] = 0;
      patch[i][j][3] = 255;
    }
  }
  for (i = 0; i < 8; ++i) {
    for (j = 0; j < 7; ++j) {
      stripes[i][j][0] = (GLubyte)(j * 36);
      stripes[i][j][1] = (GLubyte)(255 - j * 36);
      stripes[i][j][2] = (i & 1) ? 200 : 50;
    }
  }
}

static void face(const float n[3], const float a[3], const float b[3], const float c[3],
                 const float d[3])
{
  glNormal3fv(n);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3fv(a);
  glTexCoord2f(1.0f, 0.0f); glVertex3fv(b);
  glTexCoord2f(1.0f, 1.0f); glVertex3fv(c);
  glTexCoord2f(0.0f, 1.0f); glVertex3fv(d);
  glEnd();
}

static void draw(void)
{
  static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const float nx[3] = {1, 0, 0}, ny[3] = {0, 1, 0}, nz[3] = {0, 0, 1};
  static const float mx[3] = {-1, 0, 0}, my[3] = {0, -1, 0}, mz[3] = {0, 0, -1};
  static const GLfloat lightPosition[4] = {2.0f, 3.0f, 4.0f, 0.0f};
  GLuint textures[3];

  makeImages();
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glGenTextures(3, textures);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 12, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, patch);

  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 7, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);

  glBindTexture(GL_TEXTURE_2D, textures[2]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 32, 32, 0, GL_LUMINANCE_ALPHA,
               GL_UNSIGNED_BYTE, ring);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(3.0, 2.5, 5.0, 0.3, 0.0, 0.0, 0.0, 1.0, 0.0);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  glBindTexture(GL_TEXTURE_2D, textures[0]);
  face(nz, v[4], v[5], v[6], v[7]);
  face(nx, v[5], v[1], v[2], v[6]);
  face(ny, v[7], v[6], v[2], v[3]);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  face(mz, v[1], v[0], v[3], v[2]);
  face(mx, v[0], v[4], v[7], v[3]);
  face(my, v[0], v[1], v[5], v[4]);

  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindTexture(GL_TEXTURE_2D, textures[2]);
  glColor3f(1.0f, 1.0f, 0.4f);
  glPushMatrix();
  glTranslatef(1.6f, 0.2f, 1.4f);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-0.8f, -0.8f, 0.0f);
  glTexCoord2f(1.0f, 0.0f); glVertex3f(0.8f, -0.8f, 0.0f);
  glTexCoord2f(1.0f, 1.0f); glVertex3f(0.8f, 0.8f, 0.0f);
  glTexCoord2f(0.0f, 1.0f); glVertex3f(-0.8f, 0.8f, 0.0f);
  glEnd();
  glPopMatrix();
  glDisable(GL_BLEND);

  glBindTexture(GL_TEXTURE_2D, 0);
  glColor3f(0.3f, 0.8f, 0.3f);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0.5f, 0.5f);
  glVertex3f(-2.5f, -1.5f, 0.0f);
  glVertex3f(-1.5f, -1.5f, 0.0f);
  glVertex3f(-2.0f, -0.5f, 0.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(3, textures);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
