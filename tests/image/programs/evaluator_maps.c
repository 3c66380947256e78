/* Evaluator maps the bezier_* programs leave out (section 5.1 of the GL 1.5 specification), in
 * four viewports:
 *   top left: a rational patch (GL_MAP2_VERTEX_4) with an explicit GL_MAP2_NORMAL map and a
 *     GL_MAP2_COLOR_4 map, lit with GL_COLOR_MATERIAL, so the evaluated colour drives the
 *     diffuse reflectance;
 *   top right: GL_MAP2_TEXTURE_COORD_1 into a 1D texture, on a grid whose ranges both run
 *     backwards (glMapGrid2f(n, 1, 0, m, 1, 0)), drawn by glEvalMesh2(GL_FILL) over part of it,
 *     with GL_MAP2_TEXTURE_COORD_3 enabled too (the higher dimension wins);
 *   bottom left: glEvalCoord2f and glEvalPoint2 mixed with glVertex in one quad strip; the
 *     evaluated colour must not become the current colour, so the plain vertices keep the colour
 *     set before;
 *   bottom right: one-dimensional colour, normal and texture coordinate maps (GL_MAP1_COLOR_4,
 *     GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_2) on lit wide lines drawn by glEvalMesh1 and
 *     glEvalCoord1f. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static const GLfloat patch[3][3][4] = {
    {{-1.2f, -1.0f, 0.0f, 1.0f}, {0.0f, -1.4f, 0.56f, 1.4f}, {1.2f, -1.0f, 0.0f, 1.0f}},
    {{-0.7f, 0.0f, 0.35f, 0.7f}, {0.0f, 0.0f, 0.5f, 0.5f}, {0.7f, 0.0f, 0.35f, 0.7f}},
    {{-1.2f, 1.0f, 0.0f, 1.0f}, {0.0f, 1.4f, 0.56f, 1.4f}, {1.2f, 1.0f, 0.0f, 1.0f}}};

static void panel(int column, int row)
{
  glViewport(column * WIDTH / 2, row * HEIGHT / 2, WIDTH / 2, HEIGHT / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)WIDTH / HEIGHT, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, -3.0, 3.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
}

static void light(void)
{
  static const GLfloat position[4] = {1.0f, -1.0f, 2.0f, 0.0f};
  static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
}

static void normalsAndColours(void)
{
  static const GLfloat normals[2][2][3] = {{{-0.6f, -0.5f, 1.0f}, {-0.6f, 0.5f, 1.0f}}, {{0.6f, -0.5f, 1.0f}, {0.6f, 0.5f, 1.0f}}};
  static const GLfloat colors[2][3][4] = {{{1.0f, 0.3f, 0.2f, 1.0f}, {0.9f, 0.9f, 0.2f, 1.0f}, {0.2f, 0.9f, 0.3f, 1.0f}},
                                          {{0.2f, 0.4f, 1.0f, 1.0f}, {0.8f, 0.3f, 0.9f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f}}};
  panel(0, 1);
  light();
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glMap2f(GL_MAP2_VERTEX_4, 0.0f, 1.0f, 4, 3, 0.0f, 1.0f, 12, 3, &patch[0][0][0]);
  glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &normals[0][0][0]);
  /* Colour: quadratic along v, linear along u. */
  glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 4, 3, 0.0f, 1.0f, 12, 2, &colors[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_NORMAL);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(16, 0.0f, 1.0f, 12, 0.0f, 1.0f);
  /* The mesh's quads run clockwise about the normals, which point towards the viewer. */
  glFrontFace(GL_CW);
  glEvalMesh2(GL_FILL, 0, 16, 0, 12);
  glFrontFace(GL_CCW);
  glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_MAP2_NORMAL);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
}

static void reversedGrid(void)
{
  static GLubyte ramp[16][3];
  static const GLfloat coords1[2][2][1] = {{{0.0f}, {1.0f}}, {{2.0f}, {3.0f}}};
  static const GLfloat coords3[2][2][3] = {{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, {{0.5f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}};
  for (int i = 0; i < 16; ++i) {
    ramp[i][0] = (GLubyte)(i * 16);
    ramp[i][1] = (GLubyte)(i % 2 ? 220 : 60);
    ramp[i][2] = (GLubyte)(255 - i * 16);
  }
  panel(1, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_1D);
  glMap2f(GL_MAP2_TEXTURE_COORD_1, 0.0f, 1.0f, 1, 2, 0.0f, 1.0f, 2, 2, &coords1[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &coords3[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_1);
  glEnable(GL_MAP2_TEXTURE_COORD_3);
  glMapGrid2f(10, 1.0f, 0.0f, 8, 1.0f, 0.0f);
  glEvalMesh2(GL_FILL, 1, 10, 0, 6);
  glDisable(GL_MAP2_TEXTURE_COORD_3);
  glEvalMesh2(GL_LINE, 0, 10, 6, 8);
  glDisable(GL_MAP2_TEXTURE_COORD_1);
  glDisable(GL_TEXTURE_1D);
}

static void mixedStrip(void)
{
  static const GLfloat colors[2][2][4] = {{{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 1.0f}}, {{0.0f, 0.0f, 1.0f, 1.0f}, {1.0f, 1.0f, 0.0f, 1.0f}}};
  panel(0, 0);
  glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 8, 2, &colors[0][0][0]);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(6, 0.0f, 1.0f, 4, 0.0f, 1.0f);
  glColor3f(0.9f, 0.9f, 0.9f);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 6; ++i) {
    if (i % 2 == 0) {
      glEvalPoint2(i, 0);
      glEvalCoord2f((float)i / 6.0f, 0.5f);
    } else {
      /* Plain vertices half way up, in the current (grey) colour. */
      glVertex3f(-1.2f + 2.4f * (float)i / 6.0f, -1.2f, 0.1f);
      glVertex3f(-1.2f + 2.4f * (float)i / 6.0f, 0.0f, 0.4f);
    }
  }
  glEnd();
  glEvalMesh2(GL_LINE, 0, 6, 2, 4);
  glPointSize(4.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i <= 6; ++i) glEvalPoint2(i, 4);
  glVertex3f(0.0f, 1.4f, 0.0f);
  glEnd();
  glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_MAP2_VERTEX_4);
}

static void curves(void)
{
  static const GLfloat points[4][3] = {{-1.5f, -1.0f, 0.0f}, {-0.5f, 1.5f, 0.3f}, {0.5f, -1.5f, 0.3f}, {1.5f, 1.0f, 0.0f}};
  static const GLfloat normals[3][3] = {{-1.0f, 0.0f, 0.3f}, {0.0f, -1.0f, 1.0f}, {1.0f, 0.0f, 0.3f}};
  static const GLfloat colors[2][4] = {{1.0f, 0.8f, 0.2f, 1.0f}, {0.2f, 0.6f, 1.0f, 1.0f}};
  static const GLfloat coords[2][2] = {{0.0f, 0.0f}, {4.0f, 1.0f}};
  static GLubyte stripes[8][8][3];
  for (int t = 0; t < 8; ++t)
    for (int s = 0; s < 8; ++s) {
      stripes[t][s][0] = (GLubyte)(s < 4 ? 250 : 30);
      stripes[t][s][1] = (GLubyte)(t < 4 ? 250 : 120);
      stripes[t][s][2] = 80;
    }
  panel(1, 0);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &points[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glMap1f(GL_MAP1_NORMAL, 0.0f, 1.0f, 3, 3, &normals[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &colors[0][0]);
  glEnable(GL_MAP1_NORMAL);
  glEnable(GL_MAP1_COLOR_4);
  light();
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glLineWidth(5.0f);
  glMapGrid1f(30, 0.0f, 1.0f);
  glEvalMesh1(GL_LINE, 0, 30);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
  glDisable(GL_MAP1_NORMAL);
  glDisable(GL_MAP1_COLOR_4);

  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 2, &coords[0][0]);
  glEnable(GL_MAP1_TEXTURE_COORD_2);
  glTranslatef(0.0f, 0.0f, -0.8f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 40; ++i) glEvalCoord1f((float)i / 40.0f);
  glEnd();
  glDisable(GL_MAP1_TEXTURE_COORD_2);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_MAP1_VERTEX_3);
  glLineWidth(1.0f);
}

static void draw(void)
{
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  normalsAndColours();
  reversedGrid();
  mixedStrip();
  curves();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
