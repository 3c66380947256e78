/* Colour material set up the way the classic colour-material example does it: the diffuse
 * reflectance is given with glMaterial in the initialisation, then glColorMaterial(GL_FRONT,
 * GL_DIFFUSE) and glEnable(GL_COLOR_MATERIAL); a sphere is drawn after a glColor call that
 * changes the colour, which both glass and Mesa then use as the diffuse reflectance.
 *
 * The example's first frame draws a sphere before any glColor call. The specification says the
 * diffuse reflectance then tracks the current colour, still the initial white (spec 2.14.3), so
 * that sphere is lit white; Mesa 22.3 applies the glMaterial value when it next draws and lights
 * it grey (0.5) until the current colour changes. glass follows the specification; that sphere is
 * tested on its own against the specification (tests/unit/color_material_first_frame_test.cpp),
 * not against Mesa here. */
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
  glColor3f(0.9f, 0.4f, 0.1f);
  glPushMatrix();
  glTranslatef(1.5f, 0.0f, 0.0f);
  glutSolidSphere(1.0, 20, 16);
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
