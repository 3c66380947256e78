// glBitmap (spec 3.7) and polygon stipple (spec 3.5.2, glPolygonStipple, glGetPolygonStipple).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <cmath>
#include <cstring>
#include <limits>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

bool lit(int x, int y) {
  const Rgba p = pixelAt(x, y);
  return p.r != 0 || p.g != 0 || p.b != 0;
}

}  // namespace

TEST_CASE("pixels bitmap: set bits become fragments in the raster colour at floor(p - origin)") {
  ScopedContext context(16, 16);
  glass::test::pixelProjection(16, 16);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Two rows of 3 bits: 101 (bottom), 011 (top), most significant bit first.
  const GLubyte bits[2] = {0xA0, 0x60};
  glColor3f(1.0f, 0.0f, 0.0f);
  glRasterPos2f(5.7f, 4.2f);
  glColor3f(0.0f, 1.0f, 0.0f);  // after glRasterPos: not used
  glBitmap(3, 2, 1.5f, 0.0f, 0.0f, 0.0f, bits);
  // Lower left corner: (floor(5.7 - 1.5), floor(4.2)) = (4, 4).
  CHECK(pixelAt(4, 4) == Rgba{255, 0, 0, 255});
  CHECK_FALSE(lit(5, 4));
  CHECK(lit(6, 4));
  CHECK_FALSE(lit(4, 5));
  CHECK(lit(5, 5));
  CHECK(lit(6, 5));
  CHECK_FALSE(lit(7, 4));
  CHECK_FALSE(lit(4, 6));

  // GL_UNPACK_LSB_FIRST reads each byte from its lowest bit.
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  const GLubyte lsb[1] = {0x06};  // 0110 0000 read from the low bit: pixels 1 and 2
  glWindowPos2i(0, 0);
  glBitmap(4, 1, 0.0f, 0.0f, 0.0f, 0.0f, lsb);
  CHECK_FALSE(lit(0, 0));
  CHECK(lit(1, 0));
  CHECK(lit(2, 0));
  CHECK_FALSE(lit(3, 0));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels bitmap: a raster position a hair below an integer stays on that pixel") {
  ScopedContext context(8, 8);
  const GLubyte one = 0x80;
  glWindowPos2f(2.99999f, 3.0f);
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, &one);
  CHECK(lit(3, 3));
  CHECK_FALSE(lit(2, 3));
}

TEST_CASE("pixels bitmap: fragments go through the fragment operations") {
  ScopedContext context(8, 8);
  glass::test::pixelProjection(8, 8);
  const GLubyte full[1] = {0xFF};
  glEnable(GL_DEPTH_TEST);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glRasterPos3f(0.0f, 0.0f, -0.5f);  // depth 0.75: behind
  glBitmap(8, 1, 0.0f, 0.0f, 0.0f, 0.0f, full);
  CHECK_FALSE(lit(0, 0));
  glRasterPos3f(0.0f, 1.0f, 0.5f);  // depth 0.25: in front
  glBitmap(8, 1, 0.0f, 0.0f, 0.0f, 0.0f, full);
  CHECK(lit(0, 1));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels bitmap: errors and display lists") {
  ScopedContext context(16, 8);
  const GLubyte one = 0x80;
  glBitmap(-1, 1, 0.0f, 0.0f, 0.0f, 0.0f, &one);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glBegin(GL_POINTS);
  glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, &one);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);

  // A list draws with the bits and unpack state of compile time, moving the raster position
  // when executed.
  GLubyte bits = 0xC0;
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBitmap(2, 1, 0.0f, 0.0f, 3.0f, 0.0f, &bits);
  glEndList();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  bits = 0x00;
  glWindowPos2i(0, 0);
  glCallList(list);  // 0xC0 read from the low bit: no pixel of the first two
  glCallList(list);
  CHECK_FALSE(lit(0, 0));
  CHECK_FALSE(lit(3, 0));
  GLfloat position[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, position);
  CHECK(position[0] == 6.0f);

  const GLuint list2 = glGenLists(1);
  bits = 0xC0;
  glNewList(list2, GL_COMPILE);
  glBitmap(2, 1, 0.0f, 0.0f, 3.0f, 0.0f, &bits);
  glEndList();
  glCallList(list2);
  CHECK(lit(6, 0));
  CHECK(lit(7, 0));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels stipple: filled polygons keep the fragments whose pattern bit is set") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  // Pattern: row y has bit x set when (x + y) is a multiple of 3; rows as 4 bytes, MSB first.
  GLubyte pattern[32 * 4] = {};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if ((x + y) % 3 == 0) pattern[y * 4 + x / 8] |= static_cast<GLubyte>(0x80u >> (x % 8));
  glPolygonStipple(pattern);
  glEnable(GL_POLYGON_STIPPLE);
  glRectf(0.0f, 0.0f, 64.0f, 40.0f);
  for (int y = 0; y < 40; y += 7)
    for (int x = 0; x < 64; x += 5) {
      CAPTURE(x);
      CAPTURE(y);
      CHECK(lit(x, y) == (((x % 32) + (y % 32)) % 3 == 0));
    }
  // Lines and points are not stippled, nor polygons drawn as lines.
  glBegin(GL_LINES);
  glVertex2f(0.0f, 50.5f);
  glVertex2f(64.0f, 50.5f);
  glEnd();
  for (int x = 0; x < 64; ++x) CHECK(lit(x, 50));
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glRectf(10.5f, 44.5f, 30.5f, 48.5f);
  for (int x = 11; x < 30; ++x) CHECK(lit(x, 44));
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // Disabled: everything is drawn.
  glDisable(GL_POLYGON_STIPPLE);
  glClear(GL_COLOR_BUFFER_BIT);
  glRectf(0.0f, 0.0f, 8.0f, 8.0f);
  for (int x = 0; x < 8; ++x) CHECK(lit(x, 1));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels stipple: glGetPolygonStipple, the unpack and pack state, display lists") {
  ScopedContext context(16, 16);
  GLubyte out[128];
  glGetPolygonStipple(out);
  for (const GLubyte b : out) CHECK(b == 0xFF);  // initially all ones
  GLboolean enabled = GL_TRUE;
  glGetBooleanv(GL_POLYGON_STIPPLE, &enabled);
  CHECK(enabled == GL_FALSE);

  GLubyte pattern[128];
  for (int i = 0; i < 128; ++i) pattern[i] = static_cast<GLubyte>(i * 37 + 11);
  glPolygonStipple(pattern);
  glGetPolygonStipple(out);
  CHECK(std::memcmp(out, pattern, 128) == 0);
  // Packed LSB first, each byte comes back with its bits reversed.
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glGetPolygonStipple(out);
  GLubyte reversed = 0;
  for (int b = 0; b < 8; ++b)
    if (pattern[5] & (1u << b)) reversed |= static_cast<GLubyte>(0x80u >> b);
  CHECK(out[5] == reversed);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);

  // Compiled with the data of compile time.
  const GLuint list = glGenLists(1);
  GLubyte zeros[128] = {};
  glNewList(list, GL_COMPILE);
  glPolygonStipple(zeros);
  glEndList();
  zeros[0] = 0xFF;
  glGetPolygonStipple(out);
  CHECK(out[0] == pattern[0]);
  glCallList(list);
  glGetPolygonStipple(out);
  CHECK(out[0] == 0);
  glBegin(GL_TRIANGLES);
  glPolygonStipple(pattern);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("pixels bitmap: a raster position moved to infinity or a NaN zoom draws nothing and is no error") {
  ScopedContext context(16, 16);
  const GLubyte bits[8] = {0xFF, 0, 0, 0, 0xFF, 0, 0, 0};  // rows 4-byte aligned
  glWindowPos2i(2, 2);
  glBitmap(8, 2, 0.0f, 0.0f, 1e38f, 0.0f, bits);
  glBitmap(8, 2, 0.0f, 0.0f, 1e38f, 0.0f, bits);  // the position is now infinite
  glBitmap(8, 2, 0.0f, 0.0f, 0.0f, 0.0f, bits);
  CHECK(glGetError() == GL_NO_ERROR);
  int drawn = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) drawn += lit(x, y) ? 1 : 0;
  CHECK(drawn == 16);  // only the first bitmap
  const GLubyte white[4] = {255, 255, 255, 255};
  glClear(GL_COLOR_BUFFER_BIT);
  glWindowPos2i(4, 4);
  const float nan = std::nanf("");
  glPixelZoom(nan, 1.0f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glPixelZoom(1.0f, -std::numeric_limits<float>::infinity());
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK_FALSE(lit(4, 4));
  CHECK_FALSE(lit(4, 3));
}

TEST_CASE("pixels bitmap: between glBegin and glEnd glBitmap and glDrawPixels read no client data") {
  ScopedContext context(8, 8);
  // Nothing may be read from a null pointer's worth of data the unpack state says is there: the
  // commands are refused before reading.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 1 << 20);
  const GLubyte one[1] = {0x80};
  glBegin(GL_POINTS);
  glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, one);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, one);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}
