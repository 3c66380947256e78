/* Lit spheres and cylinders (gluSphere, gluCylinder) under the three kinds of light of the
 * OpenGL 1.x lighting equation (spec 2.13.1), one kind per column:
 *   left    a directional light (w = 0): the same direction everywhere, no attenuation;
 *   middle  a positional light close to the shapes with constant, linear and quadratic
 *           attenuation: the lit side fades with the distance to the light;
 *   right   a spotlight (cutoff 18 degrees, exponent 8) aimed at the shapes: only a disc of the
 *           surface is lit, brightest at the centre of the cone.
 * The top row is a sphere, the bottom row a cylinder lying along x, all smooth shaded with a
 * white specular highlight (shininess 40) and a little scene ambient. The lights are placed
 * after the viewing transformation, so their positions are in world coordinates. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 320 };

static void material(void)
{
  static const GLfloat diffuse[4] = {0.7f, 0.55f, 0.35f, 1.0f};
  static const GLfloat ambient[4] = {0.3f, 0.25f, 0.2f, 1.0f};
  static const GLfloat specular[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
}

/* The lights, each at the column it lights (columns at x = -3, 0, 3). */
static void lights(void)
{
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat dim[4] = {0.1f, 0.1f, 0.1f, 1.0f};
  static const GLfloat direction[4] = {-1.0f, 1.5f, 2.0f, 0.0f};
  static const GLfloat point[4] = {1.2f, 1.2f, 1.6f, 1.0f};
  static const GLfloat spot[4] = {3.0f, 0.2f, 4.0f, 1.0f};
  static const GLfloat spotDirection[3] = {0.0f, -0.05f, -1.0f};
  static const GLfloat sceneAmbient[4] = {0.1f, 0.1f, 0.12f, 1.0f};
  int i;
  for (i = 0; i < 3; ++i) {
    glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0 + i, GL_SPECULAR, white);
    glLightfv(GL_LIGHT0 + i, GL_AMBIENT, dim);
  }
  glLightfv(GL_LIGHT0, GL_POSITION, direction);

  glLightfv(GL_LIGHT1, GL_POSITION, point);
  glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
  glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.15f);

  glLightfv(GL_LIGHT2, GL_POSITION, spot);
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, spotDirection);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 18.0f);
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8.0f);

  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, sceneAmbient);
  glEnable(GL_LIGHTING);
}

static void draw(void)
{
  GLUquadric *q = gluNewQuadric();
  int column;

  glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(38.0, (double)WIDTH / HEIGHT, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 0.0, 10.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  lights();
  material();

  for (column = 0; column < 3; ++column) {
    const float x = -3.0f + 3.0f * (float)column;
    glDisable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glDisable(GL_LIGHT2);
    glEnable(GL_LIGHT0 + column);

    glPushMatrix();
    glTranslatef(x, 1.1f, 0.0f);
    gluSphere(q, 1.0, 32, 16);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(x - 1.1f, -1.5f, 0.0f);
    glRotatef(90.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(-30.0f, 0.0f, 0.0f, 1.0f);
    gluCylinder(q, 0.7, 0.7, 2.2, 32, 6);
    glPopMatrix();
  }
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
