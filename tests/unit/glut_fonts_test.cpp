// GLUT's fonts (pipeline/src/glut/glut_fonts.cpp): freeglut 3's metrics, the raster position and
// modelview moves, the unpack state put back, display lists, feedback, and bad arguments.
// (tests/glut_fonts compares every advance and height with the installed freeglut.)
#include <GL/glut.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "glut/font_glyphs.h"
#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

const unsigned char* text(const char* s) { return reinterpret_cast<const unsigned char*>(s); }

struct RasterPosition {
  float x, y;
  bool valid;
};

RasterPosition rasterPosition() {
  GLfloat p[4] = {0, 0, 0, 0};
  GLboolean valid = GL_FALSE;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  return {p[0], p[1], valid == GL_TRUE};
}

// The modelview matrix's translation column.
void modelviewTranslation(float& x, float& y) {
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  x = m[12];
  y = m[13];
}

struct InkBox {
  int left = 1 << 30, bottom = 1 << 30, right = -1, top = -1;  // right and top inclusive
  bool empty() const { return right < 0; }
};

InkBox inkBox(int width, int height) {
  const std::vector<uint8_t> pixels = glass::test::readFramebuffer(width, height);
  InkBox box;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 4];
      if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
      box.left = std::min(box.left, x);
      box.right = std::max(box.right, x);
      box.bottom = std::min(box.bottom, y);
      box.top = std::max(box.top, y);
    }
  return box;
}

void* const kBitmapFonts[] = {GLUT_BITMAP_9_BY_15,        GLUT_BITMAP_8_BY_13,
                              GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
                              GLUT_BITMAP_HELVETICA_10,   GLUT_BITMAP_HELVETICA_12,
                              GLUT_BITMAP_HELVETICA_18};
// freeglut's line heights and descents (the yorig of its glyph boxes), in the order above.
const int kHeights[] = {16, 14, 14, 29, 14, 16, 23};
const int kDescents[] = {4, 3, 4, 7, 3, 4, 5};

}  // namespace

TEST_CASE("glut fonts: glass's glyphs are 94 different letters, descending only where they should") {
  using glass::gl::glut::glyphRows;
  using glass::gl::glut::kGlyphRows;
  const std::string descenders = "gjpqy,;_";
  for (int a = 33; a < 127; ++a) {
    CAPTURE(static_cast<char>(a));
    const std::uint8_t* rows = glyphRows(a);
    bool inked = false;
    for (int r = 0; r < kGlyphRows; ++r) {
      CHECK(rows[r] < 32);  // 5 columns
      inked = inked || rows[r] != 0;
    }
    CHECK(inked);
    const bool descends = rows[7] != 0 || rows[8] != 0;
    CHECK(descends == (descenders.find(static_cast<char>(a)) != std::string::npos));
    for (int b = a + 1; b < 127; ++b)
      CHECK_FALSE(std::equal(rows, rows + kGlyphRows, glyphRows(b)));
  }
  // Outside printable ASCII: the space's blank glyph.
  for (int c : {0, 31, 127, 200, 255}) {
    const std::uint8_t* rows = glyphRows(c);
    CHECK(std::all_of(rows, rows + kGlyphRows, [](std::uint8_t r) { return r == 0; }));
  }
}

TEST_CASE("glut fonts: the handles are nine distinct addresses, as in freeglut on Unix") {
  void* const handles[] = {GLUT_STROKE_ROMAN,          GLUT_STROKE_MONO_ROMAN,
                           GLUT_BITMAP_9_BY_15,        GLUT_BITMAP_8_BY_13,
                           GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
                           GLUT_BITMAP_HELVETICA_10,   GLUT_BITMAP_HELVETICA_12,
                           GLUT_BITMAP_HELVETICA_18};
  for (int i = 0; i < 9; ++i)
    for (int j = i + 1; j < 9; ++j) CHECK(handles[i] != handles[j]);
  CHECK(GLUT_BITMAP_HELVETICA_18 == static_cast<void*>(&glutBitmapHelvetica18));
}

TEST_CASE("glut fonts: bitmap widths and heights are freeglut's") {
  for (int f = 0; f < 7; ++f) CHECK(glutBitmapHeight(kBitmapFonts[f]) == kHeights[f]);
  CHECK(glutBitmapWidth(GLUT_BITMAP_9_BY_15, 'W') == 9);
  CHECK(glutBitmapWidth(GLUT_BITMAP_8_BY_13, 'i') == 8);
  CHECK(glutBitmapWidth(GLUT_BITMAP_TIMES_ROMAN_24, 'M') == 22);
  CHECK(glutBitmapWidth(GLUT_BITMAP_TIMES_ROMAN_10, ' ') == 2);
  CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_10, 'i') == 2);
  CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_12, '@') == 12);
  CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_18, 'W') == 18);
  // Characters beyond ASCII advance too (ISO 8859-1: 0xE9 is e acute), control characters by
  // the font's placeholder width.
  CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_18, 0xE9) == 10);
  CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_18, 7) == 5);
}

TEST_CASE("glut fonts: bitmap lengths are the widest line's") {
  const int hello = glutBitmapWidth(GLUT_BITMAP_HELVETICA_12, 'H') +
                    glutBitmapWidth(GLUT_BITMAP_HELVETICA_12, 'i');
  CHECK(glutBitmapLength(GLUT_BITMAP_HELVETICA_12, text("Hi")) == hello);
  CHECK(hello == 9 + 3);
  CHECK(glutBitmapLength(GLUT_BITMAP_HELVETICA_12, text("Hi\nWWW\nx")) == 3 * 11);
  CHECK(glutBitmapLength(GLUT_BITMAP_9_BY_15, text("abc\n")) == 27);
  CHECK(glutBitmapLength(GLUT_BITMAP_9_BY_15, text("")) == 0);
  CHECK(glutBitmapLength(GLUT_BITMAP_9_BY_15, nullptr) == 0);
}

TEST_CASE("glut fonts: stroke widths, lengths and heights are freeglut's") {
  CHECK(glutStrokeHeight(GLUT_STROKE_ROMAN) == 152.381f);
  CHECK(glutStrokeHeight(GLUT_STROKE_MONO_ROMAN) == 152.381f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, 'A') == 80.4905f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, 'm') == 123.962f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, 127) == 66.6667f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_MONO_ROMAN, 'i') == 104.762f);
  // glutStrokeWidth rounds to nearest.
  CHECK(glutStrokeWidth(GLUT_STROKE_ROMAN, 'A') == 80);
  CHECK(glutStrokeWidth(GLUT_STROKE_ROMAN, 'B') == 84);  // 83.6267
  CHECK(glutStrokeWidth(GLUT_STROKE_MONO_ROMAN, 'x') == 105);
  // Only 32 to 127 exist.
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, 31) == 0.0f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, 128) == 0.0f);
  CHECK(glutStrokeWidthf(GLUT_STROKE_ROMAN, -1) == 0.0f);

  const float ab = 80.4905f + 83.6267f;
  CHECK(glutStrokeLengthf(GLUT_STROKE_ROMAN, text("AB")) == ab);
  CHECK(glutStrokeLengthf(GLUT_STROKE_ROMAN, text("A\nAB\nB")) == ab);
  CHECK(glutStrokeLength(GLUT_STROKE_ROMAN, text("AB")) == 164);  // 164.1172 rounded
  CHECK(glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, text("abc")) == 3.0f * 104.762f);
  // Characters the font lacks add nothing.
  CHECK(glutStrokeLengthf(GLUT_STROKE_ROMAN, text("A\tB\xC8")) == ab);
  CHECK(glutStrokeLengthf(GLUT_STROKE_ROMAN, nullptr) == 0.0f);
}

TEST_CASE("glut fonts: a bitmap character moves the raster position by its advance") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glRasterPos2i(10, 20);
  glutBitmapCharacter(GLUT_BITMAP_9_BY_15, 'A');
  RasterPosition p = rasterPosition();
  CHECK(p.x == 19.0f);
  CHECK(p.y == 20.0f);
  glutBitmapCharacter(GLUT_BITMAP_HELVETICA_10, 'i');
  CHECK(rasterPosition().x == 21.0f);

  // A string: each character's advance; '\n' goes back to the line's start, one height down.
  glRasterPos2i(5, 40);
  glutBitmapString(GLUT_BITMAP_HELVETICA_18, text("ab\ncde"));
  p = rasterPosition();
  CHECK(p.x == 5.0f + 10 + 11 + 10);  // c, d, e
  CHECK(p.y == 40.0f - 23);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glut fonts: glyphs sit on the baseline, inside the font's box, in the raster colour") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  for (int f = 0; f < 7; ++f) {
    for (int c = 33; c < 127; ++c) {
      glClear(GL_COLOR_BUFFER_BIT);
      glColor3f(1.0f, 0.0f, 0.0f);
      glRasterPos2i(20, 20);
      glColor3f(0.0f, 1.0f, 0.0f);  // after glRasterPos: not the text's colour
      glutBitmapCharacter(kBitmapFonts[f], c);
      const InkBox box = inkBox(64, 64);
      CAPTURE(f);
      CAPTURE(c);
      REQUIRE_FALSE(box.empty());
      CHECK(box.bottom >= 20 - kDescents[f]);
      CHECK(box.top < 20 - kDescents[f] + kHeights[f]);
      // Centred on the advance, at most 2 pixels past it on either side (narrow advances).
      const int advance = glutBitmapWidth(kBitmapFonts[f], c);
      CHECK(box.left >= 20 - 2);
      CHECK(box.right < 20 + advance + 2);
    }
  }
  // Capitals rest on the baseline: the bottom of 'E' is row 20.
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  glRasterPos2i(20, 20);
  glColor3f(0.0f, 1.0f, 0.0f);
  glutBitmapCharacter(GLUT_BITMAP_8_BY_13, 'E');
  CHECK(inkBox(64, 64).bottom == 20);
  // Every lit pixel is the raster colour.
  const std::vector<uint8_t> pixels = glass::test::readFramebuffer(64, 64);
  int red = 0;
  int other = 0;
  for (std::size_t i = 0; i < pixels.size(); i += 4) {
    if (pixels[i] == 255 && pixels[i + 1] == 0 && pixels[i + 2] == 0) ++red;
    else if (pixels[i] != 0 || pixels[i + 1] != 0 || pixels[i + 2] != 0) ++other;
  }
  CHECK(red > 10);
  CHECK(other == 0);
  // A space draws nothing and moves.
  glClear(GL_COLOR_BUFFER_BIT);
  glRasterPos2i(20, 20);
  glutBitmapCharacter(GLUT_BITMAP_TIMES_ROMAN_24, ' ');
  CHECK(inkBox(64, 64).empty());
  CHECK(rasterPosition().x == 26.0f);
}

TEST_CASE("glut fonts: an invalid raster position draws nothing and stays put") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  glRasterPos3f(10.0f, 10.0f, 5.0f);  // outside the view volume (z beyond the far plane)
  REQUIRE_FALSE(rasterPosition().valid);
  glutBitmapString(GLUT_BITMAP_9_BY_15, text("AB\nC"));
  CHECK(inkBox(32, 32).empty());
  CHECK_FALSE(rasterPosition().valid);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glut fonts: the unpack state and the client attribute stack are left as found") {
  ScopedContext context(64, 32);
  glass::test::pixelProjection(64, 32);
  glRasterPos2i(4, 10);
  glutBitmapString(GLUT_BITMAP_HELVETICA_12, text("Glass"));
  const std::vector<uint8_t> expected = glass::test::readFramebuffer(64, 32);

  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glRasterPos2i(4, 10);
  glutBitmapCharacter(GLUT_BITMAP_HELVETICA_12, 'G');
  glutBitmapString(GLUT_BITMAP_HELVETICA_12, text("lass"));

  GLint v = 0;
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &v);
  CHECK(v == GL_TRUE);
  glGetIntegerv(GL_UNPACK_LSB_FIRST, &v);
  CHECK(v == GL_TRUE);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &v);
  CHECK(v == 7);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &v);
  CHECK(v == 2);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &v);
  CHECK(v == 3);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &v);
  CHECK(v == 8);
  glGetIntegerv(GL_PACK_ALIGNMENT, &v);
  CHECK(v == 2);
  glGetIntegerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &v);
  CHECK(v == 0);
  CHECK(glGetError() == GL_NO_ERROR);

  // The program's unpack state did not change the glyphs.
  CHECK(glass::test::readFramebuffer(64, 32) == expected);
}

TEST_CASE("glut fonts: bitmap text compiles into display lists and feeds back as glBitmap") {
  ScopedContext context(64, 32);
  glass::test::pixelProjection(64, 32);
  glRasterPos2i(4, 10);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glutBitmapString(GLUT_BITMAP_8_BY_13, text("Hey"));
  glEndList();
  CHECK(rasterPosition().x == 4.0f);  // compiled, not executed
  CHECK(inkBox(64, 32).empty());
  glCallList(list);
  CHECK(rasterPosition().x == 4.0f + 3 * 8);
  CHECK_FALSE(inkBox(64, 32).empty());

  // Feedback: one GL_BITMAP_TOKEN per character, at the raster position before it.
  GLfloat buffer[64];
  glFeedbackBuffer(64, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glRasterPos2i(4, 10);
  glutBitmapString(GLUT_BITMAP_9_BY_15, text("ab"));
  const GLint count = glRenderMode(GL_RENDER);
  REQUIRE(count == 6);
  CHECK(buffer[0] == static_cast<GLfloat>(GL_BITMAP_TOKEN));
  CHECK(buffer[1] == 4.0f);
  CHECK(buffer[3] == static_cast<GLfloat>(GL_BITMAP_TOKEN));
  CHECK(buffer[4] == 13.0f);
  glDeleteLists(list, 1);
}

TEST_CASE("glut fonts: a stroke character is line strips within its advance, then a translation") {
  ScopedContext context(32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1000, 1000, -1000, 1000, -1, 1);  // model units = feedback units / 16
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  for (void* font : {GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN}) {
    for (int c = 33; c < 127; ++c) {
      std::vector<GLfloat> buffer(4096);
      glFeedbackBuffer(static_cast<GLsizei>(buffer.size()), GL_2D, buffer.data());
      glRenderMode(GL_FEEDBACK);
      glLoadIdentity();
      glutStrokeCharacter(font, c);
      const GLint count = glRenderMode(GL_RENDER);
      CAPTURE(c);
      REQUIRE(count > 0);
      // Window x = 16 + 16 * model x / 1000, y likewise.
      const float advance = glutStrokeWidthf(font, c);
      for (GLint i = 0; i < count;) {
        const GLfloat token = buffer[static_cast<std::size_t>(i)];
        REQUIRE((token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN));
        for (int k = 0; k < 2; ++k) {
          const float x = (buffer[static_cast<std::size_t>(i + 1 + 2 * k)] - 16.0f) * 1000.0f / 16.0f;
          const float y = (buffer[static_cast<std::size_t>(i + 2 + 2 * k)] - 16.0f) * 1000.0f / 16.0f;
          // Within half a model unit (1/128 pixel here) of the bounds.
          CHECK(x >= -0.5f);
          CHECK(x <= advance + 0.5f);
          CHECK(y >= -33.3f - 0.5f);
          CHECK(y <= 100.0f + 0.5f);
        }
        i += 5;
      }
      float tx = 0, ty = 0;
      modelviewTranslation(tx, ty);
      CHECK(tx == advance);
      CHECK(ty == 0.0f);
    }
  }
}

TEST_CASE("glut fonts: a stroke string translates by its advances and goes down a line at '\\n'") {
  ScopedContext context(32, 32);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glutStrokeString(GLUT_STROKE_MONO_ROMAN, text("ab\ncde"));
  float tx = 0, ty = 0;
  modelviewTranslation(tx, ty);
  // freeglut translates back by the first line's length, in float, and forward by each advance.
  CHECK(tx == doctest::Approx(3 * 104.762).epsilon(1e-6));
  CHECK(ty == -152.381f);

  // Characters the font lacks are skipped without moving; a space moves.
  glLoadIdentity();
  glutStrokeString(GLUT_STROKE_ROMAN, text("\t \x80"));
  modelviewTranslation(tx, ty);
  CHECK(tx == 104.762f);
  glLoadIdentity();
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 200);
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 9);
  modelviewTranslation(tx, ty);
  CHECK(tx == 0.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glut fonts: a font of the other kind, a bad character or no string does nothing") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  glRasterPos2i(4, 10);
  glutBitmapCharacter(GLUT_STROKE_ROMAN, 'A');
  glutBitmapCharacter(GLUT_BITMAP_9_BY_15, 0);
  glutBitmapCharacter(GLUT_BITMAP_9_BY_15, 256);
  glutBitmapCharacter(GLUT_BITMAP_9_BY_15, -3);
  glutBitmapCharacter(nullptr, 'A');
  glutBitmapString(GLUT_BITMAP_9_BY_15, nullptr);
  glutBitmapString(GLUT_STROKE_MONO_ROMAN, text("A"));
  glutStrokeCharacter(GLUT_BITMAP_HELVETICA_10, 'A');
  glutStrokeString(GLUT_BITMAP_HELVETICA_10, text("A"));
  glutStrokeString(GLUT_STROKE_ROMAN, nullptr);
  CHECK(rasterPosition().x == 4.0f);
  CHECK(inkBox(32, 32).empty());
  float tx = 0, ty = 0;
  modelviewTranslation(tx, ty);
  CHECK(tx == 0.0f);
  CHECK(glutBitmapWidth(GLUT_STROKE_ROMAN, 'A') == 0);
  CHECK(glutBitmapHeight(GLUT_STROKE_ROMAN) == 0);
  CHECK(glutBitmapLength(GLUT_STROKE_ROMAN, text("A")) == 0);
  CHECK(glutStrokeWidthf(GLUT_BITMAP_9_BY_15, 'A') == 0.0f);
  CHECK(glutStrokeHeight(GLUT_BITMAP_9_BY_15) == 0.0f);
  CHECK(glutStrokeLength(GLUT_BITMAP_9_BY_15, text("A")) == 0);
  CHECK(glGetError() == GL_NO_ERROR);

  // Between glBegin and glEnd the glBitmap inside is the GL error the specification gives.
  glBegin(GL_POINTS);
  glutBitmapCharacter(GLUT_BITMAP_9_BY_15, 'A');
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}
