/* A bicubic Bezier patch (glMap2 with GL_MAP2_VERTEX_3) drawn by glEvalMesh2(GL_FILL) with
 * GL_AUTO_NORMAL and two-sided lighting (section 5.1 of the GL 1.5 specification).
 *
 * The automatic normal is dp/du x dp/dv, normalized; here u runs along x and v along y, so the
 * normals point up, towards the viewer and the light. glEvalMesh2's quads run clockwise about the
 * automatic normal, so the side the normals point to is the back side for glFrontFace(GL_CCW):
 * both copies are drawn with glFrontFace(GL_CW). The large patch shows its front (gold) where its
 * folds face the viewer and its back where they turn away; the smaller copy is turned upside down
 * and shows its back (blue), lit with the reversed normal as GL_LIGHT_MODEL_TWO_SIDE asks. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

/* Rows along u, 4 x 4 points of 3 coordinates. */
static const GLfloat controlPoints[4][4][3] = {
    {{-1.5f, -1.5f, 1.2f}, {-0.5f, -1.5f, -0.4f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 0.6f}},
    {{-1.5f, -0.5f, -0.8f}, {-0.5f, -0.5f, 0.9f}, {0.5f, -0.5f, 0.3f}, {1.5f, -0.5f, -1.2f}},
    {{-1.5f, 0.5f, 1.5f}, {-0.5f, 0.5f, -0.6f}, {0.5f, 0.5f, 2.2f}, {1.5f, 0.5f, 0.9f}},
    {{-1.5f, 1.5f, -1.4f}, {-0.5f, 1.5f, 1.6f}, {0.5f, 1.5f, -0.5f}, {1.5f, 1.5f, 1.8f}}};

static void lights(void)
{
  static const GLfloat position[4] = {2.0f, 3.0f, 4.0f, 0.0f};
  static const GLfloat ambient[4] = {0.15f, 0.15f, 0.15f, 1.0f};
  static const GLfloat gold[4] = {0.85f, 0.65f, 0.2f, 1.0f};
  static const GLfloat blue[4] = {0.25f, 0.45f, 0.9f, 1.0f};
  static const GLfloat grey[4] = {0.35f, 0.35f, 0.35f, 1.0f};
  static const GLfloat diffuse[4] = {0.75f, 0.75f, 0.75f, 1.0f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, diffuse);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, grey);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
}

static void draw(void)
{
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE); /* the smaller copy is scaled */
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  lights(); /* the light is placed in eye coordinates */
  gluLookAt(0.0, -7.0, 4.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);

  glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &controlPoints[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(20, 0.0f, 1.0f, 20, 0.0f, 1.0f);

  glFrontFace(GL_CW);
  glPushMatrix();
  glTranslatef(-0.9f, 0.0f, 0.0f);
  glRotatef(-25.0f, 0.0f, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 20, 0, 20);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.3f, 1.5f, 0.3f);
  glScalef(0.5f, 0.5f, 0.5f);
  glRotatef(60.0f, 0.0f, 0.0f, 1.0f);
  glRotatef(180.0f, 1.0f, 0.0f, 0.0f);
  glEvalMesh2(GL_FILL, 0, 20, 0, 20);
  glPopMatrix();
  glFrontFace(GL_CCW);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
