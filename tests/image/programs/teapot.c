/* glutSolidTeapot and glutWireTeapot: the Utah teapot, lit and textured, with a wire teapot
 * beside it. The Mesa reference is freeglut 3's teapot (see reference_images/README.md); glass
 * tessellates the teapot as freeglut does (8 x 8 points per patch as triangles for the solid one,
 * 10 x 10 as line strips for the wire one), so both draw the same triangles.
 *
 * The solid teapot's texture coordinates run over each patch (s along its first index, t along
 * its second), so the checkerboard repeats on every patch. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, TEXTURE = 16 };

static void checkerTexture(void)
{
  static GLubyte texels[TEXTURE][TEXTURE][3];
  for (int y = 0; y < TEXTURE; ++y)
    for (int x = 0; x < TEXTURE; ++x) {
      const int dark = ((x / 4) + (y / 4)) % 2;
      texels[y][x][0] = dark ? 150 : 255;
      texels[y][x][1] = dark ? 60 : 240;
      texels[y][x][2] = dark ? 40 : 220;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEXTURE, TEXTURE, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {-2.0f, 3.0f, 4.0f, 0.0f};
  static const GLfloat white[4] = {0.9f, 0.9f, 0.9f, 1.0f};
  static const GLfloat specular[4] = {0.4f, 0.4f, 0.4f, 1.0f};

  glClearColor(0.12f, 0.14f, 0.18f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(35.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  gluLookAt(0.0, 2.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  checkerTexture();
  glEnable(GL_TEXTURE_2D);
  glPushMatrix();
  glTranslatef(-0.6f, 0.0f, 0.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
  glutSolidTeapot(1.0);
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);

  glDisable(GL_LIGHTING);
  glColor3f(0.5f, 0.85f, 0.6f);
  glPushMatrix();
  glTranslatef(1.45f, 0.55f, -0.5f);
  glRotatef(40.0f, 0.0f, 1.0f, 0.0f);
  glutWireTeapot(0.45);
  glPopMatrix();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
