/* Fog and colour sum in the same draw (unlit, GL_COLOR_SUM, glSecondaryColor and glFogCoord per
 * vertex, linear fog from GL_FOG_COORDINATE). Spec 3.9 adds the secondary colour to the textured
 * primary colour and clamps the sum to [0, 1]; spec 3.10 then blends that clamped colour towards
 * the fog colour. So the order (sum, then fog) and the clamp between them both show:
 *
 * - Top left: one flat quad whose red sum exceeds 1. Primary (0.8, 0.5, 0.2), secondary
 *   (0.5, 0.2, 0.1), fog coordinate 5 with start 0 and end 10 (f = 0.5), fog colour
 *   (0.2, 0.4, 0.6): sum clamped (1.0, 0.7, 0.3), fogged (0.6, 0.55, 0.45), that is
 *   (153, 140, 115) in 8 bits. Summing without the clamp would give red 0.75 (191).
 * - Top right: one flat quad whose sums stay below 1. Primary (0.6, 0.3, 0.2), secondary
 *   (0.3, 0.5, 0.4): sum (0.9, 0.8, 0.6), fogged (0.55, 0.6, 0.6) = (140, 153, 153). Fogging the
 *   primary first and adding the secondary after would give (0.7, 0.85, 0.8).
 * - Bottom: a strip of quads textured on two units (GL_MODULATE, checkers of different periods),
 *   with fog coordinates from 0 to 10 and the secondary colour changing per vertex; the colours
 *   keep every sum below 1. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { WIDTH = 256, HEIGHT = 192, TEXTURE_SIZE = 8, STRIP_QUADS = 6 };

static void makeChecker(GLuint name, int period, const GLubyte a[3], const GLubyte b[3])
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
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

/* A flat quad: the same colours and fog coordinate at every vertex. */
static void flatQuad(float x0, float y0, float size, const GLfloat primary[3], const GLfloat secondary[3])
{
  glColor3fv(primary);
  glSecondaryColor3fv(secondary);
  glFogCoordf(5.0f);
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x0 + size, y0);
  glVertex2f(x0 + size, y0 + size);
  glVertex2f(x0, y0 + size);
  glEnd();
}

static void texturedStrip(void)
{
  static const GLubyte light[3] = {240, 240, 220}, dark[3] = {90, 90, 120};
  static const GLubyte red[3] = {255, 160, 160}, white[3] = {255, 255, 255};
  GLuint textures[2];
  int i;
  glGenTextures(2, textures);
  glActiveTexture(GL_TEXTURE0);
  makeChecker(textures[0], 2, light, dark);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  makeChecker(textures[1], 4, red, white);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  glBegin(GL_QUADS);
  for (i = 0; i < STRIP_QUADS; ++i) {
    const float x0 = 8.0f + 40.0f * (float)i, x1 = x0 + 36.0f;
    glColor3f(0.6f, 0.55f - 0.05f * (float)i, 0.5f);
    glSecondaryColor3f(0.05f * (float)i, 0.1f, 0.3f);
    glFogCoordf(2.0f * (float)i);
    glMultiTexCoord2f(GL_TEXTURE0, 0.03f, 0.06f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.02f, 0.03f);
    glVertex2f(x0, 8.0f);
    glFogCoordf(2.0f * (float)i + 6.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.97f, 0.06f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.51f, 0.27f);
    glVertex2f(x1, 8.0f);
    glSecondaryColor3f(0.35f, 0.0f, 0.1f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.97f, 0.94f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.98f, 0.97f);
    glVertex2f(x1, 88.0f);
    glFogCoordf(10.0f - 2.0f * (float)i);
    glMultiTexCoord2f(GL_TEXTURE0, 0.03f, 0.94f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.26f, 0.77f);
    glVertex2f(x0, 88.0f);
  }
  glEnd();

  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(2, textures);
}

static void draw(void)
{
  static const GLfloat fogColor[4] = {0.2f, 0.4f, 0.6f, 1.0f};
  static const GLfloat overPrimary[3] = {0.8f, 0.5f, 0.2f}, overSecondary[3] = {0.5f, 0.2f, 0.1f};
  static const GLfloat underPrimary[3] = {0.6f, 0.3f, 0.2f}, underSecondary[3] = {0.3f, 0.5f, 0.4f};
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glEnable(GL_COLOR_SUM);

  flatQuad(16.0f, 112.0f, 24.0f, overPrimary, overSecondary);
  flatQuad(160.0f, 112.0f, 64.0f, underPrimary, underSecondary);
  texturedStrip();

  glDisable(GL_COLOR_SUM);
  glDisable(GL_FOG);
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
