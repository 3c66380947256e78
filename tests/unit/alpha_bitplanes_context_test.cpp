// glassSetAlphaBitplanes: a colour buffer without alpha bitplanes, as Mesa gives a GLUT window
// without GLUT_ALPHA and an OSMesa context of a format without alpha. GL_ALPHA_BITS is 0 and the
// alpha read from the colour buffer is 1 (OpenGL 1.4, 4.1.8 and 4.3.2): every pixel written keeps
// alpha 255, by the block and line kernels as by the per-fragment path, on one thread or two,
// while the fragment's own alpha still drives the alpha test and GL_SRC_ALPHA blending.
#include <GL/gl.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace doctest {
template <>
struct StringMaker<std::vector<GLubyte>> {
  static String convert(const std::vector<GLubyte>& bytes) {
    std::string text;
    for (const GLubyte b : bytes) text += std::to_string(b) + " ";
    return String(text.c_str());
  }
};
}  // namespace doctest

namespace {

constexpr int kSize = 16;

GLint integer(GLenum pname) {
  GLint value = -1;
  glGetIntegerv(pname, &value);
  return value;
}

std::vector<GLubyte> readPixel(int x = 4, int y = 4) {
  std::vector<GLubyte> pixel(4, 0);
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
  return pixel;
}

std::vector<GLubyte> rgba(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { return {r, g, b, a}; }

void fullSquare() {
  glBegin(GL_QUADS);
  glVertex2f(-1.0f, -1.0f);
  glVertex2f(1.0f, -1.0f);
  glVertex2f(1.0f, 1.0f);
  glVertex2f(-1.0f, 1.0f);
  glEnd();
}

// The alpha of every pixel of the colour buffer, as glReadPixels gives it.
std::vector<GLubyte> alphas(int width, int height) {
  std::vector<GLubyte> values(static_cast<size_t>(width) * static_cast<size_t>(height));
  glReadPixels(0, 0, width, height, GL_ALPHA, GL_UNSIGNED_BYTE, values.data());
  return values;
}

bool allOpaque(int width, int height) {
  for (const GLubyte a : alphas(width, height)) {
    if (a != 255) return false;
  }
  return true;
}

// A context of kSize x kSize, current, with or without alpha bitplanes.
GlassContext* makeContext(bool alpha) {
  GlassContext* ctx = glassCreateContext(kSize, kSize);
  REQUIRE(ctx != nullptr);
  glassMakeCurrent(ctx);
  REQUIRE(glassSetAlphaBitplanes(ctx, alpha ? 1 : 0) == 1);
  return ctx;
}

void release(GlassContext* ctx) {
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
}

// Clears to grey with alpha 0.25, then draws white with alpha 0.5 blended by
// (GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA): the pixel read back.
std::vector<GLubyte> blendByDestinationAlpha() {
  glClearColor(0.5f, 0.5f, 0.5f, 0.25f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
  glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
  fullSquare();
  glDisable(GL_BLEND);
  return readPixel();
}

}  // namespace

TEST_CASE("glassSetAlphaBitplanes: GL_ALPHA_BITS, and alpha reads 1 after clearing and drawing") {
  GlassContext* ctx = makeContext(true);
  CHECK(integer(GL_ALPHA_BITS) == 8);
  glClearColor(0.5f, 0.5f, 0.5f, 0.25f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readPixel() == rgba(128, 128, 128, 64));

  // Taking the bitplanes away makes the stored alpha 1 at once, as Mesa's buffer reads.
  CHECK(glassSetAlphaBitplanes(ctx, 0) == 1);
  CHECK(integer(GL_ALPHA_BITS) == 0);
  CHECK(integer(GL_RED_BITS) == 8);
  CHECK(readPixel() == rgba(128, 128, 128, 255));
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readPixel() == rgba(128, 128, 128, 255));
  glColor4f(0.2f, 0.4f, 0.6f, 0.3f);
  fullSquare();
  CHECK(readPixel() == rgba(51, 102, 153, 255));
  CHECK(glassSetAlphaBitplanes(nullptr, 0) == 0);
  release(ctx);

  // A context made without them starts with alpha 1 everywhere.
  ctx = makeContext(false);
  CHECK(allOpaque(kSize, kSize));
  release(ctx);
}

TEST_CASE("glassSetAlphaBitplanes: blending reads destination alpha 1 without bitplanes") {
  GlassContext* ctx = makeContext(true);
  // With alpha: 1 * 0.75 + 0.5 * 0.25 = 0.875, alpha 0.5 * 0.75 + 0.25 * 0.25 (Mesa's numbers).
  CHECK(blendByDestinationAlpha() == rgba(223, 223, 223, 112));
  release(ctx);

  ctx = makeContext(false);
  // Without: 1 * 0 + 0.5 * 1, the destination as it was.
  CHECK(blendByDestinationAlpha() == rgba(128, 128, 128, 255));
  // GL_DST_ALPHA as the source factor: the source as it comes.
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_ALPHA, GL_ZERO);
  glColor4f(0.6f, 0.2f, 1.0f, 0.1f);
  fullSquare();
  CHECK(readPixel() == rgba(153, 51, 255, 255));
  // The fragment's alpha still weighs GL_SRC_ALPHA blending.
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
  fullSquare();
  CHECK(readPixel() == rgba(128, 128, 128, 255));
  // A logic op's alpha is not kept either (255 XOR 255 would be 0).
  glDisable(GL_BLEND);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
  fullSquare();
  CHECK(readPixel() == rgba(127, 128, 128, 255));
  glDisable(GL_COLOR_LOGIC_OP);
  release(ctx);
}

TEST_CASE("glassSetAlphaBitplanes: the alpha test uses the fragment's alpha; the colour mask is queried as set") {
  GlassContext* ctx = makeContext(false);
  glClearColor(0.0f, 0.0f, 1.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1.0f, 0.0f, 0.0f, 0.4f);
  fullSquare();
  CHECK(readPixel() == rgba(0, 0, 255, 255));  // rejected
  glColor4f(0.0f, 1.0f, 0.0f, 0.6f);
  fullSquare();
  CHECK(readPixel() == rgba(0, 255, 0, 255));  // passed, stored with alpha 1
  glDisable(GL_ALPHA_TEST);

  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  GLboolean mask[4] = {};
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  CHECK(mask[0] == GL_TRUE);
  CHECK(mask[3] == GL_FALSE);
  glColor4f(1.0f, 1.0f, 0.0f, 0.2f);
  fullSquare();
  CHECK(readPixel() == rgba(255, 255, 0, 255));
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glColor4f(0.0f, 0.0f, 0.0f, 0.2f);
  fullSquare();
  CHECK(readPixel() == rgba(255, 0, 0, 255));
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readPixel() == rgba(255, 0, 0, 255));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  CHECK(mask[3] == GL_TRUE);
  release(ctx);
}

TEST_CASE("glassSetAlphaBitplanes: kept by glassResetContext and glassResizeContext") {
  GlassContext* ctx = makeContext(false);
  CHECK(glassResetContext(ctx) == 1);
  CHECK(integer(GL_ALPHA_BITS) == 0);
  CHECK(blendByDestinationAlpha() == rgba(128, 128, 128, 255));
  CHECK(glassResizeContext(ctx, 20, 12) == 1);
  CHECK(integer(GL_ALPHA_BITS) == 0);
  CHECK(allOpaque(20, 12));  // the new buffer starts with alpha 1
  CHECK(blendByDestinationAlpha() == rgba(128, 128, 128, 255));
  // glassSetAncillaryBuffers leaves the alpha bitplanes alone.
  CHECK(glassSetAncillaryBuffers(ctx, 1, 1, 1) == 1);
  CHECK(integer(GL_ALPHA_BITS) == 0);

  CHECK(glassSetAlphaBitplanes(ctx, 1) == 1);
  CHECK(glassResizeContext(ctx, 16, 16) == 1);
  CHECK(integer(GL_ALPHA_BITS) == 8);
  CHECK(readPixel() == rgba(0, 0, 0, 0));
  CHECK(blendByDestinationAlpha() == rgba(223, 223, 223, 112));
  release(ctx);
}

TEST_CASE("glassSetAlphaBitplanes: glAccum, glDrawPixels, glCopyPixels, glBitmap, lines and points store alpha 1") {
  for (const bool alpha : {true, false}) {
    CAPTURE(alpha);
    GlassContext* ctx = makeContext(alpha);
    const GLubyte expected = alpha ? 26 : 255;
    glClearAccum(0.5f, 0.5f, 0.5f, 0.1f);
    glClear(GL_ACCUM_BUFFER_BIT);
    glAccum(GL_RETURN, 1.0f);
    CHECK(readPixel()[3] == (alpha ? 25 : 255));

    // glDrawPixels: the bytes' fast path, and with zoom the fragments' path.
    std::vector<GLubyte> image(static_cast<size_t>(kSize) * kSize * 4);
    for (size_t i = 0; i < image.size(); ++i) image[i] = i % 4 == 3 ? 26 : 200;
    for (const float zoom : {1.0f, 2.0f}) {
      CAPTURE(zoom);
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glPixelZoom(zoom, zoom);
      glRasterPos2f(-1.0f, -1.0f);
      glDrawPixels(kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
      CHECK(readPixel() == rgba(200, 200, 200, expected));
    }
    glPixelZoom(1.0f, 1.0f);

    // glCopyPixels of a colour drawn with the alpha test on (not the kernels' path).
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1.0f, 0.0f, 0.0f, 0.1f);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.0f);
    glRectf(-1.0f, -1.0f, 0.0f, 0.0f);
    glDisable(GL_ALPHA_TEST);
    CHECK(readPixel(2, 2) == rgba(255, 0, 0, expected));
    glRasterPos2f(0.0f, 0.0f);
    glCopyPixels(0, 0, 8, 8, GL_COLOR);
    CHECK(readPixel(10, 10) == rgba(255, 0, 0, expected));

    // glBitmap, lines and points, plain and smooth, all with alpha 0.1.
    glClear(GL_COLOR_BUFFER_BIT);
    const GLubyte bits[8] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2f(-1.0f, -1.0f);
    glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
    CHECK(readPixel(3, 3) == rgba(255, 0, 0, expected));
    glClear(GL_COLOR_BUFFER_BIT);
    for (const bool smooth : {false, true}) {
      CAPTURE(smooth);
      if (smooth) {
        glEnable(GL_LINE_SMOOTH);
        glEnable(GL_POINT_SMOOTH);
      }
      glPointSize(3.0f);
      glBegin(GL_LINES);
      glVertex2f(-0.9f, -0.8f);
      glVertex2f(0.9f, -0.5f);
      glEnd();
      glBegin(GL_POINTS);
      glVertex2f(0.5f, 0.5f);
      glEnd();
      glDisable(GL_LINE_SMOOTH);
      glDisable(GL_POINT_SMOOTH);
    }
    CHECK(allOpaque(kSize, kSize) == !alpha);
    release(ctx);
  }
}

namespace {

constexpr int kFrameWidth = 150, kFrameHeight = 130;  // several 64 x 64 tiles

// Smooth triangles with varying alpha, blended by the destination's alpha or replacing it, a
// depth-tested pair, a textured one, fogged ones, lines and smooth lines and points; with
// `referencePath`, an alpha test that passes everything keeps every draw off the kernels.
// Returns the colour buffer.
std::vector<GLubyte> renderFrame(int threads, bool alpha, bool referencePath) {
  const std::string count = std::to_string(threads);
  setenv("GLASS_THREADS", count.c_str(), 1);
  GlassContext* ctx = glassCreateContext(kFrameWidth, kFrameHeight);
  unsetenv("GLASS_THREADS");
  REQUIRE(ctx != nullptr);
  glassMakeCurrent(ctx);
  glassSetAlphaBitplanes(ctx, alpha ? 1 : 0);
  if (referencePath) {
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.0f);
  }
  glClearColor(0.2f, 0.3f, 0.4f, 0.3f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  auto triangles = [](float shift) {
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 12; ++i) {
      const float x = -1.0f + 0.15f * static_cast<float>(i) + shift, y = -0.9f + 0.1f * static_cast<float>(i % 5);
      glColor4f(1.0f, 0.1f * static_cast<float>(i % 10), 0.3f, 0.05f * static_cast<float>(i));
      glVertex3f(x, y, 0.2f);
      glColor4f(0.1f, 0.9f, 0.5f, 0.9f - 0.05f * static_cast<float>(i));
      glVertex3f(x + 0.9f, y + 0.2f, -0.3f);
      glColor4f(0.4f, 0.2f, 1.0f, 0.7f);
      glVertex3f(x + 0.3f, y + 1.1f, 0.0f);
    }
    glEnd();
  };
  triangles(0.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
  triangles(0.05f);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  triangles(0.1f);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  triangles(0.02f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  triangles(-0.03f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  triangles(0.07f);
  glDisable(GL_FOG);

  const GLubyte texels[4 * 4] = {255, 0, 0, 40, 0, 255, 0, 90, 0, 0, 255, 140, 255, 255, 255, 200};
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(-0.8f, -0.8f);
  glTexCoord2f(3.0f, 0.0f);
  glVertex2f(0.8f, -0.6f);
  glTexCoord2f(0.0f, 3.0f);
  glVertex2f(0.0f, 0.8f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &texture);

  for (const bool smooth : {false, true}) {
    if (smooth) {
      glEnable(GL_LINE_SMOOTH);
      glEnable(GL_POINT_SMOOTH);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    glLineWidth(smooth ? 2.5f : 1.0f);
    glPointSize(4.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 10; ++i) {
      glColor4f(0.1f * static_cast<float>(i), 1.0f, 0.0f, 0.3f);
      glVertex2f(-0.95f, -0.95f + 0.19f * static_cast<float>(i));
      glColor4f(1.0f, 0.0f, 0.1f * static_cast<float>(i), 0.6f);
      glVertex2f(0.95f, -0.7f + 0.15f * static_cast<float>(i));
    }
    glEnd();
    glBegin(GL_POINTS);
    for (int i = 0; i < 10; ++i) glVertex2f(-0.9f + 0.18f * static_cast<float>(i), 0.9f - 0.05f * static_cast<float>(i));
    glEnd();
  }
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_POINT_SMOOTH);

  std::vector<GLubyte> pixels(static_cast<size_t>(kFrameWidth) * kFrameHeight * 4);
  glReadPixels(0, 0, kFrameWidth, kFrameHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  release(ctx);
  return pixels;
}

// How many bytes differ.
size_t differences(const std::vector<GLubyte>& a, const std::vector<GLubyte>& b) {
  size_t count = 0;
  for (size_t i = 0; i < a.size(); ++i) count += a[i] != b[i] ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("glassSetAlphaBitplanes: the kernels and the per-fragment path store the same bytes, on 1 and 2 threads") {
  for (const bool alpha : {true, false}) {
    CAPTURE(alpha);
    const std::vector<GLubyte> fast = renderFrame(1, alpha, false);
    CHECK(differences(fast, renderFrame(1, alpha, true)) == 0);
    CHECK(differences(fast, renderFrame(2, alpha, false)) == 0);
    CHECK(differences(fast, renderFrame(2, alpha, true)) == 0);
    size_t opaque = 0;
    for (size_t i = 3; i < fast.size(); i += 4) opaque += fast[i] == 255 ? 1 : 0;
    if (alpha) {
      CHECK(opaque < fast.size() / 4);  // with bitplanes the alphas drawn are kept
    } else {
      CHECK(opaque == fast.size() / 4);
    }
  }
}
