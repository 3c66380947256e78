/* GLUT's text in all nine fonts, as a program written for freeglut draws it:
 *   - a line in each bitmap font (glutBitmapString), in the raster colour set before
 *     glRasterPos, over a grey box glutBitmapLength wide and glutBitmapHeight tall whose bottom
 *     is the font's descent below the baseline: the text must sit inside its box;
 *   - printable ASCII 32 to 126 in 8 by 13, one glutBitmapString with newlines (each line starts
 *     under the first) and, beside it, the same characters one glutBitmapCharacter at a time
 *     from a display list, under GL_UNPACK_LSB_FIRST and an alignment of 8, which GLUT's text
 *     must not notice;
 *   - the two stroke fonts scaled, with glutStrokeString (two lines) and glutStrokeCharacter
 *     (rotated), over boxes glutStrokeLength wide and 100 units (the capitals' height) tall.
 * glass-only: glass draws its own glyphs, not freeglut's X11 and Hershey ones, so a comparison
 * with Mesa and freeglut would compare two typefaces; the reference is a reviewed glass render
 * (reference_images/README.md). Where the text goes is freeglut's: the advances, line heights
 * and state effects are checked against freeglut by tests/unit/glut_fonts_test.cpp and
 * tests/glut_fonts. */
#include <GL/freeglut.h>

#include "gl_program.h"

enum { WIDTH = 480, HEIGHT = 400 };

static const unsigned char *text(const char *s) { return (const unsigned char *)s; }

static void rect(float x0, float y0, float x1, float y1)
{
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
  glEnd();
}

/* One bitmap line whose box has its top at `top`, the baseline `descent` rows above the box's
 * bottom; returns the top of the next line's box. */
static int bitmapLine(void *font, int descent, int x, int top, const char *s,
                      float r, float g, float b)
{
  const int length = glutBitmapLength(font, text(s));
  const int height = glutBitmapHeight(font);
  const int baseline = top - height + descent;
  glColor3f(0.25f, 0.27f, 0.32f);
  rect((float)x, (float)(top - height), (float)(x + length), (float)top);
  glColor3f(r, g, b);
  glRasterPos2i(x, baseline);
  glutBitmapString(font, text(s));
  return top - height - 3;
}

static void strokeLine(void *font, float x, float y, float scale, const char *s)
{
  const float length = glutStrokeLengthf(font, text(s));
  glPushMatrix();
  glTranslatef(x, y, 0.0f);
  glScalef(scale, scale, 1.0f);
  glColor3f(0.25f, 0.27f, 0.32f);
  rect(0.0f, 0.0f, length, 100.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glutStrokeString(font, text(s));
  glPopMatrix();
}

static void draw(void)
{
  static const char ascii[] =
      " !\"#$%&'()*+,-./0123456789:;<=>?\n"
      "@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_\n"
      "`abcdefghijklmnopqrstuvwxyz{|}~";
  int y = HEIGHT - 6;
  GLuint list;

  glClearColor(0.08f, 0.09f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* freeglut's descents (the yorig of its glyph boxes), which GLUT does not report. */
  y = bitmapLine(GLUT_BITMAP_9_BY_15, 4, 8, y, "9 by 15: The quick brown fox", 1.0f, 0.9f, 0.4f);
  y = bitmapLine(GLUT_BITMAP_8_BY_13, 3, 8, y, "8 by 13: jumps over the lazy dog", 0.5f, 1.0f, 0.6f);
  y = bitmapLine(GLUT_BITMAP_TIMES_ROMAN_10, 4, 8, y, "Times Roman 10: Sphinx of black quartz",
                 0.6f, 0.8f, 1.0f);
  y = bitmapLine(GLUT_BITMAP_TIMES_ROMAN_24, 7, 8, y, "Times Roman 24: judge my vow",
                 1.0f, 0.6f, 0.6f);
  y = bitmapLine(GLUT_BITMAP_HELVETICA_10, 3, 8, y, "Helvetica 10: Pack my box with five dozen",
                 0.9f, 0.7f, 1.0f);
  y = bitmapLine(GLUT_BITMAP_HELVETICA_12, 4, 8, y, "Helvetica 12: liquor jugs, 42 + 17 = 59?",
                 0.6f, 1.0f, 1.0f);
  y = bitmapLine(GLUT_BITMAP_HELVETICA_18, 5, 8, y, "Helvetica 18: glass {GLUT} [text]",
                 1.0f, 1.0f, 1.0f);

  /* Printable ASCII: a string with newlines, and character by character from a display list
   * under a hostile unpack state. */
  y -= 16;
  glColor3f(0.9f, 0.9f, 0.9f);
  glRasterPos2i(8, y);
  glutBitmapString(GLUT_BITMAP_8_BY_13, text(ascii));

  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  {
    const char *c;
    for (c = ascii; *c; ++c) {
      if (*c == '\n') break;
      glutBitmapCharacter(GLUT_BITMAP_HELVETICA_10, *c);
    }
  }
  glEndList();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glColor3f(1.0f, 0.8f, 0.3f);
  glRasterPos2i(280, y);
  glCallList(list);
  glColor3f(0.4f, 0.9f, 1.0f);
  glRasterPos2i(280, y - 14);
  glCallList(list);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glDeleteLists(list, 1);

  /* The stroke fonts. */
  strokeLine(GLUT_STROKE_ROMAN, 8.0f, 140.0f, 0.2f, "Roman: Hello, GL! 2 + 2 = 4");
  strokeLine(GLUT_STROKE_MONO_ROMAN, 8.0f, 95.0f, 0.15f, "Mono Roman: glutStroke()\nline two");
  glPushMatrix();
  glTranslatef(330.0f, 25.0f, 0.0f);
  glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
  glScalef(0.25f, 0.25f, 1.0f);
  glColor3f(1.0f, 0.5f, 0.3f);
  glLineWidth(2.0f);
  {
    const char *c;
    for (c = "Tilted"; *c; ++c) glutStrokeCharacter(GLUT_STROKE_ROMAN, *c);
  }
  glLineWidth(1.0f);
  glPopMatrix();
}

int main(int argc, char **argv) { return run_gl_program(argc, argv, WIDTH, HEIGHT, draw); }
