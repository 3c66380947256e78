/* Vertex arrays through many vertex-stage states, drawn with glDrawElements from a mesh of 525
 * shared vertices (more than glass's post-transform cache holds, so entries are replaced while a
 * draw runs, and indices 256 apart compete for one) and with glDrawArrays from the same mesh
 * unrolled into separate triangles. Six panels, left to right, top to bottom:
 *   1. two lights, a directional one and a positional one with attenuation, colour material
 *      (GL_AMBIENT_AND_DIFFUSE) from unsigned-byte colours, separate specular colour, GL_NORMALIZE
 *      under a non-uniform scale; glDrawElements
 *   2. a spotlight with a local viewer and two-sided lighting (the mesh is an open, wavy sheet
 *      seen from both sides), colour material on the front diffuse colour only, from float
 *      colours, GL_RESCALE_NORMAL; glDrawArrays
 *   3. texture coordinates from an array through the texture matrix, lit and modulated, with
 *      linear fog from a fog-coordinate array; glDrawElements
 *   4. unlit, flat shaded, a secondary colour array with GL_COLOR_SUM and a user clip plane;
 *      glDrawArrays of GL_TRIANGLE_STRIP, one strip for every other row
 *   5. polygon mode GL_LINE with an edge-flag array hiding the diagonals; glDrawArrays
 *   6. GL_LINE_STRIP and GL_POINTS through glDrawElements with repeated indices, lit by the
 *      current normal (no normal array) and the current colour
 * The GL calls are those any GL 1.4 program makes; glass's fast vertex path must give the same
 * picture as its per-vertex path (tests/image/fast_paths.cmake) and as Mesa. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 320, COLUMNS = 24, ROWS = 20 };
enum { VERTICES = (COLUMNS + 1) * (ROWS + 1), TRIANGLES = 2 * COLUMNS * ROWS };

static GLfloat positions[VERTICES][3], normals[VERTICES][3], texCoords[VERTICES][2];
static GLfloat fogCoords[VERTICES], floatColors[VERTICES][4];
static GLubyte byteColors[VERTICES][4], secondary[VERTICES][3], edgeFlags[3 * TRIANGLES];
static GLuint indices[3 * TRIANGLES];
static GLushort lineIndices[60];
/* The mesh unrolled: vertex k of the arrays is vertex indices[k] of the mesh. */
static GLfloat flatPositions[3 * TRIANGLES][3], flatNormals[3 * TRIANGLES][3];
static GLfloat flatColors[3 * TRIANGLES][4];
/* The mesh as one triangle strip per row: row j is v(j, 0), v(j + 1, 0), v(j, 1), v(j + 1, 1), ... */
enum { STRIP = 2 * (COLUMNS + 1) };
static GLfloat stripPositions[ROWS * STRIP][3];
static GLubyte stripColors[ROWS * STRIP][4], stripSecondary[ROWS * STRIP][3];

/* A wavy sheet, x and y in [-1, 1], its normals 1.7 times too long (GL_NORMALIZE or
 * GL_RESCALE_NORMAL must fix them). */
static void makeMesh(void)
{
  for (int j = 0; j <= ROWS; ++j)
    for (int i = 0; i <= COLUMNS; ++i) {
      const int v = j * (COLUMNS + 1) + i;
      const float x = -1.0f + 2.0f * (float)i / COLUMNS, y = -1.0f + 2.0f * (float)j / ROWS;
      const float z = 0.3f * sinf(3.0f * x) * cosf(2.5f * y);
      const float dzdx = 0.9f * cosf(3.0f * x) * cosf(2.5f * y);
      const float dzdy = -0.75f * sinf(3.0f * x) * sinf(2.5f * y);
      const float length = sqrtf(dzdx * dzdx + dzdy * dzdy + 1.0f) / 1.7f;
      positions[v][0] = x;
      positions[v][1] = y;
      positions[v][2] = z;
      normals[v][0] = -dzdx / length;
      normals[v][1] = -dzdy / length;
      normals[v][2] = 1.0f / length;
      texCoords[v][0] = 2.0f * (float)i / COLUMNS;
      texCoords[v][1] = 2.0f * (float)j / ROWS;
      fogCoords[v] = 4.0f * (float)j / ROWS;
      byteColors[v][0] = (GLubyte)(60 + 8 * i);
      byteColors[v][1] = (GLubyte)(240 - 9 * j);
      byteColors[v][2] = (GLubyte)(90 + 5 * (i + j));
      byteColors[v][3] = 255;
      floatColors[v][0] = 0.3f + 0.7f * (float)j / ROWS;
      floatColors[v][1] = 0.9f - 0.6f * (float)i / COLUMNS;
      floatColors[v][2] = 0.5f;
      floatColors[v][3] = 1.0f;
      secondary[v][0] = (GLubyte)(4 * i);
      secondary[v][1] = 0;
      secondary[v][2] = (GLubyte)(5 * j);
    }
  int k = 0;
  for (int j = 0; j < ROWS; ++j)
    for (int i = 0; i < COLUMNS; ++i) {
      const GLuint a = (GLuint)(j * (COLUMNS + 1) + i), b = a + 1, c = a + COLUMNS + 1, d = c + 1;
      const GLuint quad[6] = {a, b, d, a, d, c};
      for (int q = 0; q < 6; ++q, ++k) {
        indices[k] = quad[q];
        /* The diagonal a-d is the edge from the third vertex of (a, b, d) and from the first
         * of (a, d, c): those vertices' flags hide it. */
        edgeFlags[k] = (GLubyte)(q != 2 && q != 3);
      }
    }
  for (k = 0; k < 3 * TRIANGLES; ++k) {
    const GLuint v = indices[k];
    for (int c = 0; c < 3; ++c) {
      flatPositions[k][c] = positions[v][c];
      flatNormals[k][c] = normals[v][c];
    }
    for (int c = 0; c < 4; ++c) flatColors[k][c] = floatColors[v][c];
  }
  for (int j = 0; j < ROWS; ++j)
    for (k = 0; k < STRIP; ++k) {
      const int v = (j + k % 2) * (COLUMNS + 1) + k / 2, s = j * STRIP + k;
      for (int c = 0; c < 3; ++c) {
        stripPositions[s][c] = positions[v][c];
        stripSecondary[s][c] = secondary[v][c];
      }
      for (int c = 0; c < 4; ++c) stripColors[s][c] = byteColors[v][c];
    }
  /* Back and forth over a row, and across rows 256 vertices apart. */
  for (k = 0; k < 60; ++k) lineIndices[k] = (GLushort)((k % 2 ? 256 : 0) + (k % 25) * 3 + k / 25);
}

/* Panel p of a 3 x 2 grid: a viewport and a modelview for it. */
static void panel(int p, float angle)
{
  const int w = WIDTH / 3, h = HEIGHT / 2;
  glViewport((p % 3) * w, (1 - p / 3) * h, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.2f);
  glRotatef(angle, 1.0f, 0.3f, 0.0f);
}

/* After a draw with a colour array the current colour, and the material colour material made
 * track it, are undefined (spec 2.8), so every panel starts from stated materials. */
static void resetState(void)
{
  static const GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  static const GLfloat diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  static const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glDisable(GL_LIGHTING);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_NORMALIZE);
  glDisable(GL_RESCALE_NORMAL);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_FOG);
  glDisable(GL_COLOR_SUM);
  glDisable(GL_CLIP_PLANE0);
  glShadeModel(GL_SMOOTH);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_FOG_COORDINATE_ARRAY);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
}

static void twoLights(void)
{
  static const GLfloat direction[4] = {-0.5f, 0.6f, 0.8f, 0.0f};
  static const GLfloat lamp[4] = {1.5f, -1.0f, 1.5f, 1.0f};
  static const GLfloat warm[4] = {0.9f, 0.6f, 0.3f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  panel(0, -35.0f);
  glLightfv(GL_LIGHT0, GL_POSITION, direction);
  glLightfv(GL_LIGHT1, GL_POSITION, lamp);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
  glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.3f);
  glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.1f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glScalef(1.2f, 0.8f, 1.5f);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glNormalPointer(GL_FLOAT, 0, normals);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, byteColors);
  glDrawElements(GL_TRIANGLES, 3 * TRIANGLES, GL_UNSIGNED_INT, indices);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHT1);
}

static void spotlight(void)
{
  static const GLfloat spotPosition[4] = {0.0f, 0.0f, 2.0f, 1.0f};
  static const GLfloat spotDirection[3] = {0.1f, 0.2f, -1.0f};
  static const GLfloat backColor[4] = {0.3f, 0.4f, 0.9f, 1.0f};
  panel(1, 55.0f);
  glPushMatrix();
  glLoadIdentity();
  glLightfv(GL_LIGHT1, GL_POSITION, spotPosition);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spotDirection);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f);
  glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 6.0f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.0f);
  glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.02f);
  glPopMatrix();
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, backColor);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHTING);
  glEnable(GL_RESCALE_NORMAL);
  glScalef(0.9f, 0.9f, 0.9f);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, flatPositions);
  glNormalPointer(GL_FLOAT, 0, flatNormals);
  glColorPointer(4, GL_FLOAT, 0, flatColors);
  glDrawArrays(GL_TRIANGLES, 0, 3 * TRIANGLES);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
  glDisable(GL_LIGHT1);
}

static void texturedFog(void)
{
  static GLubyte texels[8][8][3];
  static const GLfloat fogColor[4] = {0.6f, 0.6f, 0.7f, 1.0f};
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int check = (i + j) % 2;
      texels[j][i][0] = (GLubyte)(check ? 250 : 40);
      texels[j][i][1] = (GLubyte)(check ? 220 : 90);
      texels[j][i][2] = (GLubyte)(check ? 120 : 200);
    }
  panel(2, -20.0f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_TEXTURE);
  glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 5.0f);
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glEnable(GL_FOG);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_FOG_COORDINATE_ARRAY);
  glNormalPointer(GL_FLOAT, 0, normals);
  glTexCoordPointer(2, GL_FLOAT, 0, texCoords);
  glFogCoordPointer(GL_FLOAT, 0, fogCoords);
  glDrawElements(GL_TRIANGLES, 3 * TRIANGLES, GL_UNSIGNED_INT, indices);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
}

static void flatClipped(void)
{
  static const GLdouble plane[4] = {1.0, 0.6, 0.0, 0.3};
  panel(3, 10.0f);
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glShadeModel(GL_FLAT);
  glEnable(GL_COLOR_SUM);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, stripPositions);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, stripColors);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, stripSecondary);
  for (int j = 0; j < ROWS; j += 2) glDrawArrays(GL_TRIANGLE_STRIP, j * STRIP, STRIP);
  glVertexPointer(3, GL_FLOAT, 0, positions);
}

static void edgeFlagged(void)
{
  panel(4, 30.0f);
  glColor3f(0.9f, 0.9f, 0.3f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, flatPositions);
  glEdgeFlagPointer(0, edgeFlags);
  glDrawArrays(GL_TRIANGLES, 0, 3 * TRIANGLES / 2);
  glVertexPointer(3, GL_FLOAT, 0, positions);
}

static void linesAndPoints(void)
{
  panel(5, -45.0f);
  glColor3f(0.4f, 0.9f, 0.6f);
  glNormal3f(0.0f, 0.3f, 1.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glPointSize(3.0f);
  glDrawElements(GL_LINE_STRIP, 60, GL_UNSIGNED_SHORT, lineIndices);
  glDrawElements(GL_POINTS, 60, GL_UNSIGNED_SHORT, lineIndices);
}

static void draw(void)
{
  makeMesh();
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  resetState();
  twoLights();
  resetState();
  spotlight();
  resetState();
  texturedFog();
  resetState();
  flatClipped();
  resetState();
  edgeFlagged();
  resetState();
  linesAndPoints();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
