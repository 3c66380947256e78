/* A grid of spheres, one material each, in the manner of the classic materials demo: rows differ
 * in ambient reflectance (none, grey, coloured), columns in the rest (diffuse only; diffuse with a
 * low-shininess specular; with a high-shininess specular; diffuse with emission). One directional
 * light with a global ambient term, so that the ambient columns show. A last row varies only the
 * shininess, 0 to 128, with a strong specular on a dark diffuse material. glOrtho keeps all
 * spheres the same size. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 400 };

static void sphereAt(float x, float y)
{
  glPushMatrix();
  glTranslatef(x, y, 0.0f);
  glutSolidSphere(0.9, 32, 24);
  glPopMatrix();
}

static void draw(void)
{
  static const GLfloat noMaterial[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat ambient[4] = {0.7f, 0.7f, 0.7f, 1.0f};
  static const GLfloat ambientColour[4] = {0.8f, 0.8f, 0.2f, 1.0f};
  static const GLfloat diffuse[4] = {0.1f, 0.5f, 0.8f, 1.0f};
  static const GLfloat specular[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat emission[4] = {0.3f, 0.2f, 0.2f, 0.0f};
  static const GLfloat lightAmbient[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat lightDiffuse[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat modelAmbient[4] = {0.4f, 0.4f, 0.4f, 1.0f};
  static const GLfloat darkRed[4] = {0.35f, 0.05f, 0.05f, 1.0f};
  const GLfloat *ambients[3] = {noMaterial, ambient, ambientColour};
  int row, column;

  glClearColor(0.0f, 0.1f, 0.1f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-6.0, 6.0, -5.0, 5.0, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glLightfv(GL_LIGHT0, GL_AMBIENT, lightAmbient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, lightDiffuse);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, modelAmbient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);

  for (row = 0; row < 3; ++row) {
    const float y = 3.75f - 2.5f * (float)row;
    for (column = 0; column < 4; ++column) {
      const float x = -3.75f + 2.5f * (float)column;
      glMaterialfv(GL_FRONT, GL_AMBIENT, ambients[row]);
      glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
      glMaterialfv(GL_FRONT, GL_SPECULAR, column == 1 || column == 2 ? specular : noMaterial);
      glMaterialf(GL_FRONT, GL_SHININESS, column == 1 ? 5.0f : column == 2 ? 100.0f : 0.0f);
      glMaterialfv(GL_FRONT, GL_EMISSION, column == 3 ? emission : noMaterial);
      sphereAt(x, y);
    }
  }

  glMaterialfv(GL_FRONT, GL_AMBIENT, noMaterial);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, darkRed);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialfv(GL_FRONT, GL_EMISSION, noMaterial);
  glPushMatrix();
  glScalef(0.8f, 0.8f, 0.8f);
  glEnable(GL_RESCALE_NORMAL);
  for (column = 0; column < 5; ++column) {
    glMateriali(GL_FRONT, GL_SHININESS, column * 32);
    sphereAt(-4.8f + 2.4f * (float)column, -4.9f);
  }
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
