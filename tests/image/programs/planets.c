/* A solar system with the matrix stack: a sun at the origin, a planet on a tilted orbit that
 * turns on its own axis (year, then day rotations between glPushMatrix and glPopMatrix), and a
 * moon that orbits the planet (its transform composed on top of the planet's year). The sun glows
 * by emission, the planet and moon are lit by a point light at the sun's centre, the orbits are
 * GL_LINE_LOOP circles, the planet carries a wire sphere showing its day rotation, and a second
 * planet with a ring (a gluDisk) sits further out. Perspective from gluLookAt above the plane. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void orbit(float radius)
{
  int i;
  glBegin(GL_LINE_LOOP);
  for (i = 0; i < 72; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / 72.0;
    glVertex3f(radius * (float)cos(angle), 0.0f, radius * (float)sin(angle));
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat atSun[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat sunGlow[4] = {1.0f, 0.85f, 0.3f, 1.0f};
  static const GLfloat none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat earth[4] = {0.2f, 0.4f, 1.0f, 1.0f};
  static const GLfloat moon[4] = {0.7f, 0.7f, 0.65f, 1.0f};
  static const GLfloat saturn[4] = {0.9f, 0.75f, 0.45f, 1.0f};
  static const GLfloat ring[4] = {0.6f, 0.55f, 0.4f, 1.0f};
  static const GLfloat dim[4] = {0.05f, 0.05f, 0.05f, 1.0f};
  const float year = 65.0f, day = 200.0f, month = 150.0f;
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.0f, 0.0f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (GLdouble)WIDTH / HEIGHT, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 6.0, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  /* Orbits, unlit. */
  glColor3f(0.4f, 0.4f, 0.5f);
  orbit(3.0f);
  orbit(5.5f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, dim);
  glLightfv(GL_LIGHT0, GL_POSITION, atSun);

  /* The sun: emission only, so that the light inside it does not matter. */
  glMaterialfv(GL_FRONT, GL_EMISSION, sunGlow);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, none);
  glutSolidSphere(1.0, 24, 16);
  glMaterialfv(GL_FRONT, GL_EMISSION, none);

  glPushMatrix();
  glRotatef(year, 0.0f, 1.0f, 0.0f);
  glTranslatef(3.0f, 0.0f, 0.0f);
  glPushMatrix();
  glRotatef(23.0f, 0.0f, 0.0f, 1.0f);
  glRotatef(day, 0.0f, 1.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, earth);
  glutSolidSphere(0.35, 20, 12);
  glDisable(GL_LIGHTING);
  glColor3f(0.8f, 0.9f, 1.0f);
  glutWireSphere(0.45, 8, 6);
  glEnable(GL_LIGHTING);
  glPopMatrix();
  glRotatef(month, 0.0f, 1.0f, 0.0f);
  glTranslatef(0.8f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, moon);
  glutSolidSphere(0.12, 12, 8);
  glPopMatrix();

  glPushMatrix();
  glRotatef(-140.0f, 0.0f, 1.0f, 0.0f);
  glTranslatef(5.5f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, saturn);
  gluSphere(q, 0.6, 24, 16);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, ring);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gluDisk(q, 0.8, 1.2, 32, 2);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glPopMatrix();
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
