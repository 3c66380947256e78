/* Two classic uses of the stencil buffer. Left: decals. A runway quad is drawn with the depth
 * test, writing 1 into the stencil where it is visible (glStencilOp GL_REPLACE); then its markings,
 * coplanar with it, are drawn with the depth test off and glStencilFunc(GL_EQUAL, 1), so that they
 * appear exactly where the runway is visible, and not on the box that stands in front of it.
 * Right: a mask. A diamond is drawn into the stencil buffer only (colour writes off with
 * glColorMask), then a lit torus is drawn where the stencil is 1 and a lit sphere where it is not
 * (GL_NOTEQUAL), with glStencilMask and GL_INCR/GL_INVERT exercised on the way. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 240 };

static void runwayPanel(void)
{
  int i;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 1.0, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 2.5, 4.0, 0.0, 0.0, -4.0, 0.0, 1.0, 0.0);

  /* A box in front of part of the runway, drawn first. */
  glColor3f(0.6f, 0.3f, 0.1f);
  glPushMatrix();
  glTranslatef(0.9f, 0.4f, 0.5f);
  glutSolidCube(0.8);
  glPopMatrix();

  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColor3f(0.3f, 0.3f, 0.32f);
  glBegin(GL_QUADS);
  glVertex3f(-1.0f, 0.0f, 2.0f);
  glVertex3f(1.0f, 0.0f, 2.0f);
  glVertex3f(1.0f, 0.0f, -12.0f);
  glVertex3f(-1.0f, 0.0f, -12.0f);
  glEnd();

  glDisable(GL_DEPTH_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(1.0f, 1.0f, 0.9f);
  for (i = 0; i < 7; ++i) {
    const float z = 1.5f - 2.0f * (float)i;
    glBegin(GL_QUADS);
    glVertex3f(-0.06f, 0.0f, z);
    glVertex3f(0.06f, 0.0f, z);
    glVertex3f(0.06f, 0.0f, z - 1.0f);
    glVertex3f(-0.06f, 0.0f, z - 1.0f);
    glEnd();
  }
  glColor3f(1.0f, 0.8f, 0.0f);
  glBegin(GL_LINE_STRIP);
  glVertex3f(-0.9f, 0.0f, 2.5f);
  glVertex3f(-0.9f, 0.0f, -12.0f);
  glEnd();
  glBegin(GL_LINES);
  glVertex3f(0.9f, 0.0f, 2.5f);
  glVertex3f(0.9f, 0.0f, -12.0f);
  glEnd();
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
}

static void maskPanel(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 2.0f, 0.0f};
  static const GLfloat torusColour[4] = {0.9f, 0.5f, 0.1f, 1.0f};
  static const GLfloat sphereColour[4] = {0.2f, 0.4f, 0.9f, 1.0f};

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.0, 3.0, -3.0, 3.0, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* The diamond into the stencil only: twice, with GL_INCR then GL_INVERT on its inner half,
   * leaving 1 in the outer ring and 0xFE in the inner diamond (masked to the low 4 bits by
   * glStencilMask, so 0x0E there). */
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  glBegin(GL_QUADS);
  glVertex2f(0.0f, -2.6f);
  glVertex2f(2.6f, 0.0f);
  glVertex2f(0.0f, 2.6f);
  glVertex2f(-2.6f, 0.0f);
  glEnd();
  glStencilMask(0x0F);
  glStencilOp(GL_INVERT, GL_INVERT, GL_INVERT);
  glBegin(GL_QUADS);
  glVertex2f(0.0f, -1.0f);
  glVertex2f(1.0f, 0.0f);
  glVertex2f(0.0f, 1.0f);
  glVertex2f(-1.0f, 0.0f);
  glEnd();
  glStencilMask(0xFF);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);

  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);

  glStencilFunc(GL_EQUAL, 0x1, 0xFF);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, torusColour);
  glPushMatrix();
  glRotatef(40.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.5, 1.6, 20, 40);
  glPopMatrix();

  glStencilFunc(GL_NOTEQUAL, 0x1, 0x0F);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, sphereColour);
  glutSolidSphere(1.9, 32, 24);
  glDisable(GL_LIGHTING);
  glDisable(GL_STENCIL_TEST);
}

static void draw(void)
{
  glClearColor(0.45f, 0.6f, 0.75f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glViewport(0, 0, WIDTH / 2, HEIGHT);
  runwayPanel();
  glViewport(WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  maskPanel();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
