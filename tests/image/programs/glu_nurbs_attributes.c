/* GLU NURBS with more than a vertex map (GLU 1.3, sections 7.3 and 7.4), and the tessellator
 * mode's callbacks (section 7.6), in two viewports:
 *   left: a bicubic surface given together with a GL_MAP2_TEXTURE_COORD_2 NURBS of order 2 (its
 *     own knots and a 2 x 2 net, so the checkerboard repeats three times by two) and a
 *     GL_MAP2_COLOR_4 NURBS of order 3 that modulates it, sampled by GLU_DOMAIN_DISTANCE; below
 *     it a curve with a GL_MAP1_COLOR_4 map;
 *   right: the same surface and curve with GLU_NURBS_MODE GLU_NURBS_TESSELLATOR: the
 *     GLU_NURBS_BEGIN, GLU_NURBS_VERTEX, GLU_NURBS_COLOR and GLU_NURBS_END callbacks draw what
 *     GLU returns, the surface's primitives as outlines (glPolygonMode GL_LINE). */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 240, TEXTURE = 16 };

static GLfloat hill[4][4][3];

static void GLAPIENTRY beginCallback(GLenum type) { glBegin(type); }
static void GLAPIENTRY vertexCallback(GLfloat *vertex) { glVertex3fv(vertex); }
static void GLAPIENTRY colorCallback(GLfloat *color) { glColor4fv(color); }
static void GLAPIENTRY endCallback(void) { glEnd(); }

static void checker(void)
{
  static GLubyte texels[TEXTURE][TEXTURE];
  for (int t = 0; t < TEXTURE; ++t)
    for (int s = 0; s < TEXTURE; ++s) texels[t][s] = (GLubyte)(((s / 8) + (t / 8)) % 2 ? 110 : 255);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, TEXTURE, TEXTURE, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void shapes(GLUnurbsObj *nurb, int textured)
{
  static GLfloat knots[8] = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  static GLfloat linearKnots[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  static GLfloat quadraticKnots[6] = {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f};
  static GLfloat texCoords[2][2][2] = {{{0.0f, 0.0f}, {0.0f, 2.0f}}, {{3.0f, 0.0f}, {3.0f, 2.0f}}};
  static GLfloat colors[3][3][4] = {
      {{1.0f, 0.3f, 0.3f, 1.0f}, {1.0f, 0.8f, 0.3f, 1.0f}, {0.4f, 1.0f, 0.4f, 1.0f}},
      {{0.9f, 0.4f, 1.0f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f}, {0.3f, 0.9f, 0.9f, 1.0f}},
      {{0.3f, 0.4f, 1.0f, 1.0f}, {0.6f, 0.6f, 1.0f, 1.0f}, {1.0f, 0.5f, 0.8f, 1.0f}}};
  static GLfloat curve[4][3] = {{-2.0f, -3.2f, 0.0f}, {-0.7f, -1.6f, 0.0f}, {0.7f, -4.4f, 0.0f}, {2.0f, -2.8f, 0.0f}};
  static GLfloat curveColors[2][4] = {{1.0f, 0.9f, 0.2f, 1.0f}, {0.2f, 0.6f, 1.0f, 1.0f}};

  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  if (textured)
    gluNurbsSurface(nurb, 4, linearKnots, 4, linearKnots, 2 * 2, 2, &texCoords[0][0][0], 2, 2, GL_MAP2_TEXTURE_COORD_2);
  gluNurbsSurface(nurb, 6, quadraticKnots, 6, quadraticKnots, 3 * 4, 4, &colors[0][0][0], 3, 3, GL_MAP2_COLOR_4);
  gluEndSurface(nurb);

  glLineWidth(3.0f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 8, knots, 3, &curve[0][0], 4, GL_MAP1_VERTEX_3);
  gluNurbsCurve(nurb, 4, linearKnots, 4, &curveColors[0][0], 2, GL_MAP1_COLOR_4);
  gluEndCurve(nurb);
  glLineWidth(1.0f);
}

static void view(int column)
{
  glViewport(column * WIDTH / 2, 0, WIDTH / 2, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 0.5 * WIDTH / HEIGHT, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, -4.0, 7.0, 0.0, -1.2, 0.0, 0.0, 0.0, 1.0);
}

static void draw(void)
{
  GLUnurbsObj *nurb = gluNewNurbsRenderer();
  for (int u = 0; u < 4; ++u)
    for (int v = 0; v < 4; ++v) {
      hill[u][v][0] = 2.0f * ((GLfloat)u - 1.5f) / 1.5f;
      hill[u][v][1] = 2.0f * ((GLfloat)v - 1.5f) / 1.5f;
      hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 1.5f : -0.5f;
    }
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 12.0f);
  gluNurbsProperty(nurb, GLU_V_STEP, 9.0f);

  view(0);
  checker();
  glEnable(GL_TEXTURE_2D);
  shapes(nurb, 1);
  glDisable(GL_TEXTURE_2D);

  view(1);
  gluNurbsProperty(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsCallback(nurb, GLU_NURBS_BEGIN, (void(GLAPIENTRY *)(void))beginCallback);
  gluNurbsCallback(nurb, GLU_NURBS_VERTEX, (void(GLAPIENTRY *)(void))vertexCallback);
  gluNurbsCallback(nurb, GLU_NURBS_COLOR, (void(GLAPIENTRY *)(void))colorCallback);
  gluNurbsCallback(nurb, GLU_NURBS_END, (void(GLAPIENTRY *)(void))endCallback);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  shapes(nurb, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gluDeleteNurbsRenderer(nurb);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
