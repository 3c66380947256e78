/* Lighting applies to lines and points too: wire GLUT shapes (glutWireSphere, glutWireTorus,
 * glutWireTeapot, glutWireCube) and a lit GL_POINTS cloud drawn with GL_LIGHTING enabled, as
 * students often leave it on. Each line vertex is lit with its own normal (freeglut supplies
 * them), so colours vary along the lines; smooth and flat shading side by side, two lights. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 240 };

static void shapes(void)
{
  static const GLfloat copper[4] = {0.9f, 0.5f, 0.3f, 1.0f};
  static const GLfloat sky[4] = {0.4f, 0.7f, 1.0f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  int i;
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, copper);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  glPushMatrix();
  glTranslatef(-1.2f, 0.7f, 0.0f);
  glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
  glutWireSphere(0.6, 18, 10);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.5f, 0.7f, 0.0f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glutWireTorus(0.15, 0.5, 10, 20);
  glPopMatrix();
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, sky);
  glPushMatrix();
  glTranslatef(-0.9f, -0.8f, 0.0f);
  glutWireTeapot(0.5);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.6f, -0.8f, 0.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glutWireCube(0.7);
  glPopMatrix();
  glPointSize(2.0f);
  glBegin(GL_POINTS);
  for (i = 0; i < 200; ++i) {
    const double a = i * 0.5, b = i * 0.173;
    const float nx = (float)(cos(a) * sin(b)), ny = (float)(sin(a) * sin(b)), nz = (float)cos(b);
    glNormal3f(nx, ny, nz);
    glVertex3f(1.5f + 0.35f * nx, 0.35f * ny, 0.35f * nz);
  }
  glEnd();
  glPointSize(1.0f);
}

static void draw(void)
{
  static const GLfloat key[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat fillPosition[4] = {-2.0f, -1.0f, 1.0f, 1.0f};
  static const GLfloat fill[4] = {0.3f, 0.2f, 0.5f, 1.0f};

  glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.0, 2.0, -2.0, 2.0, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT1, GL_POSITION, fillPosition);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);

  glViewport(0, 0, WIDTH / 2, HEIGHT);
  glShadeModel(GL_SMOOTH);
  shapes();
  glViewport(WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  glShadeModel(GL_FLAT);
  shapes();
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
