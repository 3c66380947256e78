/* User clip planes on spheres, as in the classic clip demo: a wire sphere with two planes (keep
 * y >= 0, keep x >= 0) set under a rotated modelview matrix, so the planes turn with the sphere;
 * a lit solid sphere cut by a plane through its centre at an angle, showing the back faces through
 * the cut with two-sided lighting (inside in another colour); a cone
 * sliced into rings by a pair of parallel planes; and a plane set under one matrix and used under
 * another (the plane is stored in eye coordinates when glClipPlane is called). */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void draw(void)
{
  /* Not exactly through the centre: the wire sphere has vertices exactly on the planes y = 0 and
   * x = 0, and which side of a plane such a vertex falls on rests on the last bit of the plane's
   * transformation (Mesa inverts matrices in float by its own formulas). */
  static const GLdouble keepUpper[4] = {0.0, 1.0, 0.0, 0.02};
  static const GLdouble keepRight[4] = {1.0, 0.0, 0.0, -0.03};
  static const GLdouble slant[4] = {1.0, 1.0, 1.0, 0.2};
  static const GLdouble below[4] = {0.0, -1.0, 0.0, 0.3};
  static const GLdouble above[4] = {0.0, 1.0, 0.0, 0.3};
  static const GLdouble window[4] = {-1.0, 0.0, 0.0, 3.5};
  static const GLfloat lightPosition[4] = {0.0f, 0.0f, 5.0f, 0.0f};
  static const GLfloat outside[4] = {0.9f, 0.6f, 0.2f, 1.0f};
  static const GLfloat inside[4] = {0.3f, 0.2f, 0.9f, 1.0f};
  static const GLfloat rings[4] = {0.4f, 0.9f, 0.4f, 1.0f};
  int i;

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glTranslatef(0.0f, 0.0f, -7.0f);

  /* A far-right window plane, set now under this matrix, used for everything. */
  glClipPlane(GL_CLIP_PLANE5, window);
  glEnable(GL_CLIP_PLANE5);

  glPushMatrix();
  glTranslatef(-2.2f, 1.0f, 0.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  glClipPlane(GL_CLIP_PLANE0, keepUpper);
  glEnable(GL_CLIP_PLANE0);
  glClipPlane(GL_CLIP_PLANE1, keepRight);
  glEnable(GL_CLIP_PLANE1);
  glColor3f(1.0f, 1.0f, 1.0f);
  glutWireSphere(1.3, 20, 16);
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE1);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.8f, 0.8f, 0.0f);
  glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
  glClipPlane(GL_CLIP_PLANE2, slant);
  glEnable(GL_CLIP_PLANE2);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, outside);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, inside);
  glutSolidSphere(1.3, 32, 24);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glDisable(GL_CLIP_PLANE2);
  glPopMatrix();

  /* Rings: the planes keep -0.3 <= y' <= 0.3 in a frame that moves up each time. */
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, rings);
  for (i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-0.6f, -2.0f + 0.9f * (float)i, 0.5f);
    glClipPlane(GL_CLIP_PLANE3, below);
    glClipPlane(GL_CLIP_PLANE4, above);
    glEnable(GL_CLIP_PLANE3);
    glEnable(GL_CLIP_PLANE4);
    glTranslatef(0.0f, -0.9f * (float)i, 0.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glutSolidCone(1.0, 2.5, 24, 8);
    glDisable(GL_CLIP_PLANE3);
    glDisable(GL_CLIP_PLANE4);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
  glDisable(GL_CLIP_PLANE5);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
