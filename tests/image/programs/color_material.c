/* glColorMaterial (spec 2.13.3): with GL_COLOR_MATERIAL enabled, glColor sets the material
 * parameter that glColorMaterial names, for the faces it names.
 *
 * Top row, one sphere per mode over a grey material, each drawn after a glColor of its own:
 * GL_AMBIENT_AND_DIFFUSE (the usual: the sphere takes the colour), GL_DIFFUSE, GL_AMBIENT (only
 * the shadowed side is coloured), GL_SPECULAR (a coloured highlight on a grey sphere),
 * GL_EMISSION (glows). Each glColor call changes the colour: Mesa 22 updates the material only
 * when the current colour changes, not when GL_COLOR_MATERIAL is enabled (docs/lighting.md).
 * Bottom: a lit strip whose colour changes at every vertex (the material follows each glColor
 * between glBegin and glEnd), and a sphere drawn after glDisable(GL_COLOR_MATERIAL) to show that
 * the last tracked colour stays in the material. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 500, HEIGHT = 240 };

static void greyMaterial(void)
{
  static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  static const GLfloat darkGrey[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, darkGrey);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, grey);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, grey);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
}

static void draw(void)
{
  static const GLfloat position[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat ambient[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  static const GLenum modes[5] = {GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_AMBIENT, GL_SPECULAR,
                                  GL_EMISSION};
  static const GLfloat colors[5][3] = {
      {0.9f, 0.3f, 0.2f}, {0.3f, 0.8f, 0.3f}, {0.9f, 0.2f, 0.8f}, {1.0f, 0.6f, 0.1f}, {0.2f, 0.4f, 0.9f}};
  GLUquadric *q = gluNewQuadric();
  int i;

  glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-5.0, 5.0, -2.4, 2.4, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);

  for (i = 0; i < 5; ++i) {
    greyMaterial();
    glColorMaterial(GL_FRONT, modes[i]);
    glEnable(GL_COLOR_MATERIAL);
    glColor3fv(colors[i]);
    glPushMatrix();
    glTranslatef(-4.0f + 2.0f * (float)i, 1.1f, 0.0f);
    gluSphere(q, 0.85, 32, 16);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);
  }

  /* A strip with a colour per vertex, tracked into the diffuse and ambient reflectance. */
  greyMaterial();
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= 12; ++i) {
    const float t = (float)i / 12.0f, x = -4.6f + 5.6f * t;
    glColor3f(t, 0.8f - 0.6f * t, 1.0f - t);
    glNormal3f(0.5f * cosf(6.0f * t), 0.0f, 1.0f);
    glVertex3f(x, -0.5f, 0.0f);
    glVertex3f(x, -2.0f, 0.0f);
  }
  glEnd();
  glColor3f(0.2f, 0.9f, 0.3f);
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(1.0f, 1.0f, 1.0f); /* no longer tracked: the sphere stays green */
  glPushMatrix();
  glTranslatef(3.3f, -1.25f, 0.0f);
  gluSphere(q, 0.8, 32, 16);
  glPopMatrix();
  gluDeleteQuadric(q);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
