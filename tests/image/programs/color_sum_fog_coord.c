/* OpenGL 1.4's secondary colour and fog coordinate, and glDrawBuffer(GL_NONE):
 * - colour sum (spec 3.9): unlit quads with a modulated checker texture and a glSecondaryColor
 *   (per vertex, and from a secondary colour array) added after texturing when GL_COLOR_SUM is
 *   enabled, and the same quads with it disabled;
 * - fog coordinates (3.10): GL_FOG_COORDINATE_SOURCE GL_FOG_COORDINATE with glFogCoord per vertex
 *   (and from a fog coordinate array) across quads at the same depth, linear and exponential fog,
 *   next to fog from the fragment depth;
 * - glDrawBuffer(GL_NONE): a quad drawn then leaves the colours alone but writes depth, which
 *   hides a later quad behind it; glClear of colour does nothing. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 400, HEIGHT = 300 };

static void checker(void)
{
  static GLubyte texels[8][8][3];
  GLuint name;
  int i, j;
  for (i = 0; i < 8; ++i)
    for (j = 0; j < 8; ++j) {
      const GLubyte v = ((i + j) % 2) ? 230 : 90;
      texels[i][j][0] = v;
      texels[i][j][1] = v;
      texels[i][j][2] = (GLubyte)(v / 2);
    }
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void texturedQuad(float x, float y, int colorSum)
{
  if (colorSum) glEnable(GL_COLOR_SUM);
  glBegin(GL_QUADS);
  glColor3f(0.9f, 0.6f, 0.6f);
  glSecondaryColor3f(0.0f, 0.0f, 0.5f);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(x, y);
  glSecondaryColor3f(0.5f, 0.0f, 0.0f);
  glTexCoord2f(1.0f, 0.0f);
  glVertex2f(x + 80.0f, y);
  glSecondaryColor3f(0.0f, 0.6f, 0.0f);
  glTexCoord2f(1.0f, 1.0f);
  glVertex2f(x + 80.0f, y + 80.0f);
  glSecondaryColor3f(0.3f, 0.3f, 0.3f);
  glTexCoord2f(0.0f, 1.0f);
  glVertex2f(x, y + 80.0f);
  glEnd();
  glDisable(GL_COLOR_SUM);
}

static void arrayQuad(float x, float y)
{
  static const GLfloat positions[8] = {0, 0, 80, 0, 80, 80, 0, 80};
  static const GLfloat texcoords[8] = {0, 0, 2, 0, 2, 2, 0, 2};
  static const GLubyte secondary[12] = {200, 0, 0, 0, 200, 0, 0, 0, 200, 100, 100, 0};
  glPushMatrix();
  glTranslatef(x, y, 0.0f);
  glColor3f(0.5f, 0.5f, 0.9f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, secondary);
  glEnable(GL_COLOR_SUM);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisable(GL_COLOR_SUM);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glPopMatrix();
}

static void fogQuad(float x, float y, GLenum mode, int coordinates)
{
  static const GLfloat fogColor[4] = {0.8f, 0.85f, 0.9f, 1.0f};
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, (GLint)mode);
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogf(GL_FOG_DENSITY, 0.25f);
  glFogi(GL_FOG_COORDINATE_SOURCE, coordinates ? GL_FOG_COORDINATE : GL_FRAGMENT_DEPTH);
  glBegin(GL_QUADS);
  glColor3f(0.8f, 0.2f, 0.1f);
  glFogCoordf(0.0f);
  glVertex3f(x, y, -1.0f);
  glFogCoordf(10.0f);
  glVertex3f(x + 80.0f, y, -1.0f);
  glColor3f(0.1f, 0.3f, 0.8f);
  glFogCoordf(4.0f);
  glVertex3f(x + 80.0f, y + 60.0f, -1.0f);
  glFogCoordf(1.0f);
  glVertex3f(x, y + 60.0f, -1.0f);
  glEnd();
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  glDisable(GL_FOG);
}

static void fogArrayQuad(float x, float y)
{
  static const GLfloat positions[12] = {0, 0, -1, 80, 0, -1, 80, 60, -1, 0, 60, -1};
  static const GLfloat fog[4] = {8.0f, 0.0f, 2.0f, 6.0f};
  glPushMatrix();
  glTranslatef(x, y, 0.0f);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glColor3f(0.2f, 0.7f, 0.3f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_FOG_COORDINATE_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glFogCoordPointer(GL_FLOAT, 0, fog);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_FOG_COORDINATE_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  glDisable(GL_FOG);
  glPopMatrix();
}

static void depthQuad(float x0, float y0, float x1, float y1, float z)
{
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

static void draw(void)
{
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, 0.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  checker();
  glEnable(GL_TEXTURE_2D);
  texturedQuad(10.0f, 210.0f, 0);
  texturedQuad(100.0f, 210.0f, 1);
  arrayQuad(190.0f, 210.0f);
  glDisable(GL_TEXTURE_2D);
  /* Colour sum without texturing. */
  texturedQuad(280.0f, 210.0f, 1);

  fogQuad(10.0f, 130.0f, GL_LINEAR, 1);
  fogQuad(100.0f, 130.0f, GL_EXP, 1);
  fogQuad(190.0f, 130.0f, GL_EXP2, 1);
  fogQuad(280.0f, 130.0f, GL_LINEAR, 0);
  fogArrayQuad(10.0f, 60.0f);

  /* glDrawBuffer(GL_NONE): the quad at z = -2 writes depth only, hiding the later one at z = -4. */
  glEnable(GL_DEPTH_TEST);
  glDrawBuffer(GL_NONE);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 1.0f, 0.0f);
  depthQuad(140.0f, 20.0f, 260.0f, 80.0f, -2.0f);
  glDrawBuffer(GL_FRONT);
  glColor3f(0.9f, 0.5f, 0.9f);
  depthQuad(200.0f, 10.0f, 390.0f, 110.0f, -4.0f);
  glDisable(GL_DEPTH_TEST);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
