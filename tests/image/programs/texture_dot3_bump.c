/* DOT3 bump lighting with two texture units (OpenGL 1.3, GL_COMBINE with GL_DOT3_RGB): unit 0
 * holds a normal map (normals of a field of bumps, encoded as 0.5 + 0.5 n), and its combiner
 * takes the dot product with the primary colour, which carries the direction to the light,
 * encoded the same way, per vertex; unit 1 modulates a base texture by that diffuse term.
 *
 *   left:  the bumps lit from the upper left, on a base texture
 *   right: the same with the light low from the right, DOT3_RGBA, and unit 1 adding a little
 *          ambient with GL_ADD_SIGNED over the base texture instead
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <math.h>

#include "gl_program.h"

enum { SIZE = 256, TEX = 64, GRID = 16 };

static GLuint normalMap, base;

static void makeTextures(void)
{
  static GLubyte normals[TEX][TEX][3];
  static GLubyte colors[16][16][3];
  for (int j = 0; j < TEX; ++j) {
    for (int i = 0; i < TEX; ++i) {
      /* Hemispherical bumps of radius 6 texels on a 16-texel grid. */
      const float cx = (float)(i % 16) - 7.5f, cy = (float)(j % 16) - 7.5f;
      const float r2 = cx * cx + cy * cy;
      float n[3] = {0.0f, 0.0f, 1.0f};
      if (r2 < 36.0f) {
        const float z = sqrtf(36.0f - r2);
        n[0] = cx / 6.0f;
        n[1] = cy / 6.0f;
        n[2] = z / 6.0f;
      }
      for (int k = 0; k < 3; ++k) normals[j][i][k] = (GLubyte)lrintf(127.5f + 127.0f * n[k]);
    }
  }
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      colors[j][i][0] = (GLubyte)(180 + 4 * i);
      colors[j][i][1] = (GLubyte)(120 + 6 * j);
      colors[j][i][2] = (GLubyte)(((i + j) % 4) ? 90 : 200);
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &normalMap);
  glBindTexture(GL_TEXTURE_2D, normalMap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE, normals);
  glGenTextures(1, &base);
  glBindTexture(GL_TEXTURE_2D, base);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, colors);
}

/* A grid whose primary colour at each vertex is the unit vector towards the light, encoded. */
static void litGrid(float x0, float y0, float size, const float light[3])
{
  const float step = size / GRID;
  for (int j = 0; j < GRID; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= GRID; ++i) {
      for (int k = 1; k >= 0; --k) {
        const float x = x0 + i * step, y = y0 + (j + k) * step;
        float l[3] = {light[0] - x, light[1] - y, light[2]};
        const float length = sqrtf(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        glColor3f(0.5f + 0.5f * l[0] / length, 0.5f + 0.5f * l[1] / length,
                  0.5f + 0.5f * l[2] / length);
        glMultiTexCoord2f(GL_TEXTURE0, 2.0f * i / GRID, 2.0f * (j + k) / GRID);
        glMultiTexCoord2f(GL_TEXTURE1, 1.5f * i / GRID, 1.5f * (j + k) / GRID);
        glVertex2f(x, y);
      }
    }
    glEnd();
  }
}

static void dot3Unit(GLenum function)
{
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, normalMap);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)function);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
}

static void draw(void)
{
  const float upperLeft[3] = {20.0f, 220.0f, 90.0f};
  const float lowRight[3] = {2.0f * SIZE, 100.0f, 30.0f};
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 2 * SIZE, 0.0, SIZE, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  makeTextures();

  dot3Unit(GL_DOT3_RGB);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, base);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  litGrid(8.0f, 8.0f, SIZE - 16.0f, upperLeft);

  dot3Unit(GL_DOT3_RGBA);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
  litGrid(SIZE + 8.0f, 8.0f, SIZE - 16.0f, lowRight);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, 2 * SIZE, SIZE, draw);
}
