/* Materials (spec 2.13.1): emission, ambient, diffuse and specular reflectance and shininess,
 * and the light model's separate specular colour and local viewer.
 *
 * Top row, left to right: a sphere that only glows (emission, no light reflected); a matte
 * sphere (diffuse only); the same with a broad highlight (shininess 8); with a tight highlight
 * (shininess 100); with a coloured specular reflectance (the highlight takes the colour of
 * the material's specular term, not of the diffuse one).
 * Bottom row: the same five spheres with GL_LIGHT_MODEL_COLOR_CONTROL set to
 * GL_SEPARATE_SPECULAR_COLOR (the specular sum goes to the secondary colour and is added after
 * texturing; without texture the sum is the same picture up to where clamping happens: a
 * saturated diffuse colour no longer eats the highlight) and GL_LIGHT_MODEL_LOCAL_VIEWER
 * (highlights computed from the true direction to the eye, so they move on spheres away from
 * the centre). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 500, HEIGHT = 220 };

struct Look {
  GLfloat emission[4], ambient[4], diffuse[4], specular[4], shininess;
};

static const struct Look looks[5] = {
    {{0.9f, 0.45f, 0.1f, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, 0.0f},
    {{0, 0, 0, 1}, {0.2f, 0.2f, 0.25f, 1}, {0.2f, 0.5f, 0.8f, 1}, {0, 0, 0, 1}, 0.0f},
    {{0, 0, 0, 1}, {0.2f, 0.2f, 0.25f, 1}, {0.2f, 0.5f, 0.8f, 1}, {0.7f, 0.7f, 0.7f, 1}, 8.0f},
    {{0, 0, 0, 1}, {0.2f, 0.2f, 0.25f, 1}, {0.9f, 0.95f, 0.2f, 1}, {1.0f, 1.0f, 1.0f, 1}, 100.0f},
    {{0, 0, 0, 1}, {0.2f, 0.2f, 0.25f, 1}, {0.7f, 0.15f, 0.1f, 1}, {0.2f, 1.0f, 0.3f, 1}, 30.0f}};

static void row(GLUquadric *q, float y)
{
  int i;
  for (i = 0; i < 5; ++i) {
    glMaterialfv(GL_FRONT, GL_EMISSION, looks[i].emission);
    glMaterialfv(GL_FRONT, GL_AMBIENT, looks[i].ambient);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, looks[i].diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, looks[i].specular);
    glMaterialf(GL_FRONT, GL_SHININESS, looks[i].shininess);
    glPushMatrix();
    glTranslatef(-4.0f + 2.0f * (float)i, y, 0.0f);
    gluSphere(q, 0.85, 40, 20);
    glPopMatrix();
  }
}

static void draw(void)
{
  static const GLfloat position[4] = {-1.0f, 1.0f, 1.5f, 0.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLUquadric *q = gluNewQuadric();

  glClearColor(0.12f, 0.12f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(24.0, (double)WIDTH / HEIGHT, 5.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -12.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);

  row(q, 1.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  row(q, -1.0f);
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
