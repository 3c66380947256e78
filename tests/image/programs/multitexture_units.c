/* Multitexture (OpenGL 1.3, spec 2.7, 2.8, 3.8.17): texture units applied in order, each on the
 * previous unit's result. Six panels, left to right, top row first:
 *
 *   1. two units: a brick texture (unit 0) modulated by a lightmap (unit 1, its own coordinates)
 *   2. three units: 1, then an intensity texture blended with unit 2's own environment colour
 *   3. unit 1 with texture coordinate generation (OBJECT_LINEAR s, EYE_LINEAR t) and a rotated
 *      and scaled texture matrix, MIRRORED_REPEAT; inside glPushAttrib / glPopAttrib, which must
 *      undo all of it
 *   4. vertex arrays: one texture coordinate array per unit, chosen with glClientActiveTexture
 *   5. a display list that selects units, binds, enables, sets environments and coordinates
 *   6. lines and points carrying both units' coordinates, and a quad cut by a clip plane (the
 *      cut interpolates unit 1's coordinates too)
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { CELL = 160, COLUMNS = 3, ROWS = 2, GRID = 8 };

static GLuint bricks, lightmap, speckle;

static void linearFilters(void)
{
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void makeTextures(void)
{
  static GLubyte brick[32][32][3];
  static GLubyte light[16][16];
  static GLubyte dots[8][8];
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) {
      const int row = j / 8;
      const int shifted = (i + (row % 2) * 8) % 16;
      const int mortar = (j % 8 == 0) || (shifted == 0);
      brick[j][i][0] = (GLubyte)(mortar ? 200 : 170 + (i * 3) % 40);
      brick[j][i][1] = (GLubyte)(mortar ? 200 : 60 + (j * 5) % 30);
      brick[j][i][2] = (GLubyte)(mortar ? 190 : 40);
    }
  }
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const float dx = (i - 5.5f) / 8.0f, dy = (j - 9.5f) / 8.0f;
      const float v = 1.0f - 0.9f * (dx * dx + dy * dy);
      light[j][i] = (GLubyte)(255.0f * (v < 0.15f ? 0.15f : v > 1.0f ? 1.0f : v));
    }
  }
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) dots[j][i] = (GLubyte)(((i * 5 + j * 3) % 8) < 2 ? 255 : 0);

  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &bricks);
  glBindTexture(GL_TEXTURE_2D, bricks);
  linearFilters();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, brick);
  glGenTextures(1, &lightmap);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  linearFilters();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, light);
  glGenTextures(1, &speckle);
  glBindTexture(GL_TEXTURE_2D, speckle);
  linearFilters();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY, 8, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, dots);
  glBindTexture(GL_TEXTURE_2D, 0);
}

static void bindUnit(GLenum unit, GLuint texture, GLenum mode)
{
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)mode);
}

static void disableUnits(void)
{
  for (int u = 2; u >= 0; --u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glDisable(GL_TEXTURE_2D);
  }
}

/* A square of GRID x GRID quads; unit 0 takes (0..2, 0..2), units 1 and 2 (0..1, 0..1) and
 * (0..3, 0..3). Colours vary a little so that MODULATE shows the primary colour too. */
static void square(float x0, float y0, float size)
{
  const float step = size / GRID;
  for (int j = 0; j < GRID; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= GRID; ++i) {
      for (int k = 1; k >= 0; --k) {
        const float s = (float)i / GRID, t = (float)(j + k) / GRID;
        glColor3f(0.8f + 0.2f * s, 0.9f, 0.8f + 0.2f * t);
        glMultiTexCoord2f(GL_TEXTURE0, 2.0f * s, 2.0f * t);
        glMultiTexCoord2f(GL_TEXTURE1, s, t);
        glMultiTexCoord2f(GL_TEXTURE2, 3.0f * s, 3.0f * t);
        glVertex2f(x0 + i * step, y0 + (j + k) * step);
      }
    }
    glEnd();
  }
}

static void panelTwoUnits(float x0, float y0)
{
  bindUnit(GL_TEXTURE0, bricks, GL_MODULATE);
  bindUnit(GL_TEXTURE1, lightmap, GL_MODULATE);
  square(x0 + 10, y0 + 10, CELL - 20);
  disableUnits();
}

static void panelThreeUnits(float x0, float y0)
{
  const GLfloat blue[4] = {0.2f, 0.5f, 1.0f, 1.0f};
  bindUnit(GL_TEXTURE0, bricks, GL_MODULATE);
  bindUnit(GL_TEXTURE1, lightmap, GL_MODULATE);
  bindUnit(GL_TEXTURE2, speckle, GL_BLEND);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, blue);
  square(x0 + 10, y0 + 10, CELL - 20);
  disableUnits();
}

static void panelTexGen(float x0, float y0)
{
  const GLfloat sPlane[4] = {1.0f / 70.0f, 0.0f, 0.0f, -x0 / 70.0f};
  const GLfloat tPlane[4] = {0.0f, 1.0f / 70.0f, 0.0f, -y0 / 70.0f};
  glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT | GL_TRANSFORM_BIT);
  bindUnit(GL_TEXTURE0, bricks, GL_MODULATE);
  bindUnit(GL_TEXTURE1, lightmap, GL_MODULATE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_T, GL_EYE_PLANE, tPlane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glScalef(1.3f, 0.8f, 1.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  square(x0 + 10, y0 + 10, CELL - 20);
  glPopMatrix();
  /* The lightmap's wrap modes belong to the texture object; GL_TEXTURE_BIT restores them. */
  glPopAttrib();
}

static void panelArrays(float x0, float y0)
{
  enum { N = GRID + 1 };
  static GLfloat vertices[N * 2][2], base[N * 2][2], light[N * 2][2];
  const float size = CELL - 20, step = size / GRID;
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, base);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, light);
  bindUnit(GL_TEXTURE0, bricks, GL_REPLACE);
  bindUnit(GL_TEXTURE1, lightmap, GL_MODULATE);
  for (int j = 0; j < GRID; ++j) {
    for (int i = 0; i < N; ++i) {
      for (int k = 0; k < 2; ++k) {
        const float s = (float)i / GRID, t = (float)(j + 1 - k) / GRID;
        /* A wave in the lightmap's coordinates only. */
        vertices[2 * i + k][0] = x0 + 10 + i * step;
        vertices[2 * i + k][1] = y0 + 10 + (j + 1 - k) * step;
        base[2 * i + k][0] = 3.0f * s;
        base[2 * i + k][1] = 3.0f * t;
        light[2 * i + k][0] = s + 0.15f * sinf(6.0f * t);
        light[2 * i + k][1] = t;
      }
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 2 * N);
  }
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  disableUnits();
}

static void panelDisplayList(float x0, float y0)
{
  const GLfloat green[4] = {0.1f, 0.8f, 0.3f, 1.0f};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, speckle);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, green);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.9f, 0.6f);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
  glVertex2f(x0 + 10, y0 + 10);
  glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 4.0f, 0.0f);
  glVertex2f(x0 + CELL - 10, y0 + 10);
  glMultiTexCoord2f(GL_TEXTURE0, 0.5f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 2.0f, 4.0f);
  glVertex2f(x0 + CELL / 2, y0 + CELL - 10);
  glEnd();
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
  disableUnits();
}

static void panelLinesPoints(float x0, float y0)
{
  const GLdouble plane[4] = {-1.0, -1.0, 0.0, x0 + y0 + 1.2 * CELL};
  bindUnit(GL_TEXTURE0, bricks, GL_MODULATE);
  bindUnit(GL_TEXTURE1, lightmap, GL_MODULATE);
  glColor3f(1.0f, 1.0f, 1.0f);
  glLineWidth(3.0f);
  glBegin(GL_LINES);
  for (int i = 0; i < 6; ++i) {
    const float y = y0 + 12 + 8.0f * i;
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.1f * i);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.2f * i);
    glVertex2f(x0 + 10, y);
    glMultiTexCoord2f(GL_TEXTURE0, 2.0f, 0.1f * i);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.2f * i);
    glVertex2f(x0 + CELL - 10, y);
  }
  glEnd();
  glPointSize(5.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 12; ++i) {
    glMultiTexCoord2f(GL_TEXTURE0, 0.17f * i, 0.3f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.09f * i, 0.5f);
    glVertex2f(x0 + 14 + 12.0f * i, y0 + 62);
  }
  glEnd();
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
  glVertex2f(x0 + 10, y0 + 72);
  glMultiTexCoord2f(GL_TEXTURE0, 2.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
  glVertex2f(x0 + CELL - 10, y0 + 72);
  glMultiTexCoord2f(GL_TEXTURE0, 2.0f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 1.0f);
  glVertex2f(x0 + CELL - 10, y0 + CELL - 10);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 1.0f);
  glVertex2f(x0 + 10, y0 + CELL - 10);
  glEnd();
  glDisable(GL_CLIP_PLANE0);
  glLineWidth(1.0f);
  glPointSize(1.0f);
  disableUnits();
}

static void draw(void)
{
  glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, COLUMNS * CELL, 0.0, ROWS * CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  makeTextures();

  panelTwoUnits(0, CELL);
  panelThreeUnits(CELL, CELL);
  panelTexGen(2 * CELL, CELL);
  panelArrays(0, 0);
  panelDisplayList(CELL, 0);
  panelLinesPoints(2 * CELL, 0);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, COLUMNS * CELL, ROWS * CELL, draw);
}
