/* Lights as homework scenes set them up: a finely tessellated floor (so per-vertex lighting can
 * show a spot) lit by a white spotlight (cutoff 25 degrees, exponent 10) aimed down from above,
 * a red positional light with linear and quadratic attenuation near the floor, a blue directional
 * light, and a dim headlight set with the identity modelview (so it moves with the eye), over a
 * teapot and a row of spheres; global ambient on. The lights are placed after gluLookAt, so they
 * are fixed in the world. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void floorGrid(void)
{
  int i, j;
  glNormal3f(0.0f, 1.0f, 0.0f);
  for (i = 0; i < 40; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= 40; ++j) {
      glVertex3f(-4.0f + 0.2f * (float)j, 0.0f, -4.0f + 0.2f * (float)(i + 1));
      glVertex3f(-4.0f + 0.2f * (float)j, 0.0f, -4.0f + 0.2f * (float)i);
    }
    glEnd();
  }
}

static void draw(void)
{
  static const GLfloat headlightPosition[4] = {0.0f, 0.0f, 1.0f, 0.0f};
  static const GLfloat headlight[4] = {0.15f, 0.15f, 0.15f, 1.0f};
  static const GLfloat spotPosition[4] = {0.5f, 4.0f, 0.5f, 1.0f};
  static const GLfloat spotDirection[3] = {-0.2f, -1.0f, -0.3f};
  static const GLfloat redPosition[4] = {-2.5f, 0.6f, 1.5f, 1.0f};
  static const GLfloat red[4] = {1.0f, 0.2f, 0.1f, 1.0f};
  static const GLfloat bluePosition[4] = {-1.0f, 0.5f, -1.0f, 0.0f};
  static const GLfloat blue[4] = {0.1f, 0.2f, 0.6f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat ambient[4] = {0.1f, 0.1f, 0.1f, 1.0f};
  static const GLfloat floorColour[4] = {0.7f, 0.7f, 0.7f, 1.0f};
  static const GLfloat jade[4] = {0.3f, 0.7f, 0.5f, 1.0f};
  static const GLfloat pearl[4] = {0.9f, 0.85f, 0.8f, 1.0f};
  int i;

  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)WIDTH / HEIGHT, 0.5, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT3, GL_POSITION, headlightPosition);
  glLightfv(GL_LIGHT3, GL_DIFFUSE, headlight);
  glLightfv(GL_LIGHT3, GL_SPECULAR, headlight);
  gluLookAt(0.0, 3.5, 6.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0);

  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_POSITION, spotPosition);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spotDirection);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 25.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 10.0f);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);

  glLightfv(GL_LIGHT1, GL_POSITION, redPosition);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, red);
  glLightfv(GL_LIGHT1, GL_SPECULAR, red);
  glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.3f);
  glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.2f);

  glLightfv(GL_LIGHT2, GL_POSITION, bluePosition);
  glLightfv(GL_LIGHT2, GL_DIFFUSE, blue);

  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHT2);
  glEnable(GL_LIGHT3);

  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floorColour);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  floorGrid();

  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, jade);
  glMaterialf(GL_FRONT, GL_SHININESS, 80.0f);
  glPushMatrix();
  glTranslatef(0.0f, 0.55f, 0.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
  glutSolidTeapot(0.8);
  glPopMatrix();

  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, pearl);
  for (i = 0; i < 5; ++i) {
    glPushMatrix();
    glTranslatef(-3.0f + 1.5f * (float)i, 0.35f, -2.5f);
    glutSolidSphere(0.35, 20, 14);
    glPopMatrix();
  }
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
