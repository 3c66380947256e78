/* Display lists reused many times, as in the classic torus and list demos: a torus built by hand
 * (quad strips with normals) compiled once with GL_COMPILE and called in a 5 x 3 grid with
 * different transforms and materials set outside the list; a list that changes state (colour,
 * line width, shade model) and is called between others, and must leave that state changed; a
 * nested list that calls another list; glCallLists with a glListBase offset drawing a row of
 * digits-like glyphs from GL_UNSIGNED_BYTE names; a list made with GL_COMPILE_AND_EXECUTE; and a
 * glDeleteLists'ed name that glCallList must ignore. */
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 320 };

static void torus(int sides, int rings)
{
  const double pi = 3.14159265358979;
  int i, j, k;
  for (i = 0; i < sides; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= rings; ++j) {
      for (k = 1; k >= 0; --k) {
        const double s = (i + k) % sides + 0.5;
        const double t = j % rings;
        const double phi = s * 2.0 * pi / sides, theta = t * 2.0 * pi / rings;
        const double x = (1.0 + 0.35 * cos(phi)) * cos(theta);
        const double y = (1.0 + 0.35 * cos(phi)) * sin(theta);
        const double z = 0.35 * sin(phi);
        glNormal3d(cos(phi) * cos(theta), cos(phi) * sin(theta), sin(phi));
        glVertex3d(x, y, z);
      }
    }
    glEnd();
  }
}

static void glyph(int n)
{
  /* A glyph: n + 1 short bars in a fan, then translate to the next position. */
  int i;
  glBegin(GL_LINES);
  for (i = 0; i <= n; ++i) {
    glVertex2f(0.0f, 0.0f);
    glVertex2f(0.3f * (float)cos(0.35 * i), 0.3f * (float)sin(0.35 * i));
  }
  glEnd();
  glTranslatef(0.45f, 0.0f, 0.0f);
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {0.0f, 1.0f, 2.0f, 0.0f};
  GLuint torusList, stateList, nestedList, glyphBase, immediateList, dead;
  static const GLubyte text[] = {3, 1, 4, 1, 5, 9, 2, 6};
  int row, column, i;

  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  torusList = glGenLists(1);
  glNewList(torusList, GL_COMPILE);
  torus(12, 24);
  glEndList();

  stateList = glGenLists(1);
  glNewList(stateList, GL_COMPILE);
  glColor3f(1.0f, 0.9f, 0.2f);
  glLineWidth(2.0f);
  glShadeModel(GL_FLAT);
  glEndList();

  nestedList = glGenLists(1);
  glNewList(nestedList, GL_COMPILE);
  glPushMatrix();
  glScalef(0.5f, 0.5f, 0.5f);
  glCallList(torusList);
  glPopMatrix();
  glEndList();

  glyphBase = glGenLists(10);
  for (i = 0; i < 10; ++i) {
    glNewList(glyphBase + (GLuint)i, GL_COMPILE);
    glyph(i);
    glEndList();
  }

  dead = glGenLists(1);
  glNewList(dead, GL_COMPILE);
  glColor3f(1.0f, 0.0f, 0.0f);
  glRectf(-10.0f, -10.0f, 10.0f, 10.0f);
  glEndList();
  glDeleteLists(dead, 1);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-5.0, 5.0, -4.0, 4.0, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  for (row = 0; row < 3; ++row) {
    for (column = 0; column < 5; ++column) {
      glColor3f(0.3f + 0.15f * (float)column, 0.8f - 0.25f * (float)row, 0.5f);
      glPushMatrix();
      glTranslatef(-4.0f + 2.0f * (float)column, 3.0f - 2.0f * (float)row, 0.0f);
      glRotatef(25.0f * (float)(row * 5 + column), 1.0f, 0.5f, 0.0f);
      glScalef(0.65f, 0.65f, 0.65f);
      glEnable(GL_NORMALIZE);
      if ((row + column) % 3 == 2)
        glCallList(nestedList);
      else
        glCallList(torusList);
      glPopMatrix();
    }
  }
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);

  /* The state list: its colour, line width and flat shading stay after the call. */
  glCallList(stateList);
  glCallList(dead);
  glPushMatrix();
  glTranslatef(-4.2f, -3.0f, 0.0f);
  glListBase(glyphBase);
  glCallLists(8, GL_UNSIGNED_BYTE, text);
  glPopMatrix();
  glBegin(GL_TRIANGLES);
  glColor3f(0.2f, 0.9f, 0.9f);
  glVertex2f(0.5f, -3.6f);
  glColor3f(0.9f, 0.2f, 0.9f);
  glVertex2f(1.5f, -3.6f);
  glColor3f(0.9f, 0.9f, 0.2f);
  glVertex2f(1.0f, -2.6f);
  glEnd();

  immediateList = glGenLists(1);
  glShadeModel(GL_SMOOTH);
  glLineWidth(1.0f);
  glPushMatrix();
  glTranslatef(3.0f, -3.1f, 0.0f);
  glNewList(immediateList, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(0.0f, 0.0f);
  for (i = 0; i <= 6; ++i) {
    glColor3f((float)(i % 2), 0.3f, (float)((i + 1) % 2));
    glVertex2f(0.6f * (float)cos(i * 3.14159265358979 / 3.0),
               0.6f * (float)sin(i * 3.14159265358979 / 3.0));
  }
  glEnd();
  glEndList();
  glTranslatef(-1.4f, 0.0f, 0.0f);
  glCallList(immediateList);
  glPopMatrix();

  glDeleteLists(torusList, 1);
  glDeleteLists(glyphBase, 10);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
