/* Fog (spec 3.10), one band per mode: GL_LINEAR (start 4, end 16), GL_EXP (density 0.15) and
 * GL_EXP2 (density 0.12), each a long lit floor strip and a row of spheres receding from the
 * eye into a blue-grey fog.
 *
 * The floor strips are single large quads running from near to far: the fog factor changes
 * along them non-linearly for EXP and EXP2, which shows whether it is computed per fragment (as
 * glass and Mesa's llvmpipe do) or interpolated from the vertices. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 300 };

static void band(GLUquadric *q, float x)
{
  static const GLfloat floorColor[4] = {0.6f, 0.55f, 0.45f, 1.0f};
  static const GLfloat sphereColor[4] = {0.9f, 0.3f, 0.2f, 1.0f};
  int i;
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floorColor);
  glNormal3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);
  glVertex3f(x - 0.8f, -1.0f, -3.0f);
  glVertex3f(x + 0.8f, -1.0f, -3.0f);
  glVertex3f(x + 0.8f, -1.0f, -30.0f);
  glVertex3f(x - 0.8f, -1.0f, -30.0f);
  glEnd();
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, sphereColor);
  for (i = 0; i < 6; ++i) {
    glPushMatrix();
    glTranslatef(x, -0.6f, -6.0f - 4.0f * (float)i);
    gluSphere(q, 0.4, 20, 10);
    glPopMatrix();
  }
}

static void draw(void)
{
  static const GLfloat fogColor[4] = {0.55f, 0.6f, 0.7f, 1.0f};
  static const GLfloat position[4] = {0.3f, 1.0f, 0.5f, 0.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(fogColor[0], fogColor[1], fogColor[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 0.5, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(12.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, -1.2f, 0.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);

  glEnable(GL_FOG);
  glFogfv(GL_FOG_COLOR, fogColor);

  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 4.0f);
  glFogf(GL_FOG_END, 16.0f);
  band(q, -1.9f);

  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.15f);
  band(q, 0.0f);

  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.12f);
  band(q, 1.9f);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
