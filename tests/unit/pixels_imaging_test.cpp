// The imaging subset (OpenGL 1.4 specification, sections 3.6.3 and 3.6.5; GL_ARB_imaging): colour
// tables, convolution, the colour matrix, histogram and minmax, each checked stage by stage on
// pixels whose results are worked out by hand here, through glDrawPixels, glReadPixels and
// glCopyPixels; their queries, errors, attribute groups and display list behaviour.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// Draws one RGBA pixel at (x, y).
void drawPixel(int x, int y, Rgba c) {
  glWindowPos2i(x, y);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &c);
}

// A 4-entry table, entry i = (10 + i, 50 + i, 100 + i, 200 + i).
void loadTable(GLenum internalFormat) {
  GLubyte table[16];
  for (int i = 0; i < 4; ++i) {
    table[i * 4 + 0] = static_cast<GLubyte>(10 + i);
    table[i * 4 + 1] = static_cast<GLubyte>(50 + i);
    table[i * 4 + 2] = static_cast<GLubyte>(100 + i);
    table[i * 4 + 3] = static_cast<GLubyte>(200 + i);
  }
  glColorTable(GL_COLOR_TABLE, internalFormat, 4, GL_RGBA, GL_UNSIGNED_BYTE, table);
}

// A 4 x 3 luminance image, row 0 first: 8 16 24 32 / 40 48 56 64 / 72 80 88 96.
const GLubyte kImage[12] = {8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96};

// A 3 x 3 luminance filter: 0.25 at the four neighbours of the centre, 0 elsewhere.
const GLfloat kCross[9] = {0, 0.25f, 0, 0.25f, 0, 0.25f, 0, 0.25f, 0};

void drawImage() {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(4, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, kImage);
}

uint8_t red(int x, int y) { return pixelAt(x, y).r; }

}  // namespace

TEST_CASE("imaging: GL_ARB_imaging is advertised and every enable starts off") {
  ScopedContext context(4, 4);
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  CHECK((" " + extensions + " ").find(" GL_ARB_imaging ") != std::string::npos);
  for (GLenum cap : {GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE,
                     GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D, GL_HISTOGRAM, GL_MINMAX}) {
    CAPTURE(cap);
    CHECK(glIsEnabled(cap) == GL_FALSE);
    glEnable(cap);
    CHECK(glIsEnabled(cap) == GL_TRUE);
    glDisable(cap);
  }
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: a colour table replaces the components its format names (table 3.17)") {
  ScopedContext context(4, 4);
  // The pixel (0, 85, 170, 255) selects entries 0, 1, 2 and 3 of a 4-entry table.
  const Rgba in{0, 85, 170, 255};
  struct Case {
    GLenum format;
    Rgba expected;
  } cases[] = {
      {GL_RGBA, {10, 51, 102, 203}},
      {GL_RGB, {10, 51, 102, 255}},
      {GL_ALPHA, {0, 85, 170, 203}},
      // Luminance and intensity are the table's R (table 3.15), each component its own index.
      {GL_LUMINANCE, {10, 11, 12, 255}},
      {GL_LUMINANCE_ALPHA, {10, 11, 12, 203}},
      {GL_INTENSITY, {10, 11, 12, 13}},
      {GL_RGBA8, {10, 51, 102, 203}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.format);
    loadTable(c.format);
    glEnable(GL_COLOR_TABLE);
    drawPixel(1, 1, in);
    glDisable(GL_COLOR_TABLE);  // glReadPixels would look the pixel up again
    CHECK(pixelAt(1, 1) == c.expected);
    GLint format = 0, width = 0;
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_FORMAT, &format);
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &width);
    CHECK(format == static_cast<GLint>(c.format));
    CHECK(width == 4);
  }
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: colour table scale and bias apply when the table is specified, and it reads back") {
  ScopedContext context(4, 4);
  const GLfloat scale[4] = {2, 1, 1, 1}, bias[4] = {0, 0, 0, -0.5f};
  glColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE, scale);
  glColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_BIAS, bias);
  loadTable(GL_RGBA);
  GLubyte entries[16];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, entries);
  // R doubled; A = (200 + i) / 255 - 0.5, as bytes round(255 a - 127.5).
  CHECK(entries[0] == 20);
  CHECK(entries[4] == 22);
  CHECK(entries[1] == 50);
  CHECK(entries[3] == 73);   // 200 - 127.5 = 72.5, to even
  CHECK(entries[7] == 74);   // 73.5
  GLfloat got[4];
  glGetColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE, got);
  CHECK(got[0] == 2.0f);
  // Luminance tables read back with L in R, G = B = 0 and A = 1 (table 6.1).
  loadTable(GL_LUMINANCE);
  glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, entries);
  CHECK(entries[0] == 20);
  CHECK(entries[1] == 0);
  CHECK(entries[2] == 0);
  CHECK(entries[3] == 255);
  GLint size = -1;
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_LUMINANCE_SIZE, &size);
  CHECK(size == 8);
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_RED_SIZE, &size);
  CHECK(size == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: glColorSubTable and glCopyColorSubTable replace entries; glCopyColorTable reads the buffer") {
  ScopedContext context(8, 8);
  loadTable(GL_RGBA);
  const GLubyte two[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glColorSubTable(GL_COLOR_TABLE, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, two);
  GLubyte entries[16];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, entries);
  CHECK(entries[0] == 10);
  CHECK(entries[4] == 1);
  CHECK(entries[11] == 8);
  CHECK(entries[12] == 13);
  glColorSubTable(GL_COLOR_TABLE, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, two);  // past the end
  CHECK(glGetError() == GL_INVALID_VALUE);

  drawPixel(2, 3, Rgba{40, 41, 42, 43});
  drawPixel(3, 3, Rgba{44, 45, 46, 47});
  glCopyColorSubTable(GL_COLOR_TABLE, 0, 2, 3, 1);
  glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, entries);
  CHECK(entries[0] == 40);
  CHECK(entries[3] == 43);
  glCopyColorTable(GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_RGB, 2, 3, 2);
  glGetColorTable(GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, entries);
  CHECK(entries[4] == 44);
  CHECK(entries[7] == 255);  // an RGB table has no alpha
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: a 3x3 convolution in GL_REDUCE mode shrinks the image by the filter size less one") {
  ScopedContext context(8, 8);
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, kCross);
  glEnable(GL_CONVOLUTION_2D);
  drawImage();
  glDisable(GL_CONVOLUTION_2D);
  // C[i,0] = (Cs[i+1,0] + Cs[i,1] + Cs[i+2,1] + Cs[i+1,2]) / 4.
  CHECK(pixelAt(0, 0) == Rgba{48, 48, 48, 255});  // (16 + 40 + 56 + 80) / 4
  CHECK(pixelAt(1, 0) == Rgba{56, 56, 56, 255});  // (24 + 48 + 64 + 88) / 4
  CHECK(pixelAt(2, 0) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(0, 1) == Rgba{0, 0, 0, 0});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: constant and replicate borders keep the size; the border colour and edge groups fill in") {
  ScopedContext context(8, 8);
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, kCross);
  glEnable(GL_CONVOLUTION_2D);

  glConvolutionParameteri(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, GL_CONSTANT_BORDER);
  const GLfloat border[4] = {4 / 255.0f, 4 / 255.0f, 4 / 255.0f, 0};
  glConvolutionParameterfv(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_COLOR, border);
  drawImage();
  glDisable(GL_CONVOLUTION_2D);
  // C[i,j] = (Cs[i,j-1] + Cs[i-1,j] + Cs[i+1,j] + Cs[i,j+1]) / 4, outside groups the border.
  CHECK(red(0, 0) == 16);  // (4 + 4 + 16 + 40) / 4
  CHECK(red(1, 1) == 48);  // (16 + 40 + 56 + 80) / 4
  CHECK(red(3, 2) == 40);  // (64 + 88 + 4 + 4) / 4
  CHECK(red(3, 0) == 24);  // (4 + 24 + 4 + 64) / 4
  CHECK(pixelAt(3, 2).a == 255);  // alpha is not filtered by a luminance filter

  glEnable(GL_CONVOLUTION_2D);
  glConvolutionParameteri(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, GL_REPLICATE_BORDER);
  drawImage();
  glDisable(GL_CONVOLUTION_2D);
  CHECK(red(0, 0) == 18);  // (8 + 8 + 16 + 40) / 4
  CHECK(red(3, 2) == 86);  // (64 + 88 + 96 + 96) / 4
  CHECK(red(2, 1) == 56);  // (24 + 48 + 64 + 88) / 4
  CHECK(red(4, 0) == 0);   // the image kept its size
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: a separable filter convolves as the 2D filter of its outer product") {
  const GLfloat row[3 * 4] = {0.25f, 0.5f, 0.125f, 1, 0.5f, 0.25f, 0.5f, 1, 0.25f, 0.25f, 0.375f, 1};
  const GLfloat column[2 * 4] = {0.5f, 0.75f, 0.25f, 1, 0.5f, 0.25f, 0.75f, 1};
  GLfloat product[3 * 2 * 4];
  for (int n = 0; n < 2; ++n)
    for (int m = 0; m < 3; ++m)
      for (int k = 0; k < 4; ++k) product[(n * 3 + m) * 4 + k] = row[m * 4 + k] * column[n * 4 + k];
  std::vector<GLubyte> image(7 * 5 * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = static_cast<GLubyte>((i * 37 + 11) % 256);

  std::vector<uint8_t> results[3];
  for (int pass = 0; pass < 3; ++pass) {
    ScopedContext context(8, 8);
    const GLenum target = pass == 0 ? GL_SEPARABLE_2D : GL_CONVOLUTION_2D;
    if (pass == 0) {
      glSeparableFilter2D(GL_SEPARABLE_2D, GL_RGBA, 3, 2, GL_RGBA, GL_FLOAT, row, column);
    } else {
      glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA, 3, 2, GL_RGBA, GL_FLOAT, product);
    }
    glConvolutionParameteri(target, GL_CONVOLUTION_BORDER_MODE, GL_REPLICATE_BORDER);
    if (pass < 2) glEnable(target);
    glWindowPos2i(0, 0);
    glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glDisable(target);
    results[pass] = glass::test::readFramebuffer(8, 8);
    CHECK(glGetError() == GL_NO_ERROR);
  }
  CHECK(results[0] == results[1]);
  CHECK(results[0] != results[2]);  // and the filter did something
}

TEST_CASE("imaging: glGetConvolutionFilter and glGetSeparableFilter return the scaled and biased filter") {
  ScopedContext context(4, 4);
  const GLfloat scale[4] = {0.5f, 0.5f, 0.5f, 0.5f}, bias[4] = {0.25f, 0, 0, 0};
  glConvolutionParameterfv(GL_CONVOLUTION_1D, GL_CONVOLUTION_FILTER_SCALE, scale);
  glConvolutionParameterfv(GL_CONVOLUTION_1D, GL_CONVOLUTION_FILTER_BIAS, bias);
  const GLfloat filter[2 * 4] = {1, 0.5f, 0, 1, 0, 1, 0.5f, 0};
  glConvolutionFilter1D(GL_CONVOLUTION_1D, GL_RGBA, 2, GL_RGBA, GL_FLOAT, filter);
  GLfloat got[8] = {};
  glGetConvolutionFilter(GL_CONVOLUTION_1D, GL_RGBA, GL_FLOAT, got);
  CHECK(got[0] == 0.75f);
  CHECK(got[1] == 0.25f);
  CHECK(got[4] == 0.25f);
  CHECK(got[6] == 0.25f);
  GLint width = 0, height = 0, format = 0, maxWidth = 0;
  glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_WIDTH, &width);
  glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_HEIGHT, &height);
  glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_FORMAT, &format);
  glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_MAX_CONVOLUTION_WIDTH, &maxWidth);
  CHECK(width == 2);
  CHECK(height == 1);
  CHECK(format == GL_RGBA);
  CHECK(maxWidth == 9);

  const GLfloat row[2] = {0.25f, 0.5f}, column[3] = {0.125f, 0.75f, 1};
  glSeparableFilter2D(GL_SEPARABLE_2D, GL_LUMINANCE, 2, 3, GL_LUMINANCE, GL_FLOAT, row, column);
  GLfloat gotRow[2], gotColumn[3];
  glGetSeparableFilter(GL_SEPARABLE_2D, GL_LUMINANCE, GL_FLOAT, gotRow, gotColumn, nullptr);
  CHECK(gotRow[1] == 0.5f);
  CHECK(gotColumn[1] == 0.75f);
  GLint mode = 0;
  glGetConvolutionParameteriv(GL_SEPARABLE_2D, GL_CONVOLUTION_BORDER_MODE, &mode);
  CHECK(mode == GL_REDUCE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: glCopyConvolutionFilter2D takes the filter from the colour buffer") {
  ScopedContext context(8, 8);
  drawPixel(1, 1, Rgba{255, 255, 255, 255});  // a 1x1 identity filter at (1, 1)
  glCopyConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA, 1, 1, 1, 1);
  glEnable(GL_CONVOLUTION_2D);
  drawPixel(5, 5, Rgba{1, 2, 3, 4});
  glDisable(GL_CONVOLUTION_2D);
  CHECK(pixelAt(5, 5) == Rgba{1, 2, 3, 4});
  GLint width = 0;
  glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_CONVOLUTION_WIDTH, &width);
  CHECK(width == 1);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: the colour matrix swaps channels, then its scale and bias apply") {
  ScopedContext context(4, 4);
  // Column-major: R' = B, G' = G, B' = R, A' = A.
  const GLfloat swap[16] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  glMatrixMode(GL_COLOR);
  glLoadMatrixf(swap);
  glMatrixMode(GL_MODELVIEW);
  drawPixel(0, 0, Rgba{10, 20, 30, 40});
  CHECK(pixelAt(0, 0) == Rgba{10, 20, 30, 40});  // glReadPixels swaps them back
  glMatrixMode(GL_COLOR);
  glLoadIdentity();
  CHECK(pixelAt(0, 0) == Rgba{30, 20, 10, 40});
  glLoadMatrixf(swap);
  glPixelTransferf(GL_POST_COLOR_MATRIX_GREEN_SCALE, 0.5f);
  glPixelTransferf(GL_POST_COLOR_MATRIX_ALPHA_BIAS, 1.0f);
  drawPixel(1, 0, Rgba{10, 20, 30, 40});
  glLoadIdentity();
  glPixelTransferf(GL_POST_COLOR_MATRIX_GREEN_SCALE, 1.0f);
  glPixelTransferf(GL_POST_COLOR_MATRIX_ALPHA_BIAS, 0.0f);
  CHECK(pixelAt(1, 0) == Rgba{30, 10, 10, 255});

  GLfloat matrix[16];
  glLoadMatrixf(swap);
  glGetFloatv(GL_COLOR_MATRIX, matrix);
  CHECK(std::memcmp(matrix, swap, sizeof swap) == 0);
  GLint depth = 0, maxDepth = 0;
  glGetIntegerv(GL_MAX_COLOR_MATRIX_STACK_DEPTH, &maxDepth);
  CHECK(maxDepth >= 2);
  for (int i = 1; i < maxDepth; ++i) glPushMatrix();
  glGetIntegerv(GL_COLOR_MATRIX_STACK_DEPTH, &depth);
  CHECK(depth == maxDepth);
  CHECK(glGetError() == GL_NO_ERROR);
  glPushMatrix();
  CHECK(glGetError() == GL_STACK_OVERFLOW);
  GLint mode = 0;
  glGetIntegerv(GL_MATRIX_MODE, &mode);
  CHECK(mode == GL_COLOR);
}

TEST_CASE("imaging: the post-convolution scale and bias apply without a convolution, as in Mesa") {
  ScopedContext context(4, 4);
  glPixelTransferf(GL_POST_CONVOLUTION_RED_SCALE, 2.0f);
  glPixelTransferf(GL_POST_CONVOLUTION_BLUE_BIAS, -20 / 255.0f);
  drawPixel(0, 0, Rgba{10, 20, 30, 40});
  GLfloat scale = 0;
  glGetFloatv(GL_POST_CONVOLUTION_RED_SCALE, &scale);
  CHECK(scale == 2.0f);
  glPixelTransferf(GL_POST_CONVOLUTION_RED_SCALE, 1.0f);
  glPixelTransferf(GL_POST_CONVOLUTION_BLUE_BIAS, 0.0f);
  CHECK(pixelAt(0, 0) == Rgba{20, 20, 10, 40});
}

TEST_CASE("imaging: the post-convolution and post-colour-matrix tables come after their stages") {
  ScopedContext context(4, 4);
  // A 2-entry RGBA table mapping [0, 1] to (255 - ...): entry 0 white, entry 1 black.
  const GLubyte invert[8] = {255, 255, 255, 255, 0, 0, 0, 0};
  glColorTable(GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_RGB, 2, GL_RGBA, GL_UNSIGNED_BYTE, invert);
  glEnable(GL_POST_COLOR_MATRIX_COLOR_TABLE);
  // The colour matrix doubles red first: 100 becomes 200, which selects entry 1 (black).
  glMatrixMode(GL_COLOR);
  glScalef(2, 1, 1);
  drawPixel(0, 0, Rgba{100, 100, 200, 7});
  glLoadIdentity();
  glDisable(GL_POST_COLOR_MATRIX_COLOR_TABLE);
  CHECK(pixelAt(0, 0) == Rgba{0, 255, 0, 7});
  glColorTable(GL_POST_CONVOLUTION_COLOR_TABLE, GL_ALPHA, 2, GL_RGBA, GL_UNSIGNED_BYTE, invert);
  glEnable(GL_POST_CONVOLUTION_COLOR_TABLE);
  drawPixel(1, 0, Rgba{1, 2, 3, 200});
  glDisable(GL_POST_CONVOLUTION_COLOR_TABLE);
  CHECK(pixelAt(1, 0) == Rgba{1, 2, 3, 0});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: a histogram counts known pixels, and its sink discards them") {
  ScopedContext context(16, 4);
  glHistogram(GL_HISTOGRAM, 4, GL_RGBA, GL_TRUE);
  glEnable(GL_HISTOGRAM);
  // Red 0, 0, 85, 170, 255, 255, 255, 128: entries round(r / 255 * 3) = 0 0 1 2 3 3 3 2.
  const GLubyte reds[8] = {0, 0, 85, 170, 255, 255, 255, 128};
  GLubyte row[8 * 4];
  for (int i = 0; i < 8; ++i) {
    row[i * 4 + 0] = reds[i];
    row[i * 4 + 1] = 0;
    row[i * 4 + 2] = 255;
    row[i * 4 + 3] = static_cast<GLubyte>(i < 4 ? 0 : 255);
  }
  glWindowPos2i(0, 0);
  glDrawPixels(8, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glDisable(GL_HISTOGRAM);
  CHECK(pixelAt(0, 0) == Rgba{0, 0, 0, 0});  // the sink discarded them
  CHECK(pixelAt(4, 0) == Rgba{0, 0, 0, 0});
  GLuint counts[4 * 4] = {};
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_RGBA, GL_UNSIGNED_INT, counts);
  const GLuint expected[16] = {2, 8, 0, 4, 1, 0, 0, 0, 2, 0, 0, 0, 3, 0, 8, 4};
  for (int i = 0; i < 16; ++i) {
    CAPTURE(i);
    CHECK(counts[i] == expected[i]);
  }
  GLfloat asFloat[4];
  glGetHistogram(GL_HISTOGRAM, GL_TRUE, GL_RED, GL_FLOAT, asFloat);  // and reset
  CHECK(asFloat[0] == 2.0f);
  CHECK(asFloat[3] == 3.0f);
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_RED, GL_FLOAT, asFloat);
  CHECK(asFloat[3] == 0.0f);

  // A luminance histogram counts R; without the sink the pixels are drawn.
  glHistogram(GL_HISTOGRAM, 2, GL_LUMINANCE, GL_FALSE);
  glEnable(GL_HISTOGRAM);
  glWindowPos2i(0, 1);
  glDrawPixels(8, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glDisable(GL_HISTOGRAM);
  CHECK(pixelAt(2, 1) == Rgba{85, 0, 255, 0});
  GLushort luminance[2];
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_LUMINANCE, GL_UNSIGNED_SHORT, luminance);
  CHECK(luminance[0] == 3);  // 0, 0, 85
  CHECK(luminance[1] == 5);
  GLint width = 0, format = 0, sink = -1, size = -1;
  glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH, &width);
  glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_FORMAT, &format);
  glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_SINK, &sink);
  glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_RED_SIZE, &size);
  CHECK(width == 2);
  CHECK(format == GL_LUMINANCE);
  CHECK(sink == GL_FALSE);
  CHECK(size == 0);
  glResetHistogram(GL_HISTOGRAM);
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_LUMINANCE, GL_UNSIGNED_SHORT, luminance);
  CHECK(luminance[1] == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: minmax keeps the least and greatest of each component") {
  ScopedContext context(8, 4);
  glMinmax(GL_MINMAX, GL_RGBA, GL_FALSE);
  glEnable(GL_MINMAX);
  const GLubyte pixels[12] = {10, 5, 100, 255, 200, 6, 90, 0, 50, 7, 80, 128};
  glWindowPos2i(0, 0);
  glDrawPixels(3, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  GLubyte minmax[8];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetMinmax(GL_MINMAX, GL_TRUE, GL_RGBA, GL_UNSIGNED_BYTE, minmax);
  const GLubyte expected[8] = {10, 5, 80, 0, 200, 7, 100, 255};
  CHECK(std::memcmp(minmax, expected, 8) == 0);
  CHECK(pixelAt(1, 0) == Rgba{200, 6, 90, 0});  // drawn: no sink

  // glReadPixels goes through minmax too; with the sink it writes nothing.
  glMinmax(GL_MINMAX, GL_LUMINANCE, GL_TRUE);
  GLubyte read[12];
  std::memset(read, 99, sizeof read);
  glReadPixels(0, 0, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
  CHECK(read[0] == 99);
  glDisable(GL_MINMAX);
  GLfloat luminance[2];
  glGetMinmax(GL_MINMAX, GL_FALSE, GL_LUMINANCE, GL_FLOAT, luminance);
  CHECK(luminance[0] == 10 / 255.0f);
  CHECK(luminance[1] == 200 / 255.0f);
  GLint format = 0;
  glGetMinmaxParameteriv(GL_MINMAX, GL_MINMAX_FORMAT, &format);
  CHECK(format == GL_LUMINANCE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: glReadPixels with a GL_REDUCE convolution writes the smaller image") {
  ScopedContext context(8, 8);
  drawImage();
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, kCross);
  glEnable(GL_CONVOLUTION_2D);
  GLubyte read[4 * 3];
  std::memset(read, 99, sizeof read);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 4, 3, GL_RED, GL_UNSIGNED_BYTE, read);
  CHECK(read[0] == 48);
  CHECK(read[1] == 56);
  CHECK(read[2] == 99);  // a 2 x 1 image was written
  // glCopyPixels convolves the same way.
  glWindowPos2i(4, 4);
  glCopyPixels(0, 0, 4, 3, GL_COLOR);
  glDisable(GL_CONVOLUTION_2D);
  CHECK(pixelAt(4, 4) == Rgba{48, 48, 48, 255});
  CHECK(pixelAt(5, 4) == Rgba{56, 56, 56, 255});
  CHECK(pixelAt(6, 4) == Rgba{0, 0, 0, 0});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: colour indices go through the imaging operations once converted to RGBA") {
  ScopedContext context(4, 4);
  const GLfloat ramp[2] = {0.0f, 1.0f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, ramp);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, ramp);
  glMatrixMode(GL_COLOR);
  const GLfloat redToGreen[16] = {0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  glLoadMatrixf(redToGreen);
  const GLubyte index = 1;
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &index);
  glLoadIdentity();
  CHECK(pixelAt(0, 0) == Rgba{0, 255, 0, 255});
}

TEST_CASE("imaging: errors of the specification commands and queries") {
  ScopedContext context(4, 4);
  const GLubyte data[4 * 512] = {};
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 3, GL_RGBA, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glColorTable(GL_TEXTURE_2D, GL_RGBA, 4, GL_RGBA, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glColorTable(GL_COLOR_TABLE, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, data);  // not a table 3.15 name
  CHECK(glGetError() == GL_INVALID_ENUM);
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 4, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 4, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, data);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 512, GL_RGBA, GL_UNSIGNED_BYTE, data);
  CHECK(glGetError() == GL_TABLE_TOO_LARGE);
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);  // zero is allowed
  CHECK(glGetError() == GL_NO_ERROR);
  const GLfloat scale[4] = {1, 1, 1, 1};
  glColorTableParameterfv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_SCALE, scale);
  CHECK(glGetError() == GL_INVALID_ENUM);
  GLint value = -1;
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE + 100, &value);
  CHECK(glGetError() == GL_INVALID_ENUM);

  // Proxies: a table that fits reports its size and format, one too large zeros.
  glColorTable(GL_PROXY_COLOR_TABLE, GL_LUMINANCE8, 256, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &value);
  CHECK(value == 256);
  glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_FORMAT, &value);
  CHECK(value == GL_LUMINANCE8);
  glColorTable(GL_PROXY_COLOR_TABLE, GL_RGBA, 512, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_NO_ERROR);
  glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &value);
  CHECK(value == 0);
  glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_FORMAT, &value);
  CHECK(value == 0);

  const GLfloat filter[10 * 10 * 4] = {};
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA, 10, 3, GL_RGBA, GL_FLOAT, filter);  // > 9
  CHECK(glGetError() == GL_INVALID_VALUE);
  glConvolutionFilter2D(GL_CONVOLUTION_1D, GL_RGBA, 3, 3, GL_RGBA, GL_FLOAT, filter);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glConvolutionFilter1D(GL_CONVOLUTION_1D, GL_RGBA, 3, GL_DEPTH_COMPONENT, GL_FLOAT, filter);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glConvolutionParameteri(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, GL_CLAMP);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glConvolutionParameterf(GL_CONVOLUTION_2D, GL_CONVOLUTION_FILTER_SCALE, 1.0f);  // a vector
  CHECK(glGetError() == GL_INVALID_ENUM);
  GLfloat out[4];
  glGetConvolutionFilter(GL_SEPARABLE_2D, GL_RGBA, GL_FLOAT, out);
  CHECK(glGetError() == GL_INVALID_ENUM);

  glHistogram(GL_HISTOGRAM, 6, GL_RGBA, GL_FALSE);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glHistogram(GL_HISTOGRAM, 4, GL_INTENSITY, GL_FALSE);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glHistogram(GL_HISTOGRAM, 512, GL_RGBA, GL_FALSE);
  CHECK(glGetError() == GL_TABLE_TOO_LARGE);
  glHistogram(GL_PROXY_HISTOGRAM, 512, GL_RGBA, GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
  glGetHistogramParameteriv(GL_PROXY_HISTOGRAM, GL_HISTOGRAM_WIDTH, &value);
  CHECK(value == 0);
  GLuint counts[4];
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, counts);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetHistogram(GL_PROXY_HISTOGRAM, GL_FALSE, GL_RGBA, GL_UNSIGNED_INT, counts);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glMinmax(GL_HISTOGRAM, GL_RGBA, GL_FALSE);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glMinmax(GL_MINMAX, GL_INTENSITY8, GL_FALSE);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetMinmaxParameteriv(GL_MINMAX, GL_HISTOGRAM_WIDTH, &value);
  CHECK(glGetError() == GL_INVALID_ENUM);

  glBegin(GL_POINTS);
  glColorTable(GL_COLOR_TABLE, GL_RGBA, 4, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("imaging: GL_PIXEL_MODE_BIT and GL_ENABLE_BIT save the imaging state, not the tables") {
  ScopedContext context(4, 4);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glEnable(GL_HISTOGRAM);
  glPixelTransferf(GL_POST_CONVOLUTION_GREEN_BIAS, 0.5f);
  glConvolutionParameteri(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, GL_REPLICATE_BORDER);
  loadTable(GL_RGBA);
  glPopAttrib();
  CHECK(glIsEnabled(GL_HISTOGRAM) == GL_FALSE);
  GLfloat bias = -1;
  glGetFloatv(GL_POST_CONVOLUTION_GREEN_BIAS, &bias);
  CHECK(bias == 0.0f);
  GLint mode = 0, width = 0;
  glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, &mode);
  CHECK(mode == GL_REDUCE);
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &width);
  CHECK(width == 4);  // the table belongs to no group

  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_SEPARABLE_2D);
  glEnable(GL_MINMAX);
  glPopAttrib();
  CHECK(glIsEnabled(GL_SEPARABLE_2D) == GL_FALSE);
  CHECK(glIsEnabled(GL_MINMAX) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("imaging: display lists compile the specification commands, not proxies or queries") {
  ScopedContext context(4, 4);
  glNewList(1, GL_COMPILE);
  loadTable(GL_RGB);
  glColorTable(GL_PROXY_COLOR_TABLE, GL_ALPHA, 16, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glHistogram(GL_HISTOGRAM, 8, GL_RGB, GL_FALSE);
  glEnable(GL_COLOR_TABLE);
  glEndList();
  GLint width = -1;
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &width);
  CHECK(width == 0);  // compiled, not run
  glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &width);
  CHECK(width == 16);  // a proxy executes at once
  glCallList(1);
  glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &width);
  CHECK(width == 4);
  glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH, &width);
  CHECK(width == 8);
  drawPixel(0, 0, Rgba{0, 85, 170, 255});
  glDisable(GL_COLOR_TABLE);
  CHECK(pixelAt(0, 0) == Rgba{10, 51, 102, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}
