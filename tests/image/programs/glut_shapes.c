/* Every GLUT shape (GLUT 3.7, chapter 11), lit: solid in the top two rows, wireframe in the
 * bottom two. Row by row: sphere, cube, cone, torus; dodecahedron, octahedron, tetrahedron,
 * icosahedron. glass draws them with freeglut 3's vertices, normals and order (checked vertex by
 * vertex in tests/glut_shapes); the Mesa reference draws them with freeglut itself. Each shape is
 * turned so that several faces show; the dodecahedron (circumradius sqrt 3) is scaled down with
 * GL_NORMALIZE on. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 480 };

static void place(int column, int row)
{
  glTranslatef(-3.0f + 2.0f * (float)column, 3.0f - 2.0f * (float)row, 0.0f);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-35.0f, 0.0f, 1.0f, 0.0f);
}

static void shapes(int firstRow, int wire)
{
  glPushMatrix();
  place(0, firstRow);
  if (wire) glutWireSphere(0.8, 16, 10); else glutSolidSphere(0.8, 16, 10);
  glPopMatrix();
  glPushMatrix();
  place(1, firstRow);
  if (wire) glutWireCube(1.1); else glutSolidCube(1.1);
  glPopMatrix();
  glPushMatrix();
  place(2, firstRow);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -0.6f);
  if (wire) glutWireCone(0.7, 1.3, 14, 4); else glutSolidCone(0.7, 1.3, 14, 4);
  glPopMatrix();
  glPushMatrix();
  place(3, firstRow);
  if (wire) glutWireTorus(0.22, 0.6, 10, 20); else glutSolidTorus(0.22, 0.6, 10, 20);
  glPopMatrix();

  glPushMatrix();
  place(0, firstRow + 1);
  glScalef(0.45f, 0.45f, 0.45f);
  if (wire) glutWireDodecahedron(); else glutSolidDodecahedron();
  glPopMatrix();
  glPushMatrix();
  place(1, firstRow + 1);
  glScalef(0.8f, 0.8f, 0.8f);
  if (wire) glutWireOctahedron(); else glutSolidOctahedron();
  glPopMatrix();
  glPushMatrix();
  place(2, firstRow + 1);
  glScalef(0.85f, 0.85f, 0.85f);
  if (wire) glutWireTetrahedron(); else glutSolidTetrahedron();
  glPopMatrix();
  glPushMatrix();
  place(3, firstRow + 1);
  glScalef(0.8f, 0.8f, 0.8f);
  if (wire) glutWireIcosahedron(); else glutSolidIcosahedron();
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat position[4] = {-1.0f, 2.0f, 3.0f, 0.0f};
  static const GLfloat color[4] = {0.85f, 0.55f, 0.3f, 1.0f};
  static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};

  glClearColor(0.12f, 0.14f, 0.18f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.0, 4.0, -4.0, 4.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, color);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);

  shapes(0, 0);
  shapes(2, 1);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
