/* Colour material set up the way the classic colour-material example does it: the diffuse
 * reflectance is given with glMaterial in the initialisation, then glColorMaterial(GL_FRONT,
 * GL_DIFFUSE) and glEnable(GL_COLOR_MATERIAL), and the first frame draws the sphere without any
 * glColor call (the program changes the colour only later, on a mouse click). The specification
 * says the diffuse reflectance then tracks the current colour, which is still the initial white
 * (spec 2.14.3), so the sphere is lit white; Mesa 22.3 applies the glMaterial value when it next
 * draws, after glEnable copied the colour, and lights it grey (0.5) until the current colour
 * changes. glass follows the specification. A second sphere, drawn after a glColor that changes
 * the colour, agrees in both. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 160 };

static void draw(void)
{
  static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  static const GLfloat specular[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_DEPTH_TEST);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.0, 3.0, -1.5, 1.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPushMatrix();
  glTranslatef(-1.5f, 0.0f, 0.0f);
  glutSolidSphere(1.0, 20, 16);
  glPopMatrix();

  glColor3f(0.9f, 0.4f, 0.1f);
  glPushMatrix();
  glTranslatef(1.5f, 0.0f, 0.0f);
  glutSolidSphere(1.0, 20, 16);
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
