/* glBitmap (GL 1.5 specification, section 3.7) as Red Book programs use it: a bitmap font whose
 * glyphs are display lists called with glCallLists, the raster position advancing by each
 * glyph's move, the raster colour captured by glRasterPos (not by glBitmap), origins that shift
 * a bitmap against the raster position, GL_UNPACK_LSB_FIRST, glyphs running off the window's
 * edge, and a raster position outside the view volume, which makes glBitmap draw nothing and
 * move nothing. Lines of text at several scales of the glyph grid:
 *   - "GLASS 0123" and "PIXELS 456" in the 6 x 8 font, in two colours
 *   - the same font drawn with glyphs shifted by their origin (xorig, yorig)
 *   - large glyphs read with GL_UNPACK_LSB_FIRST and rows padded to GL_UNPACK_ALIGNMENT 4
 *   - text starting left of the window, and text starting at an invalid raster position */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <string.h>

#include "gl_program.h"

enum { WIDTH = 320, HEIGHT = 160 };

/* A 5 x 7 font of the characters used here, row 0 at the top, '#' for a set bit. */
static const struct {
  char c;
  const char *rows[7];
} glyphs[] = {
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".###."}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'I', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "#####"}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"####.", "....#", "....#", ".###.", "....#", "....#", "####."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
};
enum { GLYPHS = sizeof glyphs / sizeof glyphs[0] };

static GLuint fontBase;

/* Packs a glyph as a bitmap 8 bits wide (one byte a row), bottom row first; lsbFirst puts the
 * leftmost pixel in the lowest bit. */
static void packGlyph(int g, int lsbFirst, GLubyte bitmap[7])
{
  for (int r = 0; r < 7; ++r) {
    GLubyte byte = 0;
    for (int x = 0; x < 5; ++x)
      if (glyphs[g].rows[6 - r][x] == '#') byte |= (GLubyte)(lsbFirst ? 1u << x : 0x80u >> x);
    bitmap[r] = byte;
  }
}

static void makeFont(void)
{
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  fontBase = glGenLists(128);
  for (int g = 0; g < GLYPHS; ++g) {
    GLubyte bitmap[7];
    packGlyph(g, 0, bitmap);
    glNewList(fontBase + (GLuint)glyphs[g].c, GL_COMPILE);
    glBitmap(5, 7, 0.0f, 0.0f, 6.0f, 0.0f, bitmap);
    glEndList();
  }
  /* A space: one clear bit and the move. (Mesa records GL_OUT_OF_MEMORY when it compiles a
   * glBitmap with no bits into a display list, so the space has one.) */
  {
    static const GLubyte clear = 0;
    glNewList(fontBase + ' ', GL_COMPILE);
    glBitmap(1, 1, 0.0f, 0.0f, 6.0f, 0.0f, &clear);
    glEndList();
  }
}

static void text(const char *s)
{
  glListBase(fontBase);
  glCallLists((GLsizei)strlen(s), GL_UNSIGNED_BYTE, s);
}

static void draw(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  makeFont();

  /* Two lines: the colour is the one current at glRasterPos. */
  glColor3f(1.0f, 0.9f, 0.3f);
  glRasterPos2i(10, 140);
  glColor3f(0.2f, 0.2f, 1.0f); /* too late for this line */
  text("GLASS 0123");
  glColor3f(0.4f, 1.0f, 0.6f);
  glRasterPos2i(10, 128);
  text("PIXELS 456");

  /* Origins: each glyph drawn at its raster position minus (xorig, yorig). */
  glColor3f(1.0f, 0.5f, 0.3f);
  glRasterPos2i(10, 110);
  for (int g = 0; g < GLYPHS; ++g) {
    GLubyte bitmap[7];
    packGlyph(g, 0, bitmap);
    glBitmap(5, 7, (float)(g % 3), (float)(g % 4) - 1.5f, 7.0f, 0.0f, bitmap);
  }

  /* Large glyphs: each bit of the 5 x 7 grid as a 4 x 4 block, unpacked LSB first, with a
   * fractional move that accumulates across glyphs. */
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4); /* rows of 20 bits padded to 4 bytes */
  glColor3f(0.9f, 0.3f, 0.8f);
  glRasterPos2f(10.25f, 40.0f);
  for (int g = 0; g < 8; ++g) {
    GLubyte big[28][4];
    memset(big, 0, sizeof big);
    for (int r = 0; r < 28; ++r)
      for (int x = 0; x < 20; ++x)
        if (glyphs[g].rows[6 - r / 4][x / 4] == '#') big[r][x / 8] |= (GLubyte)(1u << (x % 8));
    glBitmap(20, 28, 0.0f, 0.0f, 23.6f, 0.0f, &big[0][0]);
  }
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* Off the left edge: the raster position is valid (inside the viewport), the bitmaps are cut
   * at the window's edge. */
  glColor3f(0.6f, 0.8f, 1.0f);
  glRasterPos2i(2, 90);
  glBitmap(0, 0, 0.0f, 0.0f, -14.0f, 0.0f, NULL);
  text("GLASS PIXELS");

  /* An invalid raster position: nothing is drawn and the moves are lost. */
  glRasterPos2i(-5, 70);
  text("GLASS");
  glColor3f(1.0f, 1.0f, 1.0f);
  glRasterPos2i(200, 70);
  text("0123456");
}

int main(int argc, char **argv)
{
  return run_gl_program(argc, argv, WIDTH, HEIGHT, draw);
}
