/* Every GLU quadric (gluSphere, gluCylinder, gluDisk, gluPartialDisk) in every draw style, lit.
 *
 * Columns: sphere, cylinder (a cone frustum), disk with a hole, partial disk (from 30 degrees,
 * sweeping 240). Rows, top to bottom: GLU_FILL with GLU_SMOOTH normals; GLU_FILL with GLU_FLAT
 * normals and GLU_INSIDE orientation (the shapes show their inside faces: the sphere and cylinder
 * are drawn with front-face culling off, and lit through their reversed normals); GLU_LINE;
 * GLU_SILHOUETTE; GLU_POINT (points of size 2). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 500 };

static void shapes(GLUquadric *q, float y)
{
  glPushMatrix();
  glTranslatef(-3.0f, y, 0.0f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  gluSphere(q, 0.8, 16, 10);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-1.0f, y - 0.5f, 0.0f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  gluCylinder(q, 0.8, 0.45, 1.1, 16, 3);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.0f, y, 0.0f);
  glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
  gluDisk(q, 0.3, 0.85, 16, 3);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(3.0f, y, 0.0f);
  glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
  gluPartialDisk(q, 0.2, 0.85, 14, 3, 30.0, 240.0);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat position[4] = {-1.0f, 1.0f, 2.0f, 0.0f};
  static const GLfloat color[4] = {0.4f, 0.75f, 0.55f, 1.0f};
  static const GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glPointSize(2.0f);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.2, 4.2, -5.25, 5.25, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, color);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);

  gluQuadricDrawStyle(q, GLU_FILL);
  gluQuadricNormals(q, GLU_SMOOTH);
  shapes(q, 4.0f);

  gluQuadricNormals(q, GLU_FLAT);
  gluQuadricOrientation(q, GLU_INSIDE);
  shapes(q, 2.0f);
  gluQuadricOrientation(q, GLU_OUTSIDE);
  gluQuadricNormals(q, GLU_SMOOTH);

  gluQuadricDrawStyle(q, GLU_LINE);
  shapes(q, 0.0f);
  gluQuadricDrawStyle(q, GLU_SILHOUETTE);
  shapes(q, -2.0f);
  gluQuadricDrawStyle(q, GLU_POINT);
  shapes(q, -4.0f);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
