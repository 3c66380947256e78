/* One scene (coloured axes, a lit teapot, a wire cube, a floor grid) seen through gluLookAt from
 * odd angles, in four viewports: from straight above with the up vector along -z (the usual
 * mistake of an up vector parallel to the view direction is avoided, but only just: up is
 * (0, 0.001, -1)); from below the floor looking up; from far away with a narrow field of view
 * (telephoto, near and far planes wide apart); and with a tilted, non-unit up vector and an eye
 * inside the grid's bounding box. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 400 };

static void scene(void)
{
  static const GLfloat gold[4] = {0.85f, 0.65f, 0.2f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  int i;

  glDisable(GL_LIGHTING);
  glLineWidth(2.0f);
  glBegin(GL_LINES);
  glColor3f(1.0f, 0.0f, 0.0f); glVertex3f(0.0f, 0.0f, 0.0f); glVertex3f(2.0f, 0.0f, 0.0f);
  glColor3f(0.0f, 1.0f, 0.0f); glVertex3f(0.0f, 0.0f, 0.0f); glVertex3f(0.0f, 2.0f, 0.0f);
  glColor3f(0.0f, 0.0f, 1.0f); glVertex3f(0.0f, 0.0f, 0.0f); glVertex3f(0.0f, 0.0f, 2.0f);
  glEnd();
  glLineWidth(1.0f);
  glColor3f(0.5f, 0.5f, 0.5f);
  glBegin(GL_LINES);
  for (i = -4; i <= 4; ++i) {
    glVertex3f((float)i * 0.5f, -0.6f, -2.0f);
    glVertex3f((float)i * 0.5f, -0.6f, 2.0f);
    glVertex3f(-2.0f, -0.6f, (float)i * 0.5f);
    glVertex3f(2.0f, -0.6f, (float)i * 0.5f);
  }
  glEnd();
  glColor3f(0.3f, 0.9f, 0.9f);
  glPushMatrix();
  glTranslatef(-1.2f, 0.0f, 1.0f);
  glutWireCube(0.8);
  glPopMatrix();

  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  glPushMatrix();
  glTranslatef(0.5f, 0.0f, -0.5f);
  glutSolidTeapot(0.6);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

static void view(int column, int row, double fovy, double zNear, double zFar,
                 double ex, double ey, double ez, double cx, double cy, double cz,
                 double ux, double uy, double uz)
{
  static const GLfloat lightPosition[4] = {1.0f, 3.0f, 2.0f, 0.0f};
  glViewport(column * WIDTH / 2, row * HEIGHT / 2, WIDTH / 2, HEIGHT / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(fovy, 1.0, zNear, zFar);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(ex, ey, ez, cx, cy, cz, ux, uy, uz);
  /* The light is fixed in the world: set after the viewing transform. */
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  scene();
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);

  view(0, 1, 60.0, 1.0, 20.0, 0.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.001, -1.0);
  view(1, 1, 70.0, 0.5, 20.0, 0.3, -3.0, 2.5, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
  view(0, 0, 6.0, 10.0, 200.0, 30.0, 25.0, 40.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  view(1, 0, 80.0, 0.1, 10.0, 1.5, 0.3, 1.4, -0.5, 0.2, -0.5, 3.0, 5.0, 0.5);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
