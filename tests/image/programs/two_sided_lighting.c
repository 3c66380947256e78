/* Two-sided lighting (spec 2.13.1): with GL_LIGHT_MODEL_TWO_SIDE, back-facing polygons are lit
 * with the back material and the reversed normal.
 *
 * Two open tubes (gluCylinder, no caps) tilted towards the viewer so that their inside shows.
 * Left: one-sided lighting: the inside is lit with the front material and the outward normal,
 * so it is dark where the outside would face away from the light. Right: two-sided: the inside
 * is lit with a blue back material and the inward normal, so the far inner wall, facing the
 * light, is bright. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 240 };

static void tube(GLUquadric *q, float x, float turn)
{
  glPushMatrix();
  glTranslatef(x, 0.0f, 0.0f);
  glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(turn, 0.0f, 1.0f, 0.0f); /* open end towards the middle */
  glTranslatef(0.0f, 0.0f, -1.0f);
  gluCylinder(q, 0.9, 0.9, 2.0, 36, 4);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat position[4] = {0.5f, 2.0f, 2.0f, 0.0f};
  static const GLfloat front[4] = {0.85f, 0.7f, 0.3f, 1.0f};
  static const GLfloat back[4] = {0.3f, 0.5f, 0.95f, 1.0f};
  static const GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -6.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, front);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 25.0f);

  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  tube(q, -1.9f, 20.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  tube(q, 1.9f, -20.0f);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
