/* Alpha blending (spec 4.1.7) of transparent quads over a lit scene, the classic way: opaque
 * objects first with depth writes on, then the transparent ones from back to front with
 * glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) and depth writes off (the depth test stays
 * on, so a transparent quad behind an opaque object is hidden by it).
 *
 * A lit sphere and cylinder; a blue quad at alpha 0.5 partly in front of the sphere and partly
 * behind the cylinder; a red quad at alpha 0.3 crossing in front of both. The lit colours carry
 * the material's diffuse alpha (0.6 on the cylinder), which blending ignores for opaque drawing
 * since blending is off then. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void quad(float x0, float y0, float x1, float y1, float z)
{
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

static void draw(void)
{
  static const GLfloat position[4] = {-1.0f, 2.0f, 3.0f, 0.0f};
  static const GLfloat sphere[4] = {0.9f, 0.8f, 0.2f, 1.0f};
  static const GLfloat cylinder[4] = {0.3f, 0.8f, 0.4f, 0.6f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.95f, 0.95f, 0.95f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -7.0f);

  /* Opaque, lit. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 50.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, sphere);
  glPushMatrix();
  glTranslatef(-0.9f, 0.3f, 0.0f);
  gluSphere(q, 1.1, 36, 18);
  glPopMatrix();
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, cylinder);
  glPushMatrix();
  glTranslatef(1.4f, -1.4f, -0.5f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(q, 0.6, 0.6, 2.6, 30, 3);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Transparent, unlit, back to front. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glColor4f(0.1f, 0.3f, 0.9f, 0.5f);
  quad(-1.2f, -1.6f, 2.4f, 1.0f, -0.8f);
  glColor4f(0.9f, 0.1f, 0.1f, 0.3f);
  quad(-2.6f, -0.6f, 2.2f, 0.2f, 1.4f);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
