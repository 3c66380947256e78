/* The robot arm exercise: a shoulder and an elbow joint built from scaled cubes on the matrix
 * stack (rotate about the joint, translate half a segment, push, scale, draw, pop), with three
 * fingers at the wrist. The segments are glutWireCube outlines around lit solid cubes; the
 * non-uniform glScalef of the segments distorts their normals, which GL_NORMALIZE repairs. The
 * arm is drawn twice: in two viewports, from the front and from above. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 240 };

static void segment(float length, float thickness, const GLfloat colour[4])
{
  glPushMatrix();
  glScalef(length, thickness, thickness);
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
  glutSolidCube(1.0);
  glDisable(GL_LIGHTING);
  glColor3f(1.0f, 1.0f, 1.0f);
  glutWireCube(1.02);
  glPopMatrix();
}

static void arm(float shoulder, float elbow)
{
  static const GLfloat upper[4] = {0.8f, 0.3f, 0.2f, 1.0f};
  static const GLfloat lower[4] = {0.2f, 0.6f, 0.3f, 1.0f};
  static const GLfloat finger[4] = {0.9f, 0.8f, 0.2f, 1.0f};
  int i;
  glPushMatrix();
  glTranslatef(-1.5f, 0.0f, 0.0f);
  glRotatef(shoulder, 0.0f, 0.0f, 1.0f);
  glTranslatef(1.0f, 0.0f, 0.0f);
  segment(2.0f, 0.4f, upper);
  glTranslatef(1.0f, 0.0f, 0.0f);
  glRotatef(elbow, 0.0f, 0.0f, 1.0f);
  glTranslatef(1.0f, 0.0f, 0.0f);
  segment(2.0f, 0.3f, lower);
  glTranslatef(1.0f, 0.0f, 0.0f);
  for (i = 0; i < 3; ++i) {
    glPushMatrix();
    glRotatef(-30.0f + 30.0f * (float)i, 0.0f, 0.0f, 1.0f);
    glRotatef(20.0f * (float)(i - 1), 0.0f, 1.0f, 0.0f);
    glTranslatef(0.3f, 0.0f, 0.0f);
    segment(0.6f, 0.1f, finger);
    glPopMatrix();
  }
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat lightDirection[4] = {0.3f, 0.5f, 1.0f, 0.0f};

  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glEnable(GL_LIGHT0);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(65.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);

  glViewport(0, 0, WIDTH / 2, HEIGHT);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
  glTranslatef(0.0f, -0.5f, -5.0f);
  arm(45.0f, 60.0f);

  glViewport(WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
  gluLookAt(0.0, 5.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  arm(45.0f, 60.0f);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
