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

#include <functional>

#include "fast_path_comparison.h"

using glass::test::useDepthTest;

namespace {

// Random segments, overlapping often enough for the depth test to decide many fragments; a strip
// among them.
void drawRandomLines() {
  glass::test::RandomVertices random(12345);
  glBegin(GL_LINES);
  for (int i = 0; i < 400; ++i) {
    const float ax = random.x(), ay = random.y();
    random.vertex(ax, ay);
    random.vertex(ax + random.shift(), ay + random.shift());
  }
  glEnd();
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 40; ++i) random.vertex(random.x(), random.y());
  glEnd();
}

// drawsSomething: as checkFastPathsMatch's.
void checkSameBytes(const std::function<void()>& setState, bool drawsSomething = true) {
  glass::test::checkFastPathsMatch(setState, drawRandomLines, drawsSomething);
}

}  // namespace

TEST_CASE("line kernels: the states they cover write the reference path's bytes") {
  SUBCASE("smooth colour, no depth test") { checkSameBytes([] {}); }
  SUBCASE("flat colour") { checkSameBytes([] { glShadeModel(GL_FLAT); }); }
  SUBCASE("every depth function, depth mask on") {
    for (GLenum func : {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
                        GL_ALWAYS}) {
      CAPTURE(func);
      checkSameBytes([func] { useDepthTest(func, true); }, func != GL_NEVER && func != GL_EQUAL);
    }
  }
  SUBCASE("depth mask off") { checkSameBytes([] { useDepthTest(GL_LESS, false); }); }
  SUBCASE("colour masked off, depth written") {
    checkSameBytes([] {
      useDepthTest(GL_LEQUAL, true);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    });
  }
  SUBCASE("no draw buffer, depth written") {
    checkSameBytes([] {
      useDepthTest(GL_GREATER, true);
      glDrawBuffer(GL_NONE);
    });
  }
  SUBCASE("wide lines: runs of several fragments across both axes") {
    checkSameBytes([] {
      glLineWidth(4.0f);
      useDepthTest(GL_LESS, true);
    });
  }
  SUBCASE("stippled lines") {
    checkSameBytes([] {
      glEnable(GL_LINE_STIPPLE);
      glLineStipple(2, 0x5F3A);
      useDepthTest(GL_LESS, true);
    });
  }
  SUBCASE("perspective projection") { checkSameBytes(glass::test::usePerspectiveView); }
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
      useDepthTest(GL_LESS, true);
    });
  }
  SUBCASE("logic op") {
    checkSameBytes([] {
      glEnable(GL_COLOR_LOGIC_OP);
      glLogicOp(GL_XOR);
    });
  }
  SUBCASE("partial colour mask") { checkSameBytes([] { glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE); }); }
  SUBCASE("fog") { checkSameBytes(glass::test::useLinearFog); }
  SUBCASE("texturing") { checkSameBytes([] { glass::test::useGeneratedTexture(); }); }
}
