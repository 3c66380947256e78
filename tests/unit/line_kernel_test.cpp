// The line kernels (fragment/line_kernels.h) write the reference path's bytes.
//
// The same random lines are drawn twice in fresh contexts, once with the fast paths off (the
// reference path alone) and once with them on, and the colour, depth and stencil buffers must be
// identical byte for byte. The states are those a line kernel is chosen for (smooth and flat
// colour, the depth test with every function, with and without the depth mask, colour written or
// masked off, wide and stippled lines, a perspective projection) and their neighbours, which
// must keep the reference path (blending, alpha test, stencil test, texturing, fog, logic op, a
// partial colour mask): a kernel taken for one of them would write different bytes.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "core/fast_paths.h"
#include "pipeline_test_support.h"

using glass::gl::ScopedFastPaths;
using glass::test::ScopedContext;

namespace {

// Wider and taller than one 64 x 64 tile, not a multiple of it.
constexpr int kWidth = 150, kHeight = 100;

struct Buffers {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
};

// Random segments across the window and a little beyond it, in random colours and depths,
// overlapping often enough for the depth test to decide many fragments; a strip among them.
void drawRandomLines() {
  std::mt19937 random(12345);
  std::uniform_real_distribution<float> x(-10.0f, kWidth + 10.0f), y(-10.0f, kHeight + 10.0f);
  std::uniform_real_distribution<float> z(-0.9f, 0.9f), unit(0.0f, 1.0f), shift(-40.0f, 40.0f);
  const auto vertex = [&](float vx, float vy) {
    glColor4f(unit(random), unit(random), unit(random), unit(random));
    glVertex3f(vx, vy, z(random));
  };
  glBegin(GL_LINES);
  for (int i = 0; i < 400; ++i) {
    const float ax = x(random), ay = y(random);
    vertex(ax, ay);
    vertex(ax + shift(random), ay + shift(random));
  }
  glEnd();
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 40; ++i) vertex(x(random), y(random));
  glEnd();
}

// The buffers after clearing (depth to one half, so that every depth function passes some
// fragments and fails others) and drawing the lines with `setState` applied.
Buffers render(bool fastPaths, const std::function<void()>& setState) {
  ScopedFastPaths paths(fastPaths);
  ScopedContext context(kWidth, kHeight);
  glass::test::pixelProjection(kWidth, kHeight);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(0.5);
  glClearStencil(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  setState();
  drawRandomLines();
  glFinish();

  Buffers b;
  b.color.resize(size_t{kWidth} * kHeight * 4);
  b.depth.resize(size_t{kWidth} * kHeight);
  b.stencil.resize(size_t{kWidth} * kHeight);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
  glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
  glReadPixels(0, 0, kWidth, kHeight, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
  return b;
}

// drawsSomething: the state lets some fragment through (GL_NEVER does not, nor GL_EQUAL against
// the cleared depth).
void checkSameBytes(const std::function<void()>& setState, bool drawsSomething = true) {
  const Buffers reference = render(false, setState);
  const Buffers fast = render(true, setState);
  CHECK(fast.color == reference.color);
  CHECK(fast.depth == reference.depth);
  CHECK(fast.stencil == reference.stencil);
  // Not a comparison of two empty pictures: the lines changed some pixel's colour or depth.
  if (!drawsSomething) return;
  const Buffers cleared = render(false, [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); });
  CHECK((reference.color != cleared.color || reference.depth != cleared.depth));
}

void depthTest(GLenum func, bool mask) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(func);
  glDepthMask(mask ? GL_TRUE : GL_FALSE);
}

}  // namespace

TEST_CASE("line kernels: the states they cover write the reference path's bytes") {
  SUBCASE("smooth colour, no depth test") { checkSameBytes([] {}); }
  SUBCASE("flat colour") { checkSameBytes([] { glShadeModel(GL_FLAT); }); }
  SUBCASE("every depth function, depth mask on") {
    for (GLenum func : {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
                        GL_ALWAYS}) {
      CAPTURE(func);
      checkSameBytes([func] { depthTest(func, true); }, func != GL_NEVER && func != GL_EQUAL);
    }
  }
  SUBCASE("depth mask off") { checkSameBytes([] { depthTest(GL_LESS, false); }); }
  SUBCASE("colour masked off, depth written") {
    checkSameBytes([] {
      depthTest(GL_LEQUAL, true);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    });
  }
  SUBCASE("no draw buffer, depth written") {
    checkSameBytes([] {
      depthTest(GL_GREATER, true);
      glDrawBuffer(GL_NONE);
    });
  }
  SUBCASE("wide lines: runs of several fragments across both axes") {
    checkSameBytes([] {
      glLineWidth(4.0f);
      depthTest(GL_LESS, true);
    });
  }
  SUBCASE("stippled lines") {
    checkSameBytes([] {
      glEnable(GL_LINE_STIPPLE);
      glLineStipple(2, 0x5F3A);
      depthTest(GL_LESS, true);
    });
  }
  SUBCASE("perspective projection") {
    checkSameBytes([] {
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glFrustum(0, kWidth, 0, kHeight, 1, 3);
      glMatrixMode(GL_MODELVIEW);
      glTranslatef(-kWidth * 0.5f, -kHeight * 0.5f, -2.0f);
      glScalef(1.5f, 1.5f, 1.0f);
      depthTest(GL_LESS, true);
    });
  }
}

TEST_CASE("line kernels: neighbouring states keep the reference path") {
  SUBCASE("blending") {
    checkSameBytes([] {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("alpha test") {
    checkSameBytes([] {
      glEnable(GL_ALPHA_TEST);
      glAlphaFunc(GL_GREATER, 0.5f);
    });
  }
  SUBCASE("stencil test") {
    checkSameBytes([] {
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 1, 0xFF);
      glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
      depthTest(GL_LESS, true);
    });
  }
  SUBCASE("logic op") {
    checkSameBytes([] {
      glEnable(GL_COLOR_LOGIC_OP);
      glLogicOp(GL_XOR);
    });
  }
  SUBCASE("partial colour mask") { checkSameBytes([] { glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE); }); }
  SUBCASE("fog") {
    checkSameBytes([] {
      glEnable(GL_FOG);
      glFogi(GL_FOG_MODE, GL_LINEAR);
      glFogf(GL_FOG_START, -1.0f);
      glFogf(GL_FOG_END, 1.0f);
    });
  }
  SUBCASE("texturing") {
    checkSameBytes([] {
      static const uint8_t texels[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255,
                                                0, 0, 255, 255, 255, 255, 0, 128};
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glEnable(GL_TEXTURE_2D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
      glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
      static const float sPlane[4] = {0.05f, 0.0f, 0.0f, 0.0f}, tPlane[4] = {0.0f, 0.07f, 0.0f, 0.0f};
      glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
      glTexGenfv(GL_T, GL_OBJECT_PLANE, tPlane);
      glEnable(GL_TEXTURE_GEN_S);
      glEnable(GL_TEXTURE_GEN_T);
    });
  }
}
