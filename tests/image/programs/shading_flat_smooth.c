/* Flat against smooth shading of the same lit shapes (spec 2.13.7).
 *
 * Left: glShadeModel(GL_FLAT): every polygon takes the colour lit at one of its vertices (for the
 * quad strips and triangle fans GLU emits, the last vertex of each quad or triangle), so the
 * facets of the sphere and the torus-like ring of cylinders show. Right: GL_SMOOTH (Gouraud):
 * the colours lit at the vertices are interpolated across each polygon. Same light, material and
 * tessellation on both sides. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 240 };

static void scene(GLUquadric *q)
{
  glPushMatrix();
  glTranslatef(0.0f, 0.7f, 0.0f);
  gluSphere(q, 0.9, 14, 9);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.0f, -1.2f, 0.0f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -0.4f);
  gluCylinder(q, 0.8, 0.4, 0.8, 10, 2);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat position[4] = {-2.0f, 3.0f, 4.0f, 0.0f};
  static const GLfloat diffuse[4] = {0.3f, 0.6f, 0.9f, 1.0f};
  static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.9f, 0.9f, 0.88f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.4, 3.4, -2.04, 2.04, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);

  glShadeModel(GL_FLAT);
  glPushMatrix();
  glTranslatef(-1.7f, 0.0f, 0.0f);
  scene(q);
  glPopMatrix();

  glShadeModel(GL_SMOOTH);
  glPushMatrix();
  glTranslatef(1.7f, 0.0f, 0.0f);
  scene(q);
  glPopMatrix();

  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
