/* Normals under scaling (spec 2.11.3): normals are transformed by the inverse transpose of the
 * modelview matrix, then optionally normalized (GL_NORMALIZE) or rescaled (GL_RESCALE_NORMAL).
 *
 * Top row: a sphere scaled uniformly by 0.5, lit three ways. Without either mode the transformed
 * normals are twice too long and the sphere is over-bright (the lighting equation uses the normal
 * as it is); GL_RESCALE_NORMAL divides by the scale factor the modelview matrix applies; and
 * GL_NORMALIZE makes every normal unit length. The last two look the same.
 * Bottom row: ellipsoids (spheres scaled by (1.6, 0.6, 1) and (0.6, 1.3, 1), one also rotated),
 * where only the inverse transpose keeps the normals perpendicular to the squashed surface, with
 * GL_NORMALIZE. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 420, HEIGHT = 280 };

static void draw(void)
{
  static const GLfloat position[4] = {-1.0f, 1.5f, 2.0f, 0.0f};
  static const GLfloat color[4] = {0.35f, 0.5f, 0.85f, 1.0f};
  static const GLfloat specular[4] = {0.7f, 0.7f, 0.7f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.0, 3.0, -2.0, 2.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, color);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);

  /* A sphere of radius 1.6 drawn at half size: its normals come out twice too long. */
  glPushMatrix();
  glTranslatef(-2.0f, 1.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  gluSphere(q, 1.6, 32, 16);
  glPopMatrix();

  glEnable(GL_RESCALE_NORMAL);
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  gluSphere(q, 1.6, 32, 16);
  glPopMatrix();
  glDisable(GL_RESCALE_NORMAL);

  glEnable(GL_NORMALIZE);
  glPushMatrix();
  glTranslatef(2.0f, 1.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  gluSphere(q, 1.6, 32, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-1.2f, -1.0f, 0.0f);
  glScalef(1.6f, 0.6f, 1.0f);
  gluSphere(q, 0.8, 32, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.4f, -1.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glScalef(0.6f, 1.3f, 1.0f);
  gluSphere(q, 0.7, 32, 16);
  glPopMatrix();
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
