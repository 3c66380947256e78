/* Immediate mode with every attribute a vertex can carry changing between glBegin and glEnd, the
 * way programs send them: what the vertex stage must see of each glVertex is the current state at
 * that call, whether it processes vertices one at a time or gathers them into batches.
 *
 * - Top: a lit, two-sided wavy strip of 2 x 90 vertices (more than one batch of 64) with a
 *   colour and a normal per vertex, colour material tracking ambient and diffuse on both faces;
 *   a glMaterial of the specular colour and shininess and of the emission in the middle of the
 *   strip (the vertices before it keep the old material), and a glColor after its last vertex.
 * - Middle left: glPopAttrib of GL_LIGHTING_BIT brings back a material of another colour than
 *   the current one; a fan with no glColor inside, then one whose second half has glColor.
 * - Middle right: glEvalCoord1 of a colour and vertex map and glArrayElement inside glBegin/glEnd,
 *   between plain glVertex calls, in one line strip and one triangle strip.
 * - Bottom left: unlit quads with two texture units and their own coordinates per vertex; the
 *   first two fogged by glFogCoord per vertex, the other two with a secondary colour per vertex
 *   summed in (GL_COLOR_SUM).
 * - Bottom right: a polygon in GL_LINE mode with an edge flag per vertex (hidden edges). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300, STRIP_COLUMNS = 90, TEXTURE_SIZE = 8 };

static void setUpLights(void)
{
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat half[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  static const GLfloat dim[4] = {0.4f, 0.4f, 0.5f, 1.0f};
  static const GLfloat sun[4] = {-0.3f, 0.5f, 1.0f, 0.0f};
  static const GLfloat lamp[4] = {2.0f, -1.0f, 2.5f, 1.0f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT0, GL_POSITION, sun);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, half);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightfv(GL_LIGHT1, GL_POSITION, lamp);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
  glLightfv(GL_LIGHT1, GL_SPECULAR, dim);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
}

/* The wavy strip: it turns over along its length, so both faces show. */
static void litStrip(void)
{
  static const GLfloat shiny[4] = {0.9f, 0.9f, 0.6f, 1.0f};
  static const GLfloat glow[4] = {0.15f, 0.0f, 0.2f, 1.0f};
  int i;
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10.0f);
  glBegin(GL_TRIANGLE_STRIP);
  for (i = 0; i < STRIP_COLUMNS; ++i) {
    const float u = (float)i / (STRIP_COLUMNS - 1);
    const float x = -3.6f + 7.2f * u, twist = 2.6f * u;
    const float ny = (float)sin(twist), nz = (float)cos(twist);
    if (i == STRIP_COLUMNS / 2) {
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, shiny);
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
      glMaterialfv(GL_FRONT, GL_EMISSION, glow);
    }
    glNormal3f(0.2f * (float)cos(6.0f * u), ny, nz);
    glColor3f(0.3f + 0.7f * u, 0.8f - 0.6f * u, 0.4f + 0.3f * (float)sin(9.0f * u));
    glVertex3f(x, 1.45f + 0.45f * nz, 0.45f * ny);
    glColor3f(0.9f - 0.5f * u, 0.3f + 0.5f * u, 0.6f);
    glVertex3f(x, 1.45f - 0.45f * nz, -0.45f * ny);
  }
  glColor3f(1.0f, 1.0f, 1.0f); /* after the last vertex: lights nothing of the strip */
  glEnd();
}

static void fan(float cx, float cy, int colouredFrom)
{
  int i;
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0.0f, 0.3f, 1.0f);
  glVertex3f(cx, cy, 0.0f);
  for (i = 0; i <= 10; ++i) {
    const double angle = 3.14159265358979 * i / 5.0;
    if (i >= colouredFrom) glColor3f(0.2f, 0.4f + 0.05f * (float)i, 0.9f);
    glVertex3f(cx + 0.55f * (float)cos(angle), cy + 0.45f * (float)sin(angle), 0.0f);
  }
  glEnd();
}

/* The pop brings back the material of the ochre colour while the current colour stays red: the
 * tracked ambient and diffuse follow the current colour (red), so the first fan is lit red and
 * the second turns to its own colours half way round. */
static void poppedMaterial(void)
{
  static const GLfloat matte[4] = {0.1f, 0.1f, 0.1f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, matte);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
  glColor3f(0.7f, 0.6f, 0.1f);
  glPushAttrib(GL_LIGHTING_BIT);
  glColor3f(0.8f, 0.1f, 0.1f);
  glPopAttrib();
  fan(-2.9f, 0.0f, 100);
  fan(-1.6f, 0.0f, 5);
}

static void evaluatedAndArrayVertices(void)
{
  static const GLfloat controlPoints[3][3] = {{0.4f, -0.4f, 0.0f}, {1.4f, 0.9f, 0.0f}, {2.4f, -0.4f, 0.0f}};
  static const GLfloat controlColors[2][4] = {{1.0f, 0.2f, 0.2f, 1.0f}, {0.2f, 0.3f, 1.0f, 1.0f}};
  static const GLfloat arrayPositions[3][3] = {{2.9f, -0.5f, 0.0f}, {3.3f, 0.6f, 0.0f}, {3.6f, -0.3f, 0.0f}};
  static const GLubyte arrayColors[3][4] = {{255, 255, 0, 255}, {0, 255, 128, 255}, {255, 0, 255, 255}};
  int i;
  glDisable(GL_LIGHTING);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 3, &controlPoints[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &controlColors[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glVertexPointer(3, GL_FLOAT, 0, arrayPositions);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, arrayColors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glLineWidth(2.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINE_STRIP);
  glVertex3f(0.2f, -0.9f, 0.0f);
  for (i = 0; i <= 20; ++i) glEvalCoord1f((float)i / 20.0f);
  glArrayElement(0);
  glArrayElement(1);
  glVertex3f(3.8f, 0.9f, 0.0f); /* in the colour glArrayElement(1) left current */
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  glColor3f(0.5f, 0.5f, 0.5f);
  glVertex3f(0.6f, -1.0f, 0.0f);
  glEvalCoord1f(0.25f);
  glArrayElement(2);
  glEvalCoord1f(0.75f);
  glVertex3f(3.0f, -1.1f, 0.0f);
  glEnd();
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisable(GL_MAP1_VERTEX_3);
  glDisable(GL_MAP1_COLOR_4);
  glLineWidth(1.0f);
}

static void makeTexture(GLuint name, int period, const GLubyte a[3], const GLubyte b[3])
{
  GLubyte texels[TEXTURE_SIZE][TEXTURE_SIZE][3];
  int s, t, c;
  for (t = 0; t < TEXTURE_SIZE; ++t)
    for (s = 0; s < TEXTURE_SIZE; ++s)
      for (c = 0; c < 3; ++c) texels[t][s][c] = ((s / period + t / period) % 2) ? a[c] : b[c];
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEXTURE_SIZE, TEXTURE_SIZE, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
}

static void foggedTexturedQuads(void)
{
  static const GLubyte light[3] = {240, 240, 220}, dark[3] = {90, 90, 120};
  static const GLubyte red[3] = {255, 160, 160}, white[3] = {255, 255, 255};
  static const GLfloat fogColor[4] = {0.6f, 0.7f, 0.8f, 1.0f};
  GLuint textures[2];
  int i;
  glGenTextures(2, textures);
  glActiveTexture(GL_TEXTURE0);
  makeTexture(textures[0], 2, light, dark);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  makeTexture(textures[1], 4, red, white);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  for (i = 0; i < 4; ++i) {
    const float x0 = -3.15f + 0.8f * (float)i, x1 = x0 + 0.75f;
    /* Fog on the first two, the colour sum on the other two. */
    if (i < 2) glEnable(GL_FOG); else glDisable(GL_FOG);
    if (i < 2) glDisable(GL_COLOR_SUM); else glEnable(GL_COLOR_SUM);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f - 0.2f * (float)i, 0.8f);
    glSecondaryColor3f(0.0f, 0.05f * (float)i, 0.25f);
    glFogCoordf(1.5f * (float)i);
    glMultiTexCoord2f(GL_TEXTURE0, 0.03f, 0.06f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.02f, 0.03f);
    glVertex3f(x0, -2.1f, 0.0f);
    glFogCoordf(1.5f * (float)i + 6.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.97f, 0.06f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.51f, 0.27f);
    glVertex3f(x1, -2.1f, 0.0f);
    glSecondaryColor3f(0.3f, 0.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.97f, 0.94f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.98f, 0.97f);
    glVertex3f(x1, -1.0f, 0.0f);
    glFogCoordf(0.5f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.03f, 0.94f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.26f, 0.77f);
    glVertex3f(x0, -1.0f, 0.0f);
    glEnd();
  }
  glDisable(GL_COLOR_SUM);
  glDisable(GL_FOG);
  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(2, textures);
}

/* A hexagon outline with every other edge hidden by its edge flag. */
static void flaggedOutline(void)
{
  int i;
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(1.0f, 0.9f, 0.3f);
  glBegin(GL_POLYGON);
  for (i = 0; i < 6; ++i) {
    const double angle = 3.14159265358979 * i / 3.0;
    glEdgeFlag(i % 2 == 0 ? GL_TRUE : GL_FALSE);
    glVertex3f(2.2f + 0.8f * (float)cos(angle), -1.6f + 0.6f * (float)sin(angle), 0.0f);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

static void draw(void)
{
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.375, 0.375, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -6.5f);

  setUpLights();
  litStrip();
  poppedMaterial();
  evaluatedAndArrayVertices();
  foggedTexturedQuads();
  flaggedOutline();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
