// glReadPixels (spec 4.3.2): bottom row first, laid out by GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH,
// GL_PACK_SKIP_PIXELS and GL_PACK_SKIP_ROWS, in each format and type.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <vector>

#include "pipeline_test_support.h"
#include "texture/client_pixels.h"

using glass::test::ScopedContext;

namespace {

// Pixel (x, y) gets colour (10 x, 10 y + 1, 200, 255), drawn as points at pixel centres.
void drawPattern(int width, int height) {
  glass::test::pixelProjection(width, height);
  glBegin(GL_POINTS);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      glColor4ub(static_cast<GLubyte>(10 * x), static_cast<GLubyte>(10 * y + 1), 200, 255);
      glVertex2f(x + 0.5f, y + 0.5f);
    }
  }
  glEnd();
}

constexpr uint8_t kUntouched = 0xEE;

}  // namespace

TEST_CASE("pipeline read pixels: GL_RGB rows are padded to GL_PACK_ALIGNMENT") {
  ScopedContext context(8, 8);
  drawPattern(8, 8);
  // A 3 x 2 block of RGB is 9 bytes a row: the stride is 9, 10, 12 or 16 for alignments 1-8.
  const struct {
    int alignment, stride;
  } cases[] = {{1, 9}, {2, 10}, {4, 12}, {8, 16}};
  for (const auto& c : cases) {
    CAPTURE(c.alignment);
    std::vector<uint8_t> buffer(64, kUntouched);
    glPixelStorei(GL_PACK_ALIGNMENT, c.alignment);
    glReadPixels(1, 2, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, buffer.data());
    for (int row = 0; row < 2; ++row) {
      for (int x = 0; x < 3; ++x) {
        const uint8_t* p = &buffer[row * c.stride + 3 * x];
        CHECK(p[0] == 10 * (1 + x));
        CHECK(p[1] == 10 * (2 + row) + 1);  // bottom row first
        CHECK(p[2] == 200);
      }
      // Padding bytes are not written.
      for (int i = 9; i < c.stride && row == 0; ++i) CHECK(buffer[i] == kUntouched);
    }
    CHECK(buffer[c.stride + 9] == kUntouched);
  }
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline read pixels: row length and skips place the block inside a larger image") {
  ScopedContext context(8, 8);
  drawPattern(8, 8);
  std::vector<uint8_t> buffer(400, kUntouched);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 6);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, buffer.data());
  const int stride = 6 * 4;
  for (int row = 0; row < 2; ++row) {
    for (int x = 0; x < 2; ++x) {
      const uint8_t* p = &buffer[(1 + row) * stride + (2 + x) * 4];
      CHECK(p[0] == 10 * x);
      CHECK(p[1] == 10 * row + 1);
      CHECK(p[3] == 255);
    }
  }
  CHECK(buffer[0] == kUntouched);
  CHECK(buffer[stride + 4] == kUntouched);  // the skipped pixel before the block
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
}

TEST_CASE("pipeline read pixels: formats, types, depth and stencil") {
  ScopedContext context(8, 8);
  drawPattern(8, 8);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);

  uint8_t bgra[4];
  glReadPixels(3, 4, 1, 1, GL_BGRA, GL_UNSIGNED_BYTE, bgra);
  CHECK((bgra[0] == 200 && bgra[1] == 41 && bgra[2] == 30 && bgra[3] == 255));
  uint8_t green;
  glReadPixels(3, 4, 1, 1, GL_GREEN, GL_UNSIGNED_BYTE, &green);
  CHECK(green == 41);
  uint8_t luminance;  // R + G + B, clamped
  glReadPixels(3, 4, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, &luminance);
  CHECK(luminance == 255);
  float rgba[4];
  glReadPixels(3, 4, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  CHECK(rgba[0] == doctest::Approx(30 / 255.0));
  CHECK(rgba[2] == doctest::Approx(200 / 255.0));
  GLushort rgba16[4];
  glReadPixels(3, 4, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, rgba16);
  CHECK(rgba16[0] == 30 * 257);  // (2^16 - 1) c
  CHECK(rgba16[3] == 65535);

  glClearDepth(0.25);
  glClearStencil(0x42);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  float depth = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  CHECK(depth == doctest::Approx(0.25).epsilon(1e-6));
  GLuint depth32 = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth32);
  CHECK(static_cast<double>(depth32) == doctest::Approx(0.25 * 4294967295.0).epsilon(1e-6));
  uint8_t stencil = 0;
  glReadPixels(5, 5, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  CHECK(stencil == 0x42);

  // Pixels outside the framebuffer are left as they were.
  uint8_t outside[8];
  std::fill(outside, outside + 8, kUntouched);
  glReadPixels(7, 7, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, outside);
  CHECK(outside[0] == 70);
  CHECK(outside[4] == kUntouched);
  CHECK(glGetError() == GL_NO_ERROR);
}

// glReadPixels copies stored bytes for GL_UNSIGNED_BYTE colour formats without luminance
// (packByteColorSpan) instead of taking each byte b as b / 255 and converting it back. The copy
// must write exactly what the conversion writes: every byte value, in every format it takes,
// with padding, row length and skips that place the span inside a larger block.
TEST_CASE("pack_byte_color_span_matches_floats") {
  using glass::gl::PixelLayout;
  std::vector<uint8_t> bytes(256 * 4);
  for (int i = 0; i < 256; ++i)
    for (int k = 0; k < 4; ++k) bytes[static_cast<size_t>(i) * 4 + k] = static_cast<uint8_t>((i + 67 * k) & 255);
  std::vector<float> floats(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) floats[i] = static_cast<float>(bytes[i]) / 255.0f;

  const GLenum formats[] = {GL_RGBA, GL_BGRA, GL_RGB, GL_BGR, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
  for (const GLenum format : formats) {
    for (const int alignment : {1, 2, 4, 8}) {
      PixelLayout layout{};
      layout.alignment = alignment;
      layout.rowLength = 300;
      layout.skipPixels = 3;
      layout.skipRows = 1;
      CAPTURE(format);
      CAPTURE(alignment);
      std::vector<uint8_t> copied(300 * 4 * 4 + 64, kUntouched), converted = copied;
      const int width = 260, column = 2, row = 1;
      REQUIRE(glass::gl::packByteColorSpan(bytes.data(), 256, width, column, row, format,
                                           GL_UNSIGNED_BYTE, layout, copied.data()));
      glass::gl::packColorSpan(floats.data(), 256, width, column, row, format, GL_UNSIGNED_BYTE,
                               layout, glass::gl::LuminancePacking::Sum, converted.data());
      CHECK(copied == converted);
    }
  }
  // What it does not take is left to the conversion, with nothing written.
  PixelLayout layout{};
  std::vector<uint8_t> untouched(64, kUntouched), buffer = untouched;
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                                           layout, buffer.data()));
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_RGBA, GL_UNSIGNED_SHORT,
                                           layout, buffer.data()));
  CHECK_FALSE(glass::gl::packByteColorSpan(bytes.data(), 4, 4, 0, 0, GL_LUMINANCE_ALPHA,
                                           GL_UNSIGNED_BYTE, layout, buffer.data()));
  CHECK(buffer == untouched);
}
