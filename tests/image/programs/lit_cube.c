/* The first lit program of every course: one frame of a rotating cube. The cube is drawn face
 * by face with GL_QUADS and one normal per face (flat faces under smooth shading), back faces
 * culled, lit by a positional white light with a specular highlight, in perspective. A second,
 * smaller cube (glutSolidCube) spins on its own axis beside it under GL_FLAT shading, and the
 * frame is drawn at the angles a timer would have reached after a few seconds (37 and 23.5
 * degrees), so that three faces of each cube show. */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/glut.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 240 };

static void unitCube(void)
{
  static const GLfloat normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                        {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  /* Counter-clockwise seen from outside. */
  static const GLfloat corners[6][4][3] = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
      {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
      {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
      {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
      {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
      {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}};
  int face, corner;
  glBegin(GL_QUADS);
  for (face = 0; face < 6; ++face) {
    glNormal3fv(normals[face]);
    for (corner = 0; corner < 4; ++corner) glVertex3fv(corners[face][corner]);
  }
  glEnd();
}

static void draw(void)
{
  static const GLfloat lightPosition[4] = {3.0f, 4.0f, 5.0f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat red[4] = {0.8f, 0.1f, 0.1f, 1.0f};
  static const GLfloat blue[4] = {0.15f, 0.3f, 0.9f, 1.0f};
  static const GLfloat gray[4] = {0.6f, 0.6f, 0.6f, 1.0f};

  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (GLdouble)WIDTH / (GLdouble)HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -7.0f);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, gray);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);

  glPushMatrix();
  glTranslatef(-0.9f, 0.0f, 0.0f);
  glRotatef(37.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(23.5f, 0.0f, 1.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  unitCube();
  glPopMatrix();

  glShadeModel(GL_FLAT);
  glPushMatrix();
  glTranslatef(1.9f, 0.6f, -1.0f);
  glRotatef(-23.5f, 1.0f, 1.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  glutSolidCube(1.2);
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
