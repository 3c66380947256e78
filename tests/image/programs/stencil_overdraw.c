/* Counting with the stencil buffer: a scene of overlapping translucent-looking shapes is drawn
 * with glStencilOp(GL_KEEP, GL_INCR, GL_INCR) and the depth test on, so the stencil value counts
 * the fragments per pixel (depth-failing ones included), then each count is shown in its own
 * colour by drawing a full-screen quad per value with glStencilFunc(GL_EQUAL, n). GL_INCR clamps
 * at 255 and GL_DECR at 0: a second pass decrements a band below zero. glStencilMask limits the
 * write to the low bits in the right half. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void scene(void)
{
  glPushMatrix();
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.35, 1.0, 12, 24);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.4f, 0.2f, 0.5f);
  glutSolidSphere(0.7, 16, 12);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-0.6f, -0.4f, -0.5f);
  glRotatef(40.0f, 1.0f, 1.0f, 0.0f);
  glutSolidCube(0.9);
  glPopMatrix();
}

static void fullScreen(void)
{
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

static void draw(void)
{
  static const GLfloat colours[8][3] = {{0.0f, 0.0f, 0.0f}, {0.1f, 0.1f, 0.5f}, {0.1f, 0.5f, 0.1f},
                                        {0.6f, 0.6f, 0.1f}, {0.8f, 0.4f, 0.1f}, {0.9f, 0.1f, 0.1f},
                                        {1.0f, 0.5f, 0.8f}, {1.0f, 1.0f, 1.0f}};
  int n;

  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.5f);

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  scene();

  /* Decrement a band twice: values reach 0 and stay there. */
  glDisable(GL_DEPTH_TEST);
  glStencilOp(GL_DECR, GL_DECR, GL_DECR);
  glRectf(-2.0f, -0.15f, 2.0f, 0.15f);
  glRectf(-2.0f, -0.15f, 2.0f, 0.15f);
  /* In the right half, increment through the mask 0x03: the incremented value is written to
   * the low two bits only, so 3 becomes 0 there (4 masked), 7 becomes 4. */
  glStencilMask(0x03);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  glRectf(0.0f, -2.0f, 2.0f, 2.0f);
  glStencilMask(0xFF);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (n = 0; n < 8; ++n) {
    glStencilFunc(GL_EQUAL, n, 0xFF);
    glColor3fv(colours[n]);
    fullScreen();
  }
  glStencilFunc(GL_LESS, 7, 0xFF);
  glColor3f(0.5f, 0.5f, 0.5f);
  fullScreen();
  glDisable(GL_STENCIL_TEST);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
