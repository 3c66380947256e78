/* Texturing tricks of the classic examples. Left: contour stripes on a lit teapot from a 1D
 * texture (glTexImage1D, 32 texels, one dark stripe) placed by glTexGen GL_OBJECT_LINEAR on s
 * along a tilted plane, GL_MODULATE. Middle: a sphere-mapped (GL_SPHERE_MAP) torus with a
 * generated environment picture. Right: render to texture: a small scene is drawn into the corner
 * of the colour buffer, copied into a texture with glCopyTexImage2D, the corner cleared again,
 * and the texture shown on a spinning quad in perspective, then updated in part with
 * glCopyTexSubImage2D. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 200 };

static GLubyte stripes[32][3];
static GLubyte environment[64][64][3];

static void makeImages(void)
{
  int i, j;
  for (i = 0; i < 32; ++i) {
    const int dark = i < 5;
    stripes[i][0] = (GLubyte)(dark ? 40 : 255);
    stripes[i][1] = (GLubyte)(dark ? 40 : 220 - 3 * i);
    stripes[i][2] = (GLubyte)(dark ? 120 : 120);
  }
  for (i = 0; i < 64; ++i) {
    for (j = 0; j < 64; ++j) {
      const float dx = (float)j - 31.5f, dy = (float)i - 31.5f;
      const float r = sqrtf(dx * dx + dy * dy) / 32.0f;
      environment[i][j][0] = (GLubyte)(i < 32 ? 90 + 5 * (i % 8) : 40);
      environment[i][j][1] = (GLubyte)(i < 32 ? 150 : 100 + 60 * ((j / 8) % 2));
      environment[i][j][2] = (GLubyte)(r < 0.3f ? 255 : i < 32 ? 230 : 40);
    }
  }
}

static void smallScene(void)
{
  int i;
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(0.0f, 0.0f);
  for (i = 0; i <= 8; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 8.0;
    glColor3f((float)(i % 2), 0.4f, (float)((i + 1) % 2));
    glVertex2f(0.9f * (float)cos(a), 0.9f * (float)sin(a));
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 2.0f, 0.0f};
  static const GLfloat plane[4] = {1.0f, 1.0f, 0.0f, 0.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLuint textures[3];

  makeImages();
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glGenTextures(3, textures);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* Render to texture first: the small scene into the 64 x 64 corner, copied, cleared. */
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  smallScene();
  glBindTexture(GL_TEXTURE_2D, textures[2]);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 64, 64, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  /* Overwrite part of it: a yellow bar copied from a cleared strip. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 64, 10);
  glClearColor(1.0f, 0.9f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 27, 0, 0, 64, 10);
  glScissor(0, 0, 64, 64);
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);

  glBindTexture(GL_TEXTURE_1D, textures[0]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, environment);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHT0);
  glTranslatef(0.0f, 0.0f, -4.0f);

  /* Left: contour teapot. */
  glViewport(0, 0, 160, 200);
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glPushMatrix();
  glScalef(1.0f, 1.2f, 1.0f);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glScalef(2.5f, 1.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glutSolidTeapot(0.9);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  glDisable(GL_TEXTURE_1D);
  glDisable(GL_TEXTURE_GEN_S);

  /* Middle: sphere map. */
  glViewport(160, 0, 160, 200);
  glDisable(GL_LIGHTING);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPushMatrix();
  glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.35, 0.9, 24, 36);
  glPopMatrix();
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);

  /* Right: the rendered texture on a turned quad. */
  glViewport(320, 0, 160, 200);
  glBindTexture(GL_TEXTURE_2D, textures[2]);
  glPushMatrix();
  glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(-20.0f, 1.0f, 0.0f, 0.0f);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f); glVertex2f(-1.0f, -1.0f);
  glTexCoord2f(1.0f, 0.0f); glVertex2f(1.0f, -1.0f);
  glTexCoord2f(1.0f, 1.0f); glVertex2f(1.0f, 1.0f);
  glTexCoord2f(0.0f, 1.0f); glVertex2f(-1.0f, 1.0f);
  glEnd();
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(3, textures);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
