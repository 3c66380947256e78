/* glColorMaterial in each of its modes, the way programs use it: a torus per mode, coloured
 * with glColor while GL_COLOR_MATERIAL tracks the current colour into GL_AMBIENT, GL_DIFFUSE,
 * GL_SPECULAR, GL_EMISSION and GL_AMBIENT_AND_DIFFUSE in turn (the other material terms keep
 * what glMaterial set). The last column draws a smooth-shaded quad strip whose vertex colours
 * feed the diffuse reflectance per vertex, and a fan whose colours feed the material of a
 * two-sided lit disc seen from behind (GL_FRONT_AND_BACK, so the back material tracks them).
 * The mode is changed while GL_COLOR_MATERIAL is disabled, as the specification recommends, and
 * a glColor follows each glEnable.
 *
 * Not GL_BACK alone: Mesa 22.3's fixed-function vertex program lights back faces with a wrong
 * material (white or cyan) when the colour material face is GL_BACK and colours come per vertex,
 * while GL_FRONT_AND_BACK is right; glass follows the specification in both. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 200 };

static void torusAt(float x, GLenum mode, float r, float g, float b)
{
  glDisable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, mode);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(r, g, b);
  glPushMatrix();
  glTranslatef(x, 0.9f, 0.0f);
  glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.25, 0.6, 16, 32);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  static const GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat lightPosition[4] = {-2.0f, 3.0f, 4.0f, 1.0f};
  int i;

  glClearColor(0.25f, 0.25f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.25, 0.25, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -8.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, grey);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, grey);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);

  torusAt(-4.0f, GL_AMBIENT, 0.9f, 0.1f, 0.1f);
  torusAt(-2.0f, GL_DIFFUSE, 0.1f, 0.9f, 0.1f);
  torusAt(0.0f, GL_SPECULAR, 0.2f, 0.3f, 1.0f);
  torusAt(2.0f, GL_EMISSION, 0.3f, 0.1f, 0.3f);
  glDisable(GL_COLOR_MATERIAL);
  glMaterialfv(GL_FRONT, GL_EMISSION, black);
  torusAt(4.0f, GL_AMBIENT_AND_DIFFUSE, 0.9f, 0.6f, 0.1f);

  /* Per-vertex diffuse colours on a strip. */
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glBegin(GL_QUAD_STRIP);
  glNormal3f(0.0f, 0.0f, 1.0f);
  for (i = 0; i <= 8; ++i) {
    const float x = -4.6f + 0.5f * (float)i;
    glColor3f((float)i / 8.0f, 0.2f, 1.0f - (float)i / 8.0f);
    glVertex3f(x, -0.3f, 0.0f);
    glColor3f(0.2f, (float)i / 8.0f, 0.5f);
    glVertex3f(x, -1.3f, 0.0f);
  }
  glEnd();

  /* Two-sided lighting, back material tracked, the disc seen from behind (clockwise fan). */
  glDisable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex3f(2.5f, -0.8f, 0.0f);
  for (i = 0; i <= 12; ++i) {
    const double angle = -2.0 * 3.14159265358979 * i / 12.0;
    glColor3f(0.5f + 0.5f * (float)cos(angle), 0.5f + 0.5f * (float)sin(angle), 0.3f);
    glVertex3f(2.5f + 1.6f * (float)cos(angle), -0.8f + 0.55f * (float)sin(angle), 0.0f);
  }
  glEnd();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
