/* The classic clip-plane demo: a wire sphere turned by glRotatef(90, 1, 0, 0), with two clip
 * planes through its centre set before the rotation (keep y >= 0 and x >= 0 in the frame of the
 * translated sphere), so that a quarter of the sphere remains. Several of the sphere's vertices lie
 * exactly on the planes: which side they fall on depends on the last bit of the rotation matrix
 * (cos 90 degrees is -4.37e-8 in Mesa's float arithmetic, not 0) and of the plane transformation,
 * and glass must keep and drop the same lines as Mesa. A second, solid sphere in the right half
 * of the window (its own viewport, so that it too sits on the view axis) is cut by the same
 * planes and lit on both sides.
 *
 * Both spheres sit on the view axis, as in the classic demo: moved sideways, the vertices on the
 * plane x = 0 land on either side of it by the rounding of float arithmetic, differently in
 * glass (distances in eye space) and Mesa (distances in clip space, after its own float inverse
 * of the projection). */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 500, HEIGHT = 300 };

static void draw(void)
{
  static const GLdouble upper[4] = {0.0, 1.0, 0.0, 0.0};
  static const GLdouble right[4] = {1.0, 0.0, 0.0, 0.0};
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_FLAT);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (GLfloat)(WIDTH / 2) / (GLfloat)HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glColor3f(1.0f, 1.0f, 1.0f);
  glViewport(0, 0, WIDTH / 2, HEIGHT);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glClipPlane(GL_CLIP_PLANE0, upper);
  glEnable(GL_CLIP_PLANE0);
  glClipPlane(GL_CLIP_PLANE1, right);
  glEnable(GL_CLIP_PLANE1);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  glutWireSphere(1.0, 20, 16);
  glPopMatrix();

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glShadeModel(GL_SMOOTH);
  glViewport(WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
  glClipPlane(GL_CLIP_PLANE0, upper);
  glClipPlane(GL_CLIP_PLANE1, right);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  glutSolidSphere(1.0, 24, 16);
  glPopMatrix();
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE1);
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
