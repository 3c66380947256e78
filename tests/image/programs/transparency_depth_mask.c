/* Transparency the way the classic three-dimensional blending demo does it: the opaque objects
 * first with depth writes on, then the translucent ones with glDepthMask(GL_FALSE), so that they
 * are tested against the opaque depth but do not hide each other, blended with
 * GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA. The translucent alpha comes from the material's diffuse
 * alpha under lighting (spec 2.13.1: the lit alpha is the diffuse alpha). On the right, three
 * overlapping discs add up with glBlendFunc(GL_ONE, GL_ONE) into saturated colours, and at the
 * bottom a row of quads shows GL_DST_COLOR/GL_ZERO (multiply) and GL_ONE_MINUS_DST_COLOR/GL_ZERO
 * (invert) over a gradient. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void disc(float x, float y, float r, float g, float b)
{
  int i;
  glColor3f(r, g, b);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(x, y);
  for (i = 0; i <= 36; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / 36.0;
    glVertex2f(x + 0.5f * (float)cos(angle), y + 0.5f * (float)sin(angle));
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  static const GLfloat solid[4] = {0.2f, 0.6f, 0.9f, 1.0f};
  static const GLfloat glass[4] = {0.9f, 0.8f, 0.1f, 0.45f};
  static const GLfloat tinted[4] = {0.9f, 0.1f, 0.5f, 0.3f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};

  glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.0, 2.0, -1.5, 1.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Bottom: a gradient, then multiply and invert over it. */
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(-1.9f, -1.4f);
  glColor3f(0.0f, 0.0f, 1.0f); glVertex2f(1.9f, -1.4f);
  glColor3f(0.0f, 1.0f, 0.0f); glVertex2f(1.9f, -0.9f);
  glColor3f(1.0f, 1.0f, 0.0f); glVertex2f(-1.9f, -0.9f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glColor3f(0.5f, 0.8f, 1.0f);
  glRectf(-1.6f, -1.35f, -0.2f, -0.95f);
  glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ZERO);
  glColor3f(1.0f, 1.0f, 1.0f);
  glRectf(0.2f, -1.35f, 1.6f, -0.95f);

  /* Right: additive discs. */
  glBlendFunc(GL_ONE, GL_ONE);
  disc(1.2f, 0.55f, 0.8f, 0.1f, 0.1f);
  disc(1.5f, 0.05f, 0.1f, 0.8f, 0.1f);
  disc(0.9f, 0.05f, 0.1f, 0.1f, 0.8f);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);

  /* Left: lit opaque sphere, then translucent cube and cone with the depth mask off. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
  glPushMatrix();
  glTranslatef(-0.9f, 0.3f, -1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, solid);
  glutSolidSphere(0.55, 30, 20);
  glPopMatrix();

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glPushMatrix();
  glTranslatef(-0.6f, 0.1f, 0.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, glass);
  glutSolidCube(0.8);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-1.3f, -0.2f, -2.0f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, tinted);
  glutSolidCone(0.45, 1.2, 20, 4);
  glPopMatrix();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
