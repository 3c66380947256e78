/* GL_FLAT shading with every polygon primitive, lit and unlit: a lit triangle strip, fan, quad
 * strip and quads and a polygon, each vertex with its own normal and its own colour (colour
 * material), so the colour of each flat primitive is the lit colour of the vertex the
 * specification names (the last vertex of a triangle or strip triangle, the last of a fan
 * triangle, the last of a quad and of a quad-strip quad, the first of a polygon). Under them the
 * same primitives unlit with glColor per vertex. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 500, HEIGHT = 240 };

static void colour(int i)
{
  glColor3f(0.5f + 0.5f * (float)sin(i * 1.3), 0.5f + 0.5f * (float)sin(i * 2.1 + 1.0),
            0.5f + 0.5f * (float)sin(i * 0.7 + 2.0));
}

static void normal(int i)
{
  glNormal3f((float)sin(i * 0.9) * 0.7f, (float)cos(i * 1.7) * 0.5f, 1.0f);
}

static void shapes(void)
{
  int i;
  glBegin(GL_TRIANGLE_STRIP);
  for (i = 0; i < 8; ++i) {
    colour(i); normal(i);
    glVertex2f(10.0f + 12.0f * (float)i, (i % 2) ? 90.0f : 20.0f);
  }
  glEnd();

  glBegin(GL_TRIANGLE_FAN);
  colour(20); normal(20);
  glVertex2f(150.0f, 20.0f);
  for (i = 0; i < 7; ++i) {
    const double angle = 0.2 + i * 0.45;
    colour(21 + i); normal(21 + i);
    glVertex2f(150.0f + 70.0f * (float)cos(angle), 20.0f + 70.0f * (float)sin(angle));
  }
  glEnd();

  glBegin(GL_QUAD_STRIP);
  for (i = 0; i < 8; ++i) {
    colour(40 + i); normal(40 + i);
    glVertex2f(240.0f + 14.0f * (float)(i / 2), (i % 2) ? 95.0f - 4.0f * (float)i : 20.0f);
  }
  glEnd();

  glBegin(GL_QUADS);
  for (i = 0; i < 8; ++i) {
    static const float corner[4][2] = {{0, 0}, {30, 0}, {34, 30}, {-4, 34}};
    colour(60 + i); normal(60 + i);
    glVertex2f(310.0f + 40.0f * (float)(i / 4) + corner[i % 4][0],
               25.0f + 30.0f * (float)(i / 4) + corner[i % 4][1]);
  }
  glEnd();

  glBegin(GL_POLYGON);
  for (i = 0; i < 6; ++i) {
    const double angle = i * 3.14159265358979 / 3.0;
    colour(80 + i); normal(80 + i);
    glVertex2f(450.0f + 40.0f * (float)cos(angle), 55.0f + 40.0f * (float)sin(angle));
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {250.0f, 200.0f, 120.0f, 1.0f};
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -200.0, 200.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glPushMatrix();
  glTranslatef(0.0f, 120.0f, 0.0f);
  shapes();
  glPopMatrix();
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);

  shapes();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
