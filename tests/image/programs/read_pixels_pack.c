/* glReadPixels into client memory with the pack parameters of glPixelStore (OpenGL 1.5 sections
 * 4.3.2 and 3.6.1), the pixels then drawn back with glDrawPixels, as programs save a picture,
 * make a thumbnail or show the depth buffer. The top-left cell holds the scene that is read: a
 * depth-tested pair of crossing quads in perspective over a smooth background whose alpha runs
 * from 0.2 to 1. The other cells, each 100 pixels, show what came back:
 *
 *   top row:    RGB bytes of a 45-pixel wide region (odd, so GL_PACK_ALIGNMENT 4 pads each row
 *               to 136 bytes), drawn back with the same alignment; the same region read with
 *               GL_PACK_ROW_LENGTH 90, SKIP_PIXELS 30 and SKIP_ROWS 6 into a larger image filled
 *               with a pattern beforehand, the whole image drawn (the read lands inside the
 *               pattern, the rest untouched); GL_LUMINANCE (L = R + G + B, clamped to 1, spec
 *               4.3.2) drawn as luminance
 *   bottom row: GL_UNSIGNED_SHORT_5_6_5 (each component rounded to 5 or 6 bits) drawn back the
 *               same way; GL_ALPHA drawn as luminance (the background's alpha ramp); the depth
 *               buffer as GL_FLOAT drawn as luminance after scaling with GL_DEPTH_SCALE and
 *               GL_DEPTH_BIAS on read (near is dark); and the RGBA image drawn from a raster
 *               position moved beyond the window's bottom-left corner by a glBitmap of size 0
 *               (the position stays valid, and the image is clipped by the window), with
 *               GL_UNPACK_SKIP_PIXELS to draw only its right part. */
#include <GL/gl.h>
#include <GL/glu.h>

#include "gl_program.h"

enum { CELL = 100, WIDTH = 4 * CELL, HEIGHT = 2 * CELL, READ_W = 45, READ_H = 70 };

/* The region every read takes, inside the top-left cell. */
static const int readX = 34, readY = CELL + 14;

static void drawScene(void)
{
  glViewport(0, CELL, CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* The background: behind everything (depth test off), alpha from 0.2 (bottom) to 1 (top). */
  glBegin(GL_QUADS);
  glColor4f(0.5f, 0.1f, 0.05f, 0.2f);
  glVertex2f(0.0f, 0.0f);
  glColor4f(0.6f, 0.6f, 0.1f, 0.2f);
  glVertex2f(1.0f, 0.0f);
  glColor4f(0.1f, 0.4f, 0.6f, 1.0f);
  glVertex2f(1.0f, 1.0f);
  glColor4f(0.3f, 0.05f, 0.5f, 1.0f);
  glVertex2f(0.0f, 1.0f);
  glEnd();

  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 2.0, 8.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.5f);
  /* Two quads standing at +-40 degrees about the vertical axis, crossing along it. */
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glRotatef(i == 0 ? 40.0f : -40.0f, 0.0f, 1.0f, 0.0f);
    const float h = i == 0 ? 0.9f : 0.6f;
    glBegin(GL_QUADS);
    glColor3f(0.6f, 0.15f * i, 0.1f);
    glVertex3f(-1.1f, -h, 0.0f);
    glColor3f(0.1f, 0.5f, 0.2f + 0.6f * i);
    glVertex3f(1.1f, -h, 0.0f);
    glColor3f(0.05f, 0.2f, 0.3f);
    glVertex3f(1.1f, h, 0.0f);
    glColor3f(0.7f, 0.6f, 0.1f * i);
    glVertex3f(-1.1f, h, 0.0f);
    glEnd();
    glPopMatrix();
  }
  glDisable(GL_DEPTH_TEST);
  glViewport(0, 0, WIDTH, HEIGHT);
}

/* Draws a client image at the window position (x, y) of a cell's lower-left corner. */
static void drawAt(int x, int y, int w, int h, GLenum format, GLenum type, const void *pixels)
{
  glRasterPos2i(x, y);
  glDrawPixels(w, h, format, type, pixels);
}

static void readAndDraw(void)
{
  static GLubyte rgb[READ_H][136];
  static GLubyte padded[READ_H + 6][90][4];
  static GLubyte luminance[READ_H][READ_W];
  static GLushort packed[READ_H][READ_W + 1];
  static GLubyte alpha[READ_H][READ_W];
  static GLfloat depth[READ_H][READ_W];
  static GLubyte rgba[READ_H][READ_W][4];

  /* Top row. */
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(readX, readY, READ_W, READ_H, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  drawAt(CELL + 28, CELL + 15, READ_W, READ_H, GL_RGB, GL_UNSIGNED_BYTE, rgb);

  for (int j = 0; j < READ_H + 6; ++j) {
    for (int i = 0; i < 90; ++i) {
      const GLubyte v = (GLubyte)(((i / 5 + j / 5) & 1) ? 200 : 90);
      padded[j][i][0] = padded[j][i][1] = padded[j][i][2] = v;
      padded[j][i][3] = 255;
    }
  }
  glPixelStorei(GL_PACK_ROW_LENGTH, 90);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 30);
  glPixelStorei(GL_PACK_SKIP_ROWS, 6);
  glReadPixels(readX, readY, READ_W, READ_H, GL_RGBA, GL_UNSIGNED_BYTE, padded);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  drawAt(2 * CELL + 5, CELL + 12, 90, READ_H + 6, GL_RGBA, GL_UNSIGNED_BYTE, padded);

  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glReadPixels(readX, readY, READ_W, READ_H, GL_LUMINANCE, GL_UNSIGNED_BYTE, luminance);
  drawAt(3 * CELL + 28, CELL + 15, READ_W, READ_H, GL_LUMINANCE, GL_UNSIGNED_BYTE, luminance);

  /* Bottom row. */
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glReadPixels(readX, readY, READ_W, READ_H, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed);
  drawAt(28, 15, READ_W, READ_H, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed);

  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glReadPixels(readX, readY, READ_W, READ_H, GL_ALPHA, GL_UNSIGNED_BYTE, alpha);
  drawAt(CELL + 28, 15, READ_W, READ_H, GL_LUMINANCE, GL_UNSIGNED_BYTE, alpha);

  /* The scene's depths lie between about 0.55 and 0.8: stretch them over 0..1. */
  glPixelTransferf(GL_DEPTH_SCALE, 4.0f);
  glPixelTransferf(GL_DEPTH_BIAS, -2.2f);
  glReadPixels(readX, readY, READ_W, READ_H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
  drawAt(2 * CELL + 28, 15, READ_W, READ_H, GL_LUMINANCE, GL_FLOAT, depth);

  glReadPixels(readX, readY, READ_W, READ_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  /* A valid raster position at the window's corner, moved 20 left and 30 down by an empty
   * bitmap: the image's lower-left part falls outside the window and is clipped. Then the
   * same image once more, its left 15 columns skipped. */
  glRasterPos2i(0, 0);
  glBitmap(0, 0, 0.0f, 0.0f, -20.0f, -30.0f, NULL);
  glDrawPixels(READ_W, READ_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, READ_W);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 15);
  drawAt(3 * CELL + 28, 15, READ_W - 15, READ_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
}

static void draw(void)
{
  glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  drawScene();

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* The region read, framed in the scene cell (after reading, so the frame is not read). */
  readAndDraw();
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_LINE_LOOP);
  glVertex2f(readX - 0.5f, readY - 0.5f);
  glVertex2f(readX + READ_W + 0.5f, readY - 0.5f);
  glVertex2f(readX + READ_W + 0.5f, readY + READ_H + 0.5f);
  glVertex2f(readX - 0.5f, readY + READ_H + 0.5f);
  glEnd();
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
