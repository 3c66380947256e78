/* The lighting equation (OpenGL 1.5 section 2.13.1) where homework programs set it up in ways
 * its terms make visible, one lit sphere per cell, 4 x 2:
 *
 *   top row:    a spotlight given with w = 0 by mistake (a directional light: the cone is tested
 *               against its one direction, which lies inside it, so the sphere is lit as by a
 *               plain directional light, with no pool of light); a spotlight with
 *               GL_SPOT_CUTOFF 180 and exponent 50 (no cone at all: the exponent is ignored);
 *               a positional light with linear and quadratic attenuation next to the same light
 *               with w = 0 (attenuation ignored); GL_LIGHT_MODEL_LOCAL_VIEWER with the sphere off
 *               to the side (the highlight moves towards the eye)
 *   bottom row: a textured sphere (GL_MODULATE) with GL_SINGLE_COLOR, the texture darkening the
 *               highlight; the same with GL_SEPARATE_SPECULAR_COLOR, the highlight added after
 *               texturing; an open cylinder with glFrontFace(GL_CW) and two-sided lighting (what
 *               counts as the back face follows the winding, and its material is the back one);
 *               a sphere whose material has GL_SHININESS 128 and a spotlight with exponent 128
 *               (the limits of both ranges). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { CELL = 120, COLUMNS = 4, ROWS = 2, TEX = 16 };

static GLUquadric *quadric;

static void cell(int column, int row)
{
  glViewport(column * CELL, (ROWS - 1 - row) * CELL, CELL, CELL);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void light(GLenum l, float x, float y, float z, float w)
{
  const GLfloat position[4] = {x, y, z, w};
  glLightfv(l, GL_POSITION, position);
}

static void resetLight0(void)
{
  const GLfloat down[3] = {0.0f, 0.0f, -1.0f};
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0f);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0f);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.0f);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.0f);
}

static void material(float r, float g, float b, float shininess)
{
  const GLfloat diffuse[4] = {r, g, b, 1.0f};
  const GLfloat ambient[4] = {0.2f * r, 0.2f * g, 0.2f * b, 1.0f};
  const GLfloat specular[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

static void spotCell(int column, float w, float cutoff, float exponent)
{
  cell(column, 0);
  resetLight0();
  const GLfloat direction[3] = {-1.0f, -1.0f, -1.0f};
  light(GL_LIGHT0, 2.0f, 2.0f, 2.0f, w);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
  material(0.8f, 0.6f, 0.2f, 20.0f);
  gluSphere(quadric, 1.5, 48, 32);
}

static void makeTexture(void)
{
  static GLubyte texels[TEX][TEX][3];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      const int dark = ((i / 2) + (j / 2)) & 1;
      texels[j][i][0] = (GLubyte)(dark ? 60 : 230);
      texels[j][i][1] = (GLubyte)(dark ? 40 : 220);
      texels[j][i][2] = (GLubyte)(dark ? 120 : 200);
    }
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 20.0);
  quadric = gluNewQuadric();
  const GLfloat global[4] = {0.1f, 0.1f, 0.1f, 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global);

  /* Top row. */
  spotCell(0, 0.0f, 20.0f, 2.0f);
  spotCell(1, 1.0f, 180.0f, 50.0f);

  cell(2, 0);
  resetLight0();
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.1f);
  material(0.3f, 0.7f, 0.9f, 30.0f);
  glPushMatrix();
  glTranslatef(0.0f, 0.8f, 0.0f);
  light(GL_LIGHT0, -2.0f, 1.0f, 2.0f, 1.0f);
  gluSphere(quadric, 0.7, 32, 24);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.0f, -0.8f, 0.0f);
  light(GL_LIGHT0, -2.0f, 1.0f, 2.0f, 0.0f);
  gluSphere(quadric, 0.7, 32, 24);
  glPopMatrix();

  cell(3, 0);
  resetLight0();
  light(GL_LIGHT0, 1.0f, 1.0f, 3.0f, 0.0f);
  material(0.7f, 0.2f, 0.2f, 40.0f);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glPushMatrix();
  glTranslatef(1.2f, 0.9f, -1.0f);
  gluSphere(quadric, 0.8, 40, 30);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-1.0f, -1.0f, 0.0f);
  gluSphere(quadric, 0.8, 40, 30);
  glPopMatrix();
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);

  /* Bottom row: textured spheres, single and separate specular colour. */
  makeTexture();
  gluQuadricTexture(quadric, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  for (int i = 0; i < 2; ++i) {
    cell(i, 1);
    resetLight0();
    light(GL_LIGHT0, -1.0f, 1.5f, 3.0f, 0.0f);
    material(1.0f, 1.0f, 1.0f, 16.0f);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                  i == 0 ? GL_SINGLE_COLOR : GL_SEPARATE_SPECULAR_COLOR);
    glPushMatrix();
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    gluSphere(quadric, 1.5, 40, 30);
    glPopMatrix();
  }
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_TEXTURE_2D);
  gluQuadricTexture(quadric, GL_FALSE);

  /* An open tube, tilted towards the eye, wound clockwise for the front faces. */
  cell(2, 1);
  resetLight0();
  light(GL_LIGHT0, 1.0f, 2.0f, 3.0f, 0.0f);
  material(0.2f, 0.6f, 0.9f, 30.0f);
  const GLfloat backDiffuse[4] = {0.9f, 0.5f, 0.1f, 1.0f};
  glMaterialfv(GL_BACK, GL_DIFFUSE, backDiffuse);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glFrontFace(GL_CW);
  glPushMatrix();
  glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -1.2f);
  gluCylinder(quadric, 1.0, 1.0, 2.4, 40, 6);
  glPopMatrix();
  glFrontFace(GL_CCW);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

  /* The limits: shininess 128, spot exponent 128. */
  cell(3, 1);
  resetLight0();
  const GLfloat toward[3] = {-0.3f, -0.3f, -1.0f};
  light(GL_LIGHT0, 0.5f, 0.5f, 4.0f, 1.0f);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, toward);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128.0f);
  material(0.9f, 0.9f, 0.3f, 128.0f);
  gluSphere(quadric, 1.5, 48, 32);

  gluDeleteQuadric(quadric);
  glViewport(0, 0, COLUMNS * CELL, ROWS * CELL);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
