/* Depth-buffer tricks: glDepthRange splitting the depth buffer between a background layer
 * (0.5..1) and a foreground layer (0..0.5) so that the foreground always wins; a HUD drawn with
 * glDepthRange(0, 0) that covers the 3D scene; a reversed range glDepthRange(1, 0) with
 * glDepthFunc(GL_GREATER) and glClearDepth(0); GL_LEQUAL for drawing the same geometry twice
 * (a second, coloured pass over a lit one); GL_EQUAL passes; and glDepthMask(GL_FALSE) for an
 * object that must not hide the objects drawn after it. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void draw(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat red[4] = {0.9f, 0.2f, 0.2f, 1.0f};
  static const GLfloat blue[4] = {0.2f, 0.3f, 0.9f, 1.0f};

  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glTranslatef(0.0f, 0.0f, -10.0f);

  /* Foreground layer first, then a big background sphere that is nearer in eye space but
   * lands in the back half of the depth range. */
  glEnable(GL_LIGHTING);
  glDepthRange(0.0, 0.5);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glPushMatrix();
  glTranslatef(-2.0f, 1.0f, -3.0f);
  glutSolidSphere(1.0, 24, 16);
  glPopMatrix();
  glDepthRange(0.5, 1.0);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  glPushMatrix();
  glTranslatef(-2.5f, 1.0f, 1.0f);
  glutSolidCube(1.6);
  glPopMatrix();
  glDepthRange(0.0, 1.0);

  /* Two passes over the same torus: lit, then a stripe of flat colour with GL_EQUAL. */
  glPushMatrix();
  glTranslatef(2.0f, 1.2f, 0.0f);
  glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.35, 0.9, 16, 32);
  glDisable(GL_LIGHTING);
  glDepthFunc(GL_EQUAL);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 210, WIDTH, 14);
  glColor3f(1.0f, 1.0f, 0.0f);
  glutSolidTorus(0.35, 0.9, 16, 32);
  glDisable(GL_SCISSOR_TEST);
  glDepthFunc(GL_LEQUAL);
  glPopMatrix();

  /* A translucent-looking ghost drawn without depth writes, then a cone that passes behind it. */
  glDepthMask(GL_FALSE);
  glColor3f(0.4f, 0.4f, 0.5f);
  glPushMatrix();
  glTranslatef(0.0f, -1.5f, 1.0f);
  glutSolidSphere(0.9, 20, 12);
  glPopMatrix();
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glEnable(GL_LIGHTING);
  glPushMatrix();
  glTranslatef(0.3f, -1.5f, -1.0f);
  glRotatef(-90.0f, 0.0f, 1.0f, 0.0f);
  glutSolidCone(0.5, 2.5, 16, 4);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Reversed depth in the lower right: clear depth to 0 there, GL_GREATER, range (1, 0). */
  glEnable(GL_SCISSOR_TEST);
  glScissor(260, 0, 140, 110);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glDepthRange(1.0, 0.0);
  glDepthFunc(GL_GREATER);
  glBegin(GL_TRIANGLES);
  glColor3f(0.0f, 1.0f, 0.0f);
  glVertex3f(2.0f, -3.0f, 2.0f); glVertex3f(4.0f, -3.0f, -2.0f); glVertex3f(3.0f, -1.0f, 0.0f);
  glColor3f(1.0f, 0.0f, 1.0f);
  glVertex3f(2.0f, -2.5f, -2.0f); glVertex3f(4.0f, -2.5f, 2.0f); glVertex3f(3.0f, -0.5f, 0.0f);
  glEnd();
  glDepthFunc(GL_LESS);
  glDepthRange(0.0, 1.0);
  glClearDepth(1.0);

  /* A HUD frame at depth 0 over everything. */
  glDepthRange(0.0, 0.0);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  gluOrtho2D(0.0, WIDTH, 0.0, HEIGHT);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINE_LOOP);
  glVertex2f(5.5f, 5.5f); glVertex2f(394.5f, 5.5f); glVertex2f(394.5f, 294.5f); glVertex2f(5.5f, 294.5f);
  glEnd();
  glColor3f(0.0f, 0.0f, 0.0f);
  glRectf(150.0f, 130.0f, 250.0f, 170.0f);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glDepthRange(0.0, 1.0);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
