/* A mirror floor, the classic stencil reflection: the floor is drawn into the stencil buffer
 * only; the scene is drawn mirrored through the floor plane (glScalef(1, -1, 1), with
 * glFrontFace(GL_CW) because the mirror flips the winding, and the light re-placed under the
 * mirrored matrix) where the stencil is set; then the floor is blended over the reflection at
 * 60% opacity with lighting; then the scene itself. A lit torus and a lit cube. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static const GLfloat lightPosition[4] = {1.5f, 3.0f, 2.0f, 1.0f};

static void objects(void)
{
  static const GLfloat orange[4] = {1.0f, 0.5f, 0.1f, 1.0f};
  static const GLfloat cyan[4] = {0.1f, 0.7f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, orange);
  glPushMatrix();
  glTranslatef(-0.6f, 0.9f, 0.0f);
  glRotatef(40.0f, 1.0f, 0.3f, 0.0f);
  glutSolidTorus(0.2, 0.5, 16, 32);
  glPopMatrix();
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, cyan);
  glPushMatrix();
  glTranslatef(0.8f, 0.5f, 0.3f);
  glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
  glutSolidCube(0.7);
  glPopMatrix();
}

static void floorQuad(void)
{
  glNormal3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);
  glVertex3f(-2.0f, 0.0f, 2.0f);
  glVertex3f(2.0f, 0.0f, 2.0f);
  glVertex3f(2.0f, 0.0f, -2.0f);
  glVertex3f(-2.0f, 0.0f, -2.0f);
  glEnd();
}

static void draw(void)
{
  static const GLfloat marble[4] = {0.6f, 0.6f, 0.7f, 0.6f};

  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 2.2, 5.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0);
  glEnable(GL_LIGHT0);

  /* 1. The floor into the stencil only. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  floorQuad();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);

  /* 2. The reflection where the floor is. */
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glPushMatrix();
  glScalef(1.0f, -1.0f, 1.0f);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glFrontFace(GL_CW);
  objects();
  glFrontFace(GL_CCW);
  glPopMatrix();
  glDisable(GL_STENCIL_TEST);

  /* 3. The floor, blended. */
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, marble);
  floorQuad();
  glDisable(GL_BLEND);

  /* 4. The objects. */
  objects();
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
