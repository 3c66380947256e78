/* A planar projected shadow clipped to the floor with the stencil buffer: the classic technique
 * for the shadows of homework assignments 4-5 (object on a square floor, lit by a point light).
 *
 * 1. The floor is drawn, lit, writing 1 into the stencil buffer where it covers.
 * 2. The object is flattened onto the floor plane y = 0 by the shadow matrix of the point light
 *    L: for the plane P = (0, 1, 0, 0), M = (P . L) I - L P^T (a projection from L), and drawn
 *    unlit and blended black at 50 % where the stencil is 1, with glPolygonOffset pulling it
 *    above the floor. The stencil operation zeroes the stencil where the shadow lands, so
 *    overlapping shadow polygons darken each pixel only once. The light is low enough that part
 *    of the shadow falls beyond the floor's edge, where the stencil test clips it away.
 * 3. The object itself is drawn lit. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static const GLfloat light[4] = {-2.2f, 3.2f, 1.0f, 1.0f};

static void object(GLUquadric *q)
{
  glPushMatrix();
  glTranslatef(0.4f, 1.0f, -0.2f);
  gluSphere(q, 0.6, 30, 15);
  glTranslatef(0.0f, -1.0f, 0.0f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(q, 0.25, 0.25, 0.5, 20, 1);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-0.9f, 0.35f, 0.8f);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  gluCylinder(q, 0.35, 0.0, 0.9, 24, 2);
  glPopMatrix();
}

static void floorSquare(void)
{
  glNormal3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);
  glVertex3f(-2.0f, 0.0f, 2.0f);
  glVertex3f(2.0f, 0.0f, 2.0f);
  glVertex3f(2.0f, 0.0f, -2.0f);
  glVertex3f(-2.0f, 0.0f, -2.0f);
  glEnd();
}

/* The projection from the point light onto the plane y = 0, column-major. With P = (0, 1, 0, 0)
 * and d = P . L = L_y: M = d I - L P^T. */
static void shadowMatrix(GLfloat m[16])
{
  const GLfloat d = light[1];
  int column, row;
  for (column = 0; column < 4; ++column) {
    for (row = 0; row < 4; ++row) {
      const GLfloat plane = column == 1 ? 1.0f : 0.0f;
      m[column * 4 + row] = (row == column ? d : 0.0f) - light[row] * plane;
    }
  }
}

static void draw(void)
{
  static const GLfloat floorColor[4] = {0.75f, 0.75f, 0.7f, 1.0f};
  static const GLfloat objectColor[4] = {0.8f, 0.3f, 0.25f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLfloat shadow[16];
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.2f, 0.25f, 0.3f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(2.5, 3.5, 5.5, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);

  /* 1. Floor, marking the stencil. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floorColor);
  floorSquare();

  /* 2. Shadow, where the stencil is 1, once per pixel. */
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
  shadowMatrix(shadow);
  glPushMatrix();
  glMultMatrixf(shadow);
  object(q);
  glPopMatrix();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);

  /* 3. The object. */
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, objectColor);
  object(q);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
