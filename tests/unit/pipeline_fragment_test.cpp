// The per-fragment operations (spec 4.1): depth functions and mask, stencil functions and
// operations, alpha test, blending factors and equations, logic ops, colour masks, and glClear
// with the scissor box and masks.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;
using glass::test::stencilAt;

namespace {

// Identity matrices: object z in [-1, 1] is window depth (z + 1) / 2.
void fullScreenQuad(float z) {
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, z), glVertex3f(1, -1, z), glVertex3f(1, 1, z), glVertex3f(-1, 1, z);
  glEnd();
}

float depthAt(int x, int y) {
  float d = -1.0f;
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  return d;
}

}  // namespace

TEST_CASE("pipeline fragments: the eight depth functions and the depth mask") {
  ScopedContext context(8, 8);
  glEnable(GL_DEPTH_TEST);
  struct Case {
    GLenum func;
    bool less, equal, greater;  // passes for incoming <, ==, > stored
  };
  const Case cases[] = {{GL_NEVER, false, false, false}, {GL_LESS, true, false, false},
                        {GL_EQUAL, false, true, false},  {GL_LEQUAL, true, true, false},
                        {GL_GREATER, false, false, true}, {GL_NOTEQUAL, true, false, true},
                        {GL_GEQUAL, false, true, true},  {GL_ALWAYS, true, true, true}};
  const float depths[3] = {-0.5f, 0.0f, 0.5f};  // window depth 0.25, 0.5, 0.75
  for (const Case& c : cases) {
    for (int i = 0; i < 3; ++i) {
      CAPTURE(c.func);
      CAPTURE(i);
      glClearDepth(0.5);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glDepthFunc(c.func);
      glColor3f(1, 0, 0);
      fullScreenQuad(depths[i]);
      const bool expected = i == 0 ? c.less : i == 1 ? c.equal : c.greater;
      CHECK((pixelAt(4, 4).r == 255) == expected);
      CHECK(depthAt(4, 4) == doctest::Approx(expected ? (depths[i] + 1) / 2 : 0.5f).epsilon(1e-6));
    }
  }

  // With the depth mask off, passing fragments do not write depth.
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_FALSE);
  fullScreenQuad(0.5f);
  CHECK(depthAt(4, 4) == doctest::Approx(0.5f));
  glDepthMask(GL_TRUE);

  // With the depth test disabled, the depth buffer is not written at all.
  glDisable(GL_DEPTH_TEST);
  fullScreenQuad(-0.5f);
  CHECK(depthAt(4, 4) == doctest::Approx(0.5f));
}

TEST_CASE("pipeline fragments: every stencil operation, on each path, through the write mask") {
  ScopedContext context(8, 8);
  glEnable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  struct Case {
    GLenum op;
    int from, to;
  };
  const int ref = 9;
  const Case cases[] = {{GL_KEEP, 5, 5},      {GL_ZERO, 5, 0},        {GL_REPLACE, 5, ref},
                        {GL_INCR, 5, 6},      {GL_INCR, 255, 255},    {GL_DECR, 5, 4},
                        {GL_DECR, 0, 0},      {GL_INVERT, 0x5A, 0xA5}, {GL_INCR_WRAP, 255, 0},
                        {GL_INCR_WRAP, 7, 8}, {GL_DECR_WRAP, 0, 255}, {GL_DECR_WRAP, 7, 6}};
  enum Path { kStencilFail, kDepthFail, kDepthPass };
  for (int path = kStencilFail; path <= kDepthPass; ++path) {
    for (const Case& c : cases) {
      CAPTURE(path);
      CAPTURE(c.op);
      CAPTURE(c.from);
      glClearStencil(c.from);
      glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glStencilFunc(path == kStencilFail ? GL_NEVER : GL_ALWAYS, ref, 0xFF);
      if (path == kDepthFail) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_NEVER);
      }
      glStencilOp(path == kStencilFail ? c.op : GL_KEEP, path == kDepthFail ? c.op : GL_KEEP,
                  path == kDepthPass ? c.op : GL_KEEP);
      fullScreenQuad(0.0f);
      glDisable(GL_DEPTH_TEST);
      CHECK(stencilAt(3, 3) == c.to);
    }
  }

  // The write mask keeps the bits it does not name.
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  glClearStencil(0x55);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0x0F);
  fullScreenQuad(0.0f);
  CHECK(stencilAt(3, 3) == 0x5A);
  // glClear honours the write mask too.
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  CHECK(stencilAt(3, 3) == 0x50);
  glStencilMask(0xFF);

  // The value mask applies to the reference and the stored value before comparing.
  glClearStencil(0x23);
  glClear(GL_STENCIL_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_EQUAL, 0x13, 0x0F);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0, 1, 0);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).g == 255);
  glStencilFunc(GL_EQUAL, 0x13, 0xFF);
  glColor3f(0, 0, 1);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).b == 0);
}

TEST_CASE("pipeline fragments: the alpha test compares the fragment's alpha with the reference") {
  ScopedContext context(8, 8);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 1, 0.4f);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).r == 0);
  glColor4f(1, 1, 1, 0.6f);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).r == 255);
}

TEST_CASE("pipeline fragments: the alpha test compares 8-bit fixed-point values (spec 4.1.4)") {
  ScopedContext context(8, 8);
  glEnable(GL_ALPHA_TEST);
  // 0.502 and the reference 0.5 are both 128 in the colour buffer's 8 bits: equal, not greater.
  glColor4f(1, 1, 1, 0.502f);
  glAlphaFunc(GL_GREATER, 0.5f);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).r == 0);
  glAlphaFunc(GL_EQUAL, 0.5f);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(3, 3).r == 255);
}

TEST_CASE("pipeline fragments: blending, hand-computed") {
  ScopedContext context(8, 8);
  glEnable(GL_BLEND);
  const auto blendOver = [](Rgba destination, Rgba source) {
    glClearColor(destination.r / 255.0f, destination.g / 255.0f, destination.b / 255.0f,
                 destination.a / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4ub(source.r, source.g, source.b, source.a);
    fullScreenQuad(0.0f);
    return pixelAt(3, 3);
  };
  // (255, 0, 0, 128) over (0, 0, 255, 255) with SRC_ALPHA, ONE_MINUS_SRC_ALPHA:
  //   R = 255 * 128/255 = 128, B = 255 * 127/255 = 127, A = 128 * 128/255 + 255 * 127/255 = 64 + 127
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  CHECK(blendOver({0, 0, 255, 255}, {255, 0, 0, 128}) == Rgba{128, 0, 127, 191});
  // ONE, ONE saturates.
  glBlendFunc(GL_ONE, GL_ONE);
  CHECK(blendOver({200, 100, 0, 0}, {100, 100, 100, 100}) == Rgba{255, 200, 100, 100});
  // DST_COLOR, ZERO multiplies: 200 * 100 / 255 = 78.4 -> 78.
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  CHECK(blendOver({200, 255, 0, 255}, {100, 100, 100, 255}) == Rgba{78, 100, 0, 255});
  // SRC_ALPHA_SATURATE: f = min(As, 1 - Ad) = min(200, 55) for colour, 1 for alpha.
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
  CHECK(blendOver({10, 10, 10, 200}, {255, 100, 0, 200}) == Rgba{65, 32, 10, 255});
  // The constant colour.
  glBlendColor(0.0f, 0.0f, 0.0f, 0.2f);  // alpha 0.2 -> 51
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  CHECK(blendOver({0, 0, 0, 0}, {255, 255, 255, 255}) == Rgba{51, 51, 51, 51});
  // The equations.
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquation(GL_FUNC_SUBTRACT);
  CHECK(blendOver({50, 100, 200, 0}, {100, 100, 100, 100}) == Rgba{50, 0, 0, 100});
  glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  CHECK(blendOver({50, 100, 200, 0}, {100, 100, 100, 100}) == Rgba{0, 0, 100, 0});
  glBlendEquation(GL_MIN);
  CHECK(blendOver({50, 100, 200, 0}, {100, 100, 100, 100}) == Rgba{50, 100, 100, 0});
  glBlendEquation(GL_MAX);
  CHECK(blendOver({50, 100, 200, 0}, {100, 100, 100, 100}) == Rgba{100, 100, 200, 100});
  glBlendEquation(GL_FUNC_ADD);
}

TEST_CASE("pipeline fragments: every blend factor, against the factor table") {
  ScopedContext context(8, 8);
  glEnable(GL_BLEND);
  const Rgba s{200, 60, 130, 90}, d{40, 220, 100, 170};
  const float c[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  glBlendColor(c[0], c[1], c[2], c[3]);
  // The factor of component i as a number in [0, 1] (GL 1.4 table 4.1).
  const auto factor = [&](GLenum f, int i) -> double {
    const double sv[4] = {s.r / 255.0, s.g / 255.0, s.b / 255.0, s.a / 255.0};
    const double dv[4] = {d.r / 255.0, d.g / 255.0, d.b / 255.0, d.a / 255.0};
    switch (f) {
      case GL_ZERO: return 0;
      case GL_ONE: return 1;
      case GL_SRC_COLOR: return sv[i];
      case GL_ONE_MINUS_SRC_COLOR: return 1 - sv[i];
      case GL_DST_COLOR: return dv[i];
      case GL_ONE_MINUS_DST_COLOR: return 1 - dv[i];
      case GL_SRC_ALPHA: return sv[3];
      case GL_ONE_MINUS_SRC_ALPHA: return 1 - sv[3];
      case GL_DST_ALPHA: return dv[3];
      case GL_ONE_MINUS_DST_ALPHA: return 1 - dv[3];
      case GL_CONSTANT_COLOR: return c[i];
      case GL_ONE_MINUS_CONSTANT_COLOR: return 1 - c[i];
      case GL_CONSTANT_ALPHA: return c[3];
      case GL_ONE_MINUS_CONSTANT_ALPHA: return 1 - c[3];
      default: return i == 3 ? 1 : std::min(sv[3], 1 - dv[3]);  // GL_SRC_ALPHA_SATURATE
    }
  };
  const GLenum factors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
                            GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
                            GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
                            GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA,
                            GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
  for (GLenum src : factors) {
    for (GLenum dst : factors) {
      if (dst == GL_SRC_ALPHA_SATURATE) continue;  // a source factor only
      CAPTURE(src);
      CAPTURE(dst);
      glBlendFunc(src, dst);
      glClearColor(d.r / 255.0f, d.g / 255.0f, d.b / 255.0f, d.a / 255.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glColor4ub(s.r, s.g, s.b, s.a);
      fullScreenQuad(0.0f);
      const Rgba p = pixelAt(3, 3);
      const uint8_t got[4] = {p.r, p.g, p.b, p.a};
      const uint8_t sv[4] = {s.r, s.g, s.b, s.a}, dv[4] = {d.r, d.g, d.b, d.a};
      for (int i = 0; i < 4; ++i) {
        const double expected =
            std::clamp(sv[i] * factor(src, i) + dv[i] * factor(dst, i), 0.0, 255.0);
        // 8-bit arithmetic: each product is rounded, and the constant colour is held in 8 bits.
        CHECK(std::fabs(got[i] - expected) <= 1.5);
      }
    }
  }
}

TEST_CASE("pipeline fragments: the sixteen logic ops") {
  ScopedContext context(8, 8);
  glEnable(GL_COLOR_LOGIC_OP);
  glEnable(GL_BLEND);  // a logic op replaces blending
  glBlendFunc(GL_ZERO, GL_ZERO);
  const uint8_t s = 0xCC, d = 0xAA;
  const struct {
    GLenum op;
    uint8_t result;
  } cases[] = {{GL_CLEAR, 0x00},        {GL_AND, 0x88},         {GL_AND_REVERSE, 0x44},
               {GL_COPY, 0xCC},         {GL_AND_INVERTED, 0x22}, {GL_NOOP, 0xAA},
               {GL_XOR, 0x66},          {GL_OR, 0xEE},          {GL_NOR, 0x11},
               {GL_EQUIV, 0x99},        {GL_INVERT, 0x55},      {GL_OR_REVERSE, 0xDD},
               {GL_COPY_INVERTED, 0x33}, {GL_OR_INVERTED, 0xBB}, {GL_NAND, 0x77},
               {GL_SET, 0xFF}};
  for (const auto& c : cases) {
    CAPTURE(c.op);
    glClearColor(d / 255.0f, d / 255.0f, d / 255.0f, d / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glLogicOp(c.op);
    glColor4ub(s, s, s, s);
    fullScreenQuad(0.0f);
    CHECK(pixelAt(2, 2) == Rgba{c.result, c.result, c.result, c.result});
  }
}

TEST_CASE("pipeline fragments: colour masks, and glClear inside the scissor box") {
  ScopedContext context(16, 16);
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  const Rgba cleared = pixelAt(0, 0);
  CHECK(cleared == Rgba{51, 102, 153, 204});

  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glColor4f(1, 1, 1, 1);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(5, 5) == Rgba{255, 102, 255, 204});
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 4, 4, 4);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(pixelAt(5, 5) == Rgba{0, 0, 0, 0});
  CHECK(pixelAt(3, 5) == Rgba{255, 102, 255, 204});
  CHECK(pixelAt(8, 5) == Rgba{255, 102, 255, 204});
  // Primitives are scissored too.
  glColor3f(0, 1, 0);
  fullScreenQuad(0.0f);
  CHECK(pixelAt(7, 7).g == 255);
  CHECK(pixelAt(8, 8).g == 102);
  glDisable(GL_SCISSOR_TEST);

  // glClear of the depth buffer honours the depth mask.
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  CHECK(depthAt(1, 1) == doctest::Approx(0.25f));
}

// A textured draw prepares its texture's lookups once (fragment/kernel_texture.h); the next draw
// must see the texture as it is then: a new image of another size (new texel storage), then new
// texels in place, on the same texture object, with no glFinish between the draws.
TEST_CASE("pipeline fragments: each textured draw samples the texture as it is at that draw") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  auto solidImage = [](int size, Rgba colour) {
    const std::vector<Rgba> texels(static_cast<size_t>(size) * size, colour);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  };
  auto texturedRectangle = [](float x0, float x1) {
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(x0, 0.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex2f(x1, 0.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex2f(x1, 64.0f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex2f(x0, 64.0f);
    glEnd();
  };
  const Rgba red{200, 10, 20, 255}, green{15, 210, 30, 255}, blue{5, 25, 220, 255};
  solidImage(2, red);
  texturedRectangle(0.0f, 24.0f);
  solidImage(16, green);
  texturedRectangle(24.0f, 40.0f);
  const std::vector<Rgba> blueTexels(16 * 16, blue);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, blueTexels.data());
  texturedRectangle(40.0f, 64.0f);
  for (int y : {0, 31, 63}) {
    CHECK(pixelAt(10, y) == red);
    CHECK(pixelAt(30, y) == green);
    CHECK(pixelAt(50, y) == blue);
  }
  glDeleteTextures(1, &name);
}
