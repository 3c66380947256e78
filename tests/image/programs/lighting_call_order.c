/* Lighting state set in the orders real programs set it, which the specification defines but
 * which a renderer may get wrong when it caches: glColor before glEnable(GL_COLOR_MATERIAL)
 * followed by drawing with no further glColor; glMaterial between glBegin and glEnd (allowed:
 * it changes the material for the following vertices); normals of length 2 and 0.5 with neither
 * GL_NORMALIZE nor GL_RESCALE_NORMAL (the lit colour scales with the normal's length); a light
 * moved between two objects; a light's position given before glEnable(GL_LIGHTING) under another
 * matrix; and GL_SHININESS 0 with a specular material (the specular term is constant where
 * n . l > 0). */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 240 };

static void square(float x, float y, float normalLength)
{
  glBegin(GL_QUADS);
  glNormal3f(0.0f, 0.0f, normalLength);
  glVertex2f(x, y);
  glVertex2f(x + 0.8f, y);
  glVertex2f(x + 0.8f, y + 0.8f);
  glVertex2f(x, y + 0.8f);
  glEnd();
}

static void draw(void)
{
  static const GLfloat front[4] = {0.0f, 0.0f, 1.0f, 0.0f};
  static const GLfloat grey[4] = {0.4f, 0.4f, 0.4f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat red[4] = {1.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat green[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  static const GLfloat blue[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  static const GLfloat left[4] = {-3.0f, 0.0f, 2.0f, 1.0f};
  static const GLfloat right[4] = {3.0f, 0.0f, 2.0f, 1.0f};

  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.0, 4.0, -2.0, 2.0, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* The light position is given under a rotation, before lighting is enabled: it stays where
   * that matrix put it (pointing along +x rotated to +z). */
  glPushMatrix();
  glRotatef(-90.0f, 0.0f, 1.0f, 0.0f);
  {
    static const GLfloat alongX[4] = {1.0f, 0.0f, 0.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, alongX);
  }
  glPopMatrix();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);

  /* 1. glColor, then enable colour material, then draw without glColor. */
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glColor3f(0.9f, 0.6f, 0.1f);
  glEnable(GL_COLOR_MATERIAL);
  square(-3.8f, 1.0f, 1.0f);
  glDisable(GL_COLOR_MATERIAL);

  /* 2. glMaterial inside glBegin/glEnd: each vertex its own diffuse colour. */
  glBegin(GL_TRIANGLES);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glVertex2f(-2.8f, 1.0f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
  glVertex2f(-1.8f, 1.0f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glVertex2f(-2.3f, 1.9f);
  glEnd();

  /* 3. Unnormalized normals: brighter and darker than unit length. */
  glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
  square(-1.6f, 1.0f, 2.0f);
  square(-0.7f, 1.0f, 1.0f);
  square(0.2f, 1.0f, 0.5f);

  /* 4. Shininess 0 with specular: a constant specular term. */
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 0.0f);
  glPushMatrix();
  glTranslatef(1.8f, 1.1f, 0.0f);
  glutSolidSphere(0.6, 24, 16);
  glPopMatrix();
  glMaterialfv(GL_FRONT, GL_SPECULAR, black);

  /* 5. The light moved between two objects. */
  glLightfv(GL_LIGHT0, GL_POSITION, left);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  glPushMatrix();
  glTranslatef(-2.0f, -1.0f, 0.0f);
  glutSolidSphere(0.7, 24, 16);
  glPopMatrix();
  glLightfv(GL_LIGHT0, GL_POSITION, right);
  glPushMatrix();
  glTranslatef(0.0f, -1.0f, 0.0f);
  glutSolidSphere(0.7, 24, 16);
  glPopMatrix();

  /* 6. Back to a frontal light, colour material on GL_AMBIENT_AND_DIFFUSE from before the
   * enable, on a torus. */
  glLightfv(GL_LIGHT0, GL_POSITION, front);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glColor3f(0.3f, 0.5f, 1.0f);
  glEnable(GL_COLOR_MATERIAL);
  glPushMatrix();
  glTranslatef(2.4f, -1.0f, 0.0f);
  glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.2, 0.6, 16, 24);
  glPopMatrix();
  glDisable(GL_COLOR_MATERIAL);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
