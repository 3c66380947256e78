/* glCopyPixels for colour, depth and stencil (GL 1.5 specification, section 4.3.3), glDrawPixels
 * of depth and stencil images (sections 3.6.4 and 4.3.1), and glReadPixels through the pixel
 * transfer operations (section 4.3.2). Five 100-pixel cells in a row:
 *   1. smooth triangles, then a copy of part of them shifted over itself (source and
 *      destination overlap: the copy shows the original pixels)
 *   2. a copy of cell 1's middle zoomed by 2, with RED_SCALE 0.5 in the transfer
 *   3. a depth-tested slanted quad; then a depth image (a ramp) drawn at the raster position in
 *      the raster colour: it shows where its depths are nearer than the quad's
 *   4. a stencil image (rings) drawn into the stencil buffer, half of it copied beside itself
 *      with glCopyPixels(GL_STENCIL), and a quad drawn where the stencil is 1
 *   5. cell 3's depths copied with glCopyPixels(GL_DEPTH) (the fragments take the raster colour),
 *      then a flat quad halfway back, depth tested: it covers only where the copy is farther;
 *      at the top, cell 1's colours read back with GREEN_SCALE 0 and BLUE_BIAS 0.5 and drawn */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "gl_program.h"

enum { CELL = 100, CELLS = 5 };

static void quad(float x0, float y0, float x1, float y1, float z0, float z1)
{
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z0);
  glVertex3f(x1, y0, z1);
  glVertex3f(x1, y1, z1);
  glVertex3f(x0, y1, z0);
  glEnd();
}

static void draw(void)
{
  static GLfloat depthRamp[60][60];
  static GLubyte rings[80][80];
  static GLubyte readBack[30][40][3];

  glViewport(0, 0, CELLS * CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, CELLS * CELL, 0.0, CELL, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);

  /* 1. Overlapping copy. */
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.2f, 0.2f);
  glVertex2f(5.0f, 5.0f);
  glColor3f(0.2f, 1.0f, 0.2f);
  glVertex2f(95.0f, 20.0f);
  glColor3f(0.2f, 0.3f, 1.0f);
  glVertex2f(40.0f, 95.0f);
  glEnd();
  glRasterPos2i(25, 10);
  glCopyPixels(10, 20, 50, 45, GL_COLOR);

  /* 2. Zoomed copy with a colour scale. */
  glRasterPos2i(CELL + 10, 10);
  glPixelZoom(2.0f, 2.0f);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glCopyPixels(30, 30, 40, 40, GL_COLOR);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelZoom(1.0f, 1.0f);

  /* 3. A depth image against a slanted quad. */
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.8f, 0.7f, 0.3f);
  quad(2 * CELL + 5, 5, 3 * CELL - 5, 95, 0.9f, -0.9f);
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) depthRamp[i][j] = (float)(i + j) / 118.0f;
  glColor3f(0.2f, 0.6f, 0.9f);
  glRasterPos2i(2 * CELL + 20, 20);
  glDrawPixels(60, 60, GL_DEPTH_COMPONENT, GL_FLOAT, depthRamp);
  glDisable(GL_DEPTH_TEST);

  /* 4. A stencil image, copied in part, then a quad where the stencil is 1. */
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j) {
      const int dx = j - 40, dy = i - 40, r2 = dx * dx + dy * dy;
      rings[i][j] = (GLubyte)((r2 / 90) % 2);
    }
  glRasterPos2i(3 * CELL + 10, 10);
  glDrawPixels(80, 80, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rings);
  glRasterPos2i(3 * CELL + 60, 55);
  glCopyPixels(3 * CELL + 10, 10, 40, 40, GL_STENCIL);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glColor3f(0.9f, 0.4f, 0.7f);
  quad(3 * CELL, 0, 4 * CELL, CELL, 0.0f, 0.0f);
  glDisable(GL_STENCIL_TEST);

  /* 5. Copied depths, then a flat quad tested against them; colours read back with transfer. */
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.3f, 0.3f, 0.35f);
  glRasterPos2i(4 * CELL + 5, 5);
  glCopyPixels(2 * CELL + 5, 5, 90, 60, GL_DEPTH);
  glDepthFunc(GL_LESS);
  glColor3f(0.9f, 0.9f, 0.9f);
  quad(4 * CELL, 0, 5 * CELL, 70, 0.0f, 0.0f);
  glDisable(GL_DEPTH_TEST);

  glPixelTransferf(GL_GREEN_SCALE, 0.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.5f);
  glReadPixels(30, 30, 40, 30, GL_RGB, GL_UNSIGNED_BYTE, readBack);
  glPixelTransferf(GL_GREEN_SCALE, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  glWindowPos2i(4 * CELL + 30, 70);
  glDrawPixels(40, 30, GL_RGB, GL_UNSIGNED_BYTE, readBack);
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, CELLS * CELL, CELL, draw);
}
