// glDrawPixels, glCopyPixels, glPixelZoom, glPixelTransfer, glPixelMap and glReadPixels through
// the transfer operations (spec 3.6.3-3.6.5, 4.3.1-4.3.3).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "core/fast_paths.h"
#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;
using glass::test::stencilAt;

namespace {

float depthAt(int x, int y) {
  float d = -1.0f;
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  return d;
}

// A 2 x 2 RGBA image: red, green (bottom row), blue, white (top row).
const GLubyte kQuad[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

}  // namespace

TEST_CASE("pixels draw: an RGBA image lands at the raster position, bottom row first") {
  ScopedContext context(16, 16);
  glWindowPos2i(3, 5);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  CHECK(pixelAt(3, 5) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(4, 5) == Rgba{0, 255, 0, 255});
  CHECK(pixelAt(3, 6) == Rgba{0, 0, 255, 255});
  CHECK(pixelAt(4, 6) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(5, 5) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(3, 7) == Rgba{0, 0, 0, 0});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: every 8-bit value comes back unchanged") {
  ScopedContext context(256, 1);
  std::vector<GLubyte> row(256 * 4);
  for (int i = 0; i < 256; ++i) {
    row[i * 4 + 0] = static_cast<GLubyte>(i);
    row[i * 4 + 1] = static_cast<GLubyte>(255 - i);
    row[i * 4 + 2] = static_cast<GLubyte>(i * 7);
    row[i * 4 + 3] = static_cast<GLubyte>(i ^ 0x5A);
  }
  glWindowPos2i(0, 0);
  glDrawPixels(256, 1, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
  CHECK(glass::test::readFramebuffer(256, 1) == row);
  // And through glCopyPixels onto itself.
  glWindowPos2i(0, 0);
  glCopyPixels(0, 0, 256, 1, GL_COLOR);
  CHECK(glass::test::readFramebuffer(256, 1) == row);
}

TEST_CASE("pixels draw: formats expand to RGBA as section 3.6.4 says") {
  ScopedContext context(8, 8);
  const GLubyte value[2] = {51, 204};
  struct Case {
    GLenum format;
    Rgba expected;
  } cases[] = {
      {GL_LUMINANCE, {51, 51, 51, 255}}, {GL_LUMINANCE_ALPHA, {51, 51, 51, 204}},
      {GL_ALPHA, {0, 0, 0, 51}},         {GL_RED, {51, 0, 0, 255}},
      {GL_GREEN, {0, 51, 0, 255}},       {GL_BLUE, {0, 0, 51, 255}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.format);
    glClear(GL_COLOR_BUFFER_BIT);
    glWindowPos2i(1, 1);
    glDrawPixels(1, 1, c.format, GL_UNSIGNED_BYTE, value);
    CHECK(pixelAt(1, 1) == c.expected);
  }
  const GLfloat rgb[3] = {0.2f, 1.5f, -0.5f};  // clamped
  glWindowPos2i(2, 2);
  glDrawPixels(1, 1, GL_RGB, GL_FLOAT, rgb);
  CHECK(pixelAt(2, 2) == Rgba{51, 255, 0, 255});
  const GLushort bgra[4] = {0, 65535, 65535, 32768};
  glWindowPos2i(3, 3);
  glDrawPixels(1, 1, GL_BGRA, GL_UNSIGNED_SHORT, bgra);
  CHECK(pixelAt(3, 3) == Rgba{255, 255, 0, 128});
  const GLushort rgb565 = (31u << 11) | (0u << 5) | 31u;
  glWindowPos2i(4, 4);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &rgb565);
  CHECK(pixelAt(4, 4) == Rgba{255, 0, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: the unpack parameters select the image") {
  ScopedContext context(8, 8);
  // A 4 x 3 luminance image of values 10 * (row * 4 + column), rows padded to 8 bytes.
  GLubyte image[3][8] = {};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) image[j][i] = static_cast<GLubyte>(10 * (j * 4 + i));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, image);
  CHECK(pixelAt(0, 0).r == 50);
  CHECK(pixelAt(1, 0).r == 60);
  CHECK(pixelAt(0, 1).r == 90);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 8);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glWindowPos2i(4, 4);
  glDrawPixels(2, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, image);
  CHECK(pixelAt(4, 4).r == 20);
  CHECK(pixelAt(5, 6).r == 110);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: zoom replicates and mirrors pixels from the rounded raster position") {
  ScopedContext context(16, 16);
  glWindowPos2f(4.4f, 6.6f);  // rounds to the corner (4, 7)
  glPixelZoom(2.0f, 3.0f);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  CHECK(pixelAt(4, 7) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(5, 9) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(6, 7) == Rgba{0, 255, 0, 255});
  CHECK(pixelAt(7, 12) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(8, 7) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(4, 13) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(3, 7) == Rgba{0, 0, 0, 0});

  glClear(GL_COLOR_BUFFER_BIT);
  glWindowPos2i(10, 10);
  glPixelZoom(-1.0f, -1.0f);  // image pixel (0, 0) covers window pixel (9, 9)
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  CHECK(pixelAt(9, 9) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(8, 9) == Rgba{0, 255, 0, 255});
  CHECK(pixelAt(8, 8) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(10, 10) == Rgba{0, 0, 0, 0});

  glClear(GL_COLOR_BUFFER_BIT);
  // Two image columns share one window column: the one whose rectangle [0.5 n, 0.5 (n + 1))
  // holds the pixel centre 0.5 shows, column 1 (as in Mesa).
  glPixelZoom(0.5f, 1.0f);
  glWindowPos2i(0, 0);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  CHECK(pixelAt(0, 0) == Rgba{0, 255, 0, 255});
  CHECK(pixelAt(0, 1) == Rgba{255, 255, 255, 255});
  CHECK(pixelAt(1, 0) == Rgba{0, 0, 0, 0});
  GLfloat zoom[2];
  glGetFloatv(GL_ZOOM_X, &zoom[0]);
  glGetFloatv(GL_ZOOM_Y, &zoom[1]);
  CHECK(zoom[0] == 0.5f);
  CHECK(zoom[1] == 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: fragments take the raster depth, texture-free colour, and the tests") {
  ScopedContext context(8, 8);
  glass::test::pixelProjection(8, 8);
  glEnable(GL_DEPTH_TEST);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLubyte white[4] = {255, 255, 255, 255};
  glRasterPos3f(1.0f, 1.0f, 0.5f);  // window depth 0.25: passes GL_LESS against 0.5
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  CHECK(pixelAt(1, 1) == Rgba{255, 255, 255, 255});
  CHECK(depthAt(1, 1) == doctest::Approx(0.25).epsilon(1e-6));
  glRasterPos3f(2.0f, 1.0f, -0.5f);  // window depth 0.75: fails
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  CHECK(pixelAt(2, 1) == Rgba{0, 0, 0, 0});

  // The scissor test applies.
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 0, 8, 8);
  glWindowPos2i(3, 3);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  CHECK(pixelAt(3, 3) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(4, 3) == Rgba{0, 255, 0, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: nothing happens at an invalid raster position") {
  ScopedContext context(8, 8);
  glRasterPos2f(2.0f, 0.0f);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  for (const uint8_t v : glass::test::readFramebuffer(8, 8)) CHECK(v == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: depth and stencil images") {
  ScopedContext context(8, 8);
  glass::test::pixelProjection(8, 8);
  const GLfloat depths[2] = {0.25f, 0.75f};
  glColor3f(1.0f, 0.5f, 0.0f);
  glRasterPos2i(1, 1);  // the colour is the raster colour
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  CHECK(depthAt(1, 1) == doctest::Approx(0.25).epsilon(1e-6));
  CHECK(depthAt(2, 1) == doctest::Approx(0.75).epsilon(1e-6));
  CHECK(pixelAt(2, 1) == Rgba{255, 128, 0, 255});
  glDisable(GL_DEPTH_TEST);

  // Stencil indices: masked to 8 bits and by the write mask, no other fragment operation.
  const GLuint indices[3] = {5, 0x1FF, 2};
  glStencilMask(0x0F);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xFF);  // would reject every fragment
  glWindowPos2i(4, 4);
  glDrawPixels(3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, indices);
  CHECK(stencilAt(4, 4) == 5);
  CHECK(stencilAt(5, 4) == 0x0F);
  CHECK(stencilAt(6, 4) == 2);
  CHECK(pixelAt(4, 4) == Rgba{0, 0, 0, 0});  // no colour is written
  // Index shift and offset, and the stencil map.
  glStencilMask(0xFF);
  glPixelTransferi(GL_INDEX_SHIFT, 2);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  // (glReadPixels applies them too: they are reset before each read.)
  auto drawStencil = [&](bool map) {
    glPixelTransferi(GL_INDEX_SHIFT, 2);
    glPixelTransferi(GL_INDEX_OFFSET, 1);
    glPixelTransferi(GL_MAP_STENCIL, map ? GL_TRUE : GL_FALSE);
    glWindowPos2i(0, 6);
    glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, indices);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  };
  drawStencil(false);
  CHECK(stencilAt(0, 6) == 21);
  const GLuint map[2] = {7, 9};
  glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, map);
  drawStencil(true);
  CHECK(stencilAt(0, 6) == 9);  // 21 selects entry 21 mod 2
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: scale, bias and the colour maps") {
  ScopedContext context(8, 8);
  const GLubyte gray[4] = {102, 102, 102, 255};  // 0.4
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferf(GL_GREEN_BIAS, -0.2f);
  glPixelTransferf(GL_BLUE_SCALE, 3.0f);  // 1.2, clamped
  glPixelTransferf(GL_ALPHA_BIAS, -1.0f);
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, gray);
  // (glReadPixels applies the transfer operations too: reset them before reading.)
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferf(GL_BLUE_SCALE, 1.0f);
  glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
  CHECK(pixelAt(0, 0) == Rgba{204, 51, 255, 0});

  // GL_MAP_COLOR: after scale and bias, component c picks entry round(c * (size - 1)).
  const GLfloat red[4] = {0.0f, 0.2f, 0.6f, 1.0f};  // 0.4 * 3 = 1.2: entry 1
  const GLfloat green[2] = {1.0f, 0.0f};            // 0.4: entry 0
  const GLfloat blue[3] = {0.0f, 0.5f, 1.0f};       // 0.6 * 2 = 1.2: entry 1
  const GLushort alpha[1] = {32768};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, red);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, green);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 3, blue);
  glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 1, alpha);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  const GLfloat rgba[4] = {0.4f, 0.4f, 0.6f, 1.0f};
  glDrawPixels(1, 1, GL_RGBA, GL_FLOAT, rgba);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  CHECK(pixelAt(0, 0) == Rgba{51, 255, 128, 128});

  // Colour indices: shift and offset, then the I_TO_* maps (indices modulo the map size).
  const GLfloat toRed[2] = {0.2f, 0.8f}, toOne[1] = {1.0f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, toRed);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 1, toOne);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 1, toOne);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, toOne);
  const GLubyte index[2] = {2, 3};
  glWindowPos2i(2, 2);
  glDrawPixels(2, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, index);
  CHECK(pixelAt(2, 2) == Rgba{51, 255, 255, 255});
  CHECK(pixelAt(3, 2) == Rgba{204, 255, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: glPixelMap and glGetPixelMap, sizes and errors") {
  ScopedContext context(8, 8);
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  CHECK(size == 1);
  glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, &size);
  CHECK(size == 256);
  const GLfloat values[3] = {-0.5f, 0.25f, 2.0f};
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 3, values);
  glGetIntegerv(GL_PIXEL_MAP_B_TO_B_SIZE, &size);
  CHECK(size == 3);
  GLfloat back[3];
  glGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, back);
  CHECK(back[0] == 0.0f);  // colour maps are clamped
  CHECK(back[1] == 0.25f);
  CHECK(back[2] == 1.0f);
  GLushort asShort[3];
  glGetPixelMapusv(GL_PIXEL_MAP_B_TO_B, asShort);
  CHECK(asShort[1] == 16384);
  const GLuint indices[4] = {3, 70000, 5, 6};
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, indices);
  GLuint indicesBack[4];
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, indicesBack);
  CHECK(indicesBack[1] == 70000);
  CHECK(glGetError() == GL_NO_ERROR);

  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, values);  // index maps need a power-of-two size
  CHECK(glGetError() == GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, values);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, values);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glPixelMapfv(GL_RED_SCALE, 1, values);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetPixelMapfv(GL_ZOOM_X, back);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glPixelTransferf(GL_ZOOM_X, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("pixels draw: glPixelTransfer queries") {
  ScopedContext context(8, 8);
  glPixelTransferf(GL_DEPTH_SCALE, 2.5f);
  glPixelTransferi(GL_INDEX_SHIFT, -3);
  glPixelTransferi(GL_MAP_STENCIL, 1);
  GLfloat f = 0.0f;
  glGetFloatv(GL_DEPTH_SCALE, &f);
  CHECK(f == 2.5f);
  GLint i = 0;
  glGetIntegerv(GL_INDEX_SHIFT, &i);
  CHECK(i == -3);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_MAP_STENCIL, &b);
  CHECK(b == GL_TRUE);
  glGetFloatv(GL_RED_SCALE, &f);
  CHECK(f == 1.0f);
  glGetFloatv(GL_ALPHA_BIAS, &f);
  CHECK(f == 0.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: errors of glDrawPixels and glCopyPixels") {
  ScopedContext context(8, 8);
  const GLubyte data[16] = {};
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glDrawPixels(1, 1, GL_RGBA8, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_DOUBLE, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGB, GL_BITMAP, data);  // bitmaps hold indices only
  CHECK(glGetError() == GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, data);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8, data);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glCopyPixels(0, 0, -1, 1, GL_COLOR);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("pixels draw: display lists keep the image as unpacked when compiled") {
  ScopedContext context(8, 8);
  GLubyte image[4] = {10, 20, 30, 40};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glWindowPos2i(0, 0);
  glDrawPixels(2, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, image);
  glEndList();
  CHECK(pixelAt(0, 0).r == 0);  // compiled, not executed
  image[1] = 99;                // changing the client memory later changes nothing
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelTransferf(GL_RED_SCALE, 0.5f);  // the transfer state of execution applies
  glCallList(list);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  CHECK(pixelAt(0, 0) == Rgba{10, 20, 20, 255});
  CHECK(pixelAt(1, 0) == Rgba{15, 30, 30, 255});
  // An error in a compiled command appears when the list runs.
  const GLuint bad = glGenLists(1);
  glNewList(bad, GL_COMPILE);
  glDrawPixels(1, 1, GL_RGB, GL_BITMAP, image);
  glEndList();
  CHECK(glGetError() == GL_NO_ERROR);
  glCallList(bad);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("pixels copy: overlapping copies, zoom, depth and stencil") {
  ScopedContext context(16, 4);
  // A row of distinct colours, then a copy of it one pixel to the right, over itself.
  std::vector<GLubyte> row(8 * 4);
  for (int i = 0; i < 8; ++i) {
    row[i * 4 + 0] = static_cast<GLubyte>(20 * i + 10);
    row[i * 4 + 3] = 255;
  }
  glWindowPos2i(0, 0);
  glDrawPixels(8, 1, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
  glWindowPos2i(1, 0);
  glCopyPixels(0, 0, 8, 1, GL_COLOR);
  CHECK(pixelAt(0, 0).r == 10);
  for (int i = 0; i < 8; ++i) CHECK(pixelAt(i + 1, 0).r == 20 * i + 10);

  // Zoomed copy, with the transfer operations.
  glPixelZoom(2.0f, 2.0f);
  glPixelTransferf(GL_RED_BIAS, 0.25f);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 0, 2, 1, GL_COLOR);
  glPixelTransferf(GL_RED_BIAS, 0.0f);
  glPixelZoom(1.0f, 1.0f);
  CHECK(pixelAt(10, 1).r == 74);  // 10 + 63.75
  CHECK(pixelAt(11, 2).r == 74);
  CHECK(pixelAt(12, 1).r == 94);
  CHECK(pixelAt(14, 1).r == 0);

  // Depth: copied depths with the raster colour.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  const GLfloat depths[2] = {0.125f, 0.625f};
  glWindowPos2i(0, 3);
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  glColor3f(0.0f, 1.0f, 0.0f);
  glWindowPos2i(4, 3);
  glCopyPixels(0, 3, 2, 1, GL_DEPTH);
  CHECK(depthAt(4, 3) == doctest::Approx(0.125).epsilon(1e-6));
  CHECK(depthAt(5, 3) == doctest::Approx(0.625).epsilon(1e-6));
  CHECK(pixelAt(5, 3) == Rgba{0, 255, 0, 255});
  glDisable(GL_DEPTH_TEST);

  // Stencil.
  const GLubyte stencil[2] = {3, 200};
  glWindowPos2i(8, 3);
  glDrawPixels(2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  glWindowPos2i(12, 3);
  glCopyPixels(8, 3, 2, 1, GL_STENCIL);
  CHECK(stencilAt(12, 3) == 3);
  CHECK(stencilAt(13, 3) == 200);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels read: glReadPixels goes through the transfer operations") {
  ScopedContext context(4, 4);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.5f);
  GLubyte rgb[3] = {};
  glReadPixels(1, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  CHECK(rgb[0] == 102);
  CHECK(rgb[1] == 102);
  CHECK(rgb[2] == 255);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  // Luminance is R + G + B, clamped.
  GLfloat luminance = 0.0f;
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(0, 0, 1, 1, GL_LUMINANCE, GL_FLOAT, &luminance);
  CHECK(luminance == doctest::Approx(3.0f * 51.0f / 255.0f));
  // Depth scale and bias.
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
  GLfloat depth = 0.0f;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  CHECK(depth == doctest::Approx(0.375).epsilon(1e-6));
  // Stencil index offset, and packing as a bitmap.
  glClearStencil(6);
  glClear(GL_STENCIL_BUFFER_BIT);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  GLubyte s = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  CHECK(s == 7);
  GLubyte bits = 0;
  glReadPixels(0, 0, 4, 1, GL_STENCIL_INDEX, GL_BITMAP, &bits);
  CHECK(bits == 0xF0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels draw: glCopyPixels reads only the part of its rectangle inside the framebuffer") {
  ScopedContext context(16, 16);
  glWindowPos2i(0, 0);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kQuad);
  // The source starts 3 pixels left of and 1 below the framebuffer: its pixel (3, 1) is the
  // framebuffer's (0, 0), and lands 3 columns and 1 row from the destination's corner, zoomed.
  glWindowPos2i(4, 6);
  glPixelZoom(2.0f, 3.0f);
  glCopyPixels(-3, -1, 5, 3, GL_COLOR);
  CHECK(pixelAt(4 + 6, 6 + 3) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(4 + 7, 6 + 5) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(4 + 8, 6 + 3) == Rgba{0, 255, 0, 255});
  CHECK(pixelAt(4 + 6, 6 + 6) == Rgba{0, 0, 255, 255});
  // Nothing is drawn for the part outside the framebuffer (undefined in GL).
  CHECK(pixelAt(4, 6) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(4 + 5, 6 + 2) == Rgba{0, 0, 0, 0});
  // A huge rectangle costs no more than the framebuffer, and is no error.
  glPixelZoom(1.0f, 1.0f);
  glWindowPos2i(8, 0);
  glCopyPixels(0, 0, 1 << 30, 1 << 30, GL_COLOR);
  CHECK(pixelAt(8, 0) == Rgba{255, 0, 0, 255});
  CHECK(pixelAt(9, 1) == Rgba{255, 255, 255, 255});
  glCopyPixels(-(1 << 30), -(1 << 30), 1 << 30, 1 << 30, GL_DEPTH);
  CHECK(glGetError() == GL_NO_ERROR);
}

// glDrawPixels of unsigned bytes without zoom, transfer operations or fragment operations puts
// the bytes in the colour buffer directly (drawPixelBytes); it must draw what the reference path
// draws. Every colour format, unpack layouts, images partly off each side of the window, the
// scissor box, a triangle still queued under the image, and states that leave the image to the
// reference path (blending, a zoom, a scale) drawn both ways too.
TEST_CASE("pixels draw: the byte fast path draws what the reference path draws") {
  const int size = 24;
  const GLenum formats[] = {GL_RGBA, GL_BGRA, GL_RGB, GL_BGR, GL_RED, GL_GREEN,
                            GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
  struct Placement {
    int x, y, width, height;
  };
  const Placement placements[] = {{3, 4, 9, 7}, {-5, 2, 12, 6}, {18, 19, 11, 9}, {-3, -4, 30, 31}, {2, 30, 5, 5}};
  std::vector<GLubyte> client(64 * 64 * 4 + 64);
  for (size_t i = 0; i < client.size(); ++i) client[i] = static_cast<GLubyte>((i * 13 + i / 7) & 255);

  const auto draw = [&](bool fast, GLenum format, const Placement& p, int alignment, int state) {
    glass::gl::ScopedFastPaths paths(fast);
    ScopedContext context(size, size);
    glass::test::pixelProjection(size, size);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);  // queued, under part of the image
    glColor3ub(200, 10, 90);
    glVertex2f(0, 0);
    glVertex2f(20, 3);
    glVertex2f(6, 22);
    glEnd();
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, p.width + 3);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    if (state == 1) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(5, 3, 11, 14);
    } else if (state == 2) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else if (state == 3) {
      glPixelZoom(2.0f, -1.0f);
    } else if (state == 4) {
      glPixelTransferf(GL_GREEN_SCALE, 0.5f);
    }
    glWindowPos2i(p.x, p.y);
    glDrawPixels(p.width, p.height, format, GL_UNSIGNED_BYTE, client.data());
    CHECK(glGetError() == GL_NO_ERROR);
    return glass::test::readFramebuffer(size, size);
  };
  for (const GLenum format : formats)
    for (const Placement& p : placements)
      for (const int alignment : {1, 4, 8})
        for (int state = 0; state < 5; ++state) {
          CAPTURE(format);
          CAPTURE(p.x);
          CAPTURE(p.y);
          CAPTURE(alignment);
          CAPTURE(state);
          CHECK(draw(true, format, p, alignment, state) == draw(false, format, p, alignment, state));
        }
}
