// Contexts asking for 0 depth, stencil or accumulation bits have no such buffer
// (pipeline/src/core/ancillary_buffers.h says what that changes, from the OpenGL specification).
#include <doctest/doctest.h>

#include <vector>

#include "osmesa_test_scene.h"

namespace {

constexpr int kSize = 16;

// A quad over the whole viewport at depth z (GL's default depth range), in colour rgb.
void drawQuad(float z, float r, float g, float b) {
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, z);
  glVertex3f(1, -1, z);
  glVertex3f(1, 1, z);
  glVertex3f(-1, 1, z);
  glEnd();
}

GLint integer(GLenum pname) {
  GLint value = -1;
  glGetIntegerv(pname, &value);
  return value;
}

// Draws red near, then green far, with the depth test on; returns the centre pixel's RGB.
std::vector<uint8_t> nearThenFar(const std::vector<uint8_t>& buffer) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  drawQuad(-0.5f, 1, 0, 0);
  drawQuad(0.5f, 0, 1, 0);
  glFinish();
  const size_t centre = (static_cast<size_t>(kSize / 2) * kSize + kSize / 2) * 4;
  return {buffer[centre], buffer[centre + 1], buffer[centre + 2]};
}

}  // namespace

TEST_CASE("a context with every ancillary buffer reports their bits and uses them") {
  std::vector<uint8_t> buffer(kSize * kSize * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(integer(GL_DEPTH_BITS) == 24);
  CHECK(integer(GL_STENCIL_BITS) == 8);
  CHECK(integer(GL_ACCUM_RED_BITS) == 16);
  CHECK(nearThenFar(buffer) == std::vector<uint8_t>{255, 0, 0});  // the far quad is hidden
  glAccum(GL_LOAD, 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
  GLint w = 0, h = 0, bytes = 0;
  void* depth = nullptr;
  CHECK(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth) == GL_TRUE);
  CHECK(depth != nullptr);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("0 depth bits: no depth buffer, and the depth test passes everything") {
  std::vector<uint8_t> buffer(kSize * kSize * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 8, 0, nullptr);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(integer(GL_DEPTH_BITS) == 0);
  CHECK(integer(GL_STENCIL_BITS) == 8);
  // Spec 4.1.5: with no depth buffer it is as if the depth test always passes.
  CHECK(nearThenFar(buffer) == std::vector<uint8_t>{0, 255, 0});
  CHECK(integer(GL_DEPTH_TEST) == GL_TRUE);  // the enable itself is state as usual
  // Reading depth has no buffer to read (4.3.2, 4.3.3); neither has a depth texture copy.
  float depth = 0.0f;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glClear(GL_DEPTH_BUFFER_BIT);  // nothing to clear, and no error (4.2.3)
  CHECK(glGetError() == GL_NO_ERROR);
  GLint w = 1, h = 1, bytes = 1;
  void* depthBuffer = &w;
  CHECK(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depthBuffer) == GL_FALSE);
  CHECK(w == 0);
  CHECK(depthBuffer == nullptr);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("0 stencil bits: no stencil buffer, and the stencil test passes everything") {
  std::vector<uint8_t> buffer(kSize * kSize * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(integer(GL_STENCIL_BITS) == 0);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xFF);  // would reject every fragment with a stencil buffer
  drawQuad(0, 0, 0, 1);
  glFinish();
  const size_t centre = (static_cast<size_t>(kSize / 2) * kSize + kSize / 2) * 4;
  CHECK(buffer[centre + 2] == 255);
  GLubyte stencil = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("0 accumulation bits: no accumulation buffer, and glAccum is an error") {
  std::vector<uint8_t> buffer(kSize * kSize * 4);
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, nullptr);  // 24, 8 and 0 bits, as Mesa's
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  CHECK(integer(GL_ACCUM_RED_BITS) == 0);
  CHECK(integer(GL_ACCUM_ALPHA_BITS) == 0);
  CHECK(integer(GL_DEPTH_BITS) == 24);
  glAccum(GL_ACCUM, 0.5f);
  CHECK(glGetError() == GL_INVALID_OPERATION);  // spec 4.2.4
  glClear(GL_ACCUM_BUFFER_BIT);
  CHECK(glGetError() == GL_NO_ERROR);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("formats without alpha: no alpha bitplanes, and destination alpha reads 1 (as in Mesa)") {
  // Debian 12's libOSMesa 22.3.6 gives GL_ALPHA_BITS 0 for OSMESA_RGB and OSMESA_RGB_565 (it
  // refuses OSMESA_BGR), 8 for the formats with alpha; glReadPixels then reads alpha 255 after a
  // clear with alpha 0.25, and blending by (1 - destination alpha, destination alpha) leaves the
  // clear colour.
  struct Case {
    GLenum format, type;
    GLint alphaBits;
    uint8_t cleared, blended[2];  // alpha after the clear; red and alpha after blending
  };
  const Case cases[] = {
      {OSMESA_RGBA, GL_UNSIGNED_BYTE, 8, 64, {223, 112}},
      {OSMESA_BGRA, GL_UNSIGNED_BYTE, 8, 64, {223, 112}},
      {OSMESA_ARGB, GL_UNSIGNED_BYTE, 8, 64, {223, 112}},
      {OSMESA_RGB, GL_UNSIGNED_BYTE, 0, 255, {128, 255}},
      {OSMESA_BGR, GL_UNSIGNED_BYTE, 0, 255, {128, 255}},
      {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 0, 255, {128, 255}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.format);
    std::vector<uint8_t> buffer(kSize * kSize * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(c.format, 24, 8, 0, nullptr);
    REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), c.type, kSize, kSize));
    CHECK(integer(GL_ALPHA_BITS) == c.alphaBits);
    glClearColor(0.5f, 0.5f, 0.5f, 0.25f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLubyte pixel[4] = {};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    CHECK(pixel[3] == c.cleared);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
    glColor4f(1, 1, 1, 0.5f);
    glRectf(-1, -1, 1, 1);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    CHECK(pixel[0] == c.blended[0]);
    CHECK(pixel[3] == c.blended[1]);
    OSMesaDestroyContext(ctx);
  }
}
