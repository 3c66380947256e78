// The block kernels weigh antialiased lines and points (GL_LINE_SMOOTH, GL_POINT_SMOOTH) as the
// reference path does: the same random smooth lines and points are drawn with the fast paths
// off and on (fast_path_comparison.h), and every buffer must be the same bytes. The states are
// those a block kernel covers (blending with compiled and general factors or none, the depth
// test with every function, with and without the depth mask, colour masked off while depth is
// written, the stencil test, texturing, fog, wide lines, large and attenuated points, stipple,
// perspective) and neighbours that keep the reference path (alpha test, logic op, a partial
// colour mask). A point's pixels outside its disc must change nothing, not even depth or
// stencil; a line's pixels of coverage 0 still write depth.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <functional>

#include "fast_path_comparison.h"

using glass::test::useDepthTest;

namespace {

// Random smooth segments of widths 1 to 5.5 and smooth points of sizes 1 to 10.4.
void drawRandomSmoothShapes() {
  glass::test::RandomVertices random(2468);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  for (int group = 0; group < 6; ++group) {
    glLineWidth(1.0f + static_cast<float>(group) * 0.9f);
    glBegin(GL_LINES);
    for (int i = 0; i < 60; ++i) {
      const float ax = random.x(), ay = random.y();
      random.vertex(ax, ay);
      // Some segments shorter than a pixel, which the coverage thins.
      const float reach = i % 7 == 0 ? 0.05f * random.unit() : 1.0f;
      random.vertex(ax + reach * random.shift(), ay + reach * random.shift());
    }
    glEnd();
    glPointSize(group == 0 ? 1.0f : 2.0f * static_cast<float>(group) + 0.37f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 60; ++i) random.vertex(random.x(), random.y());
    glEnd();
  }
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 12; ++i) random.vertex(random.x(), random.y());
  glEnd();
}

void checkSameBytes(const std::function<void()>& setState, bool drawsSomething = true) {
  glass::test::checkFastPathsMatch(setState, drawRandomSmoothShapes, drawsSomething);
}

void blend(GLenum source, GLenum destination) {
  glEnable(GL_BLEND);
  glBlendFunc(source, destination);
}

}  // namespace

TEST_CASE("smooth lines and points: the block kernels write the reference path's bytes") {
  SUBCASE("blending as programs antialias") { checkSameBytes([] { blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); }); }
  SUBCASE("additive blending") { checkSameBytes([] { blend(GL_SRC_ALPHA, GL_ONE); }); }
  SUBCASE("blend factors without a compiled copy") {
    checkSameBytes([] { blend(GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE); });
  }
  SUBCASE("no blending: the weighed alpha is stored") { checkSameBytes([] {}); }
  SUBCASE("every depth function, depth mask on") {
    for (GLenum func : {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
                        GL_ALWAYS}) {
      CAPTURE(func);
      checkSameBytes(
          [func] {
            useDepthTest(func, true);
            blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
          },
          func != GL_NEVER && func != GL_EQUAL);
    }
  }
  SUBCASE("depth mask off") {
    checkSameBytes([] {
      useDepthTest(GL_LESS, false);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("colour masked off, depth written: pixels outside a point's disc write no depth") {
    checkSameBytes([] {
      useDepthTest(GL_LEQUAL, true);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    });
  }
  SUBCASE("stencil test: pixels outside a point's disc change no stencil") {
    checkSameBytes([] {
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 1, 0xFF);
      glStencilOp(GL_INCR, GL_DECR, GL_INCR);
      useDepthTest(GL_LESS, true);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("texturing, linear and mipmapped") {
    for (GLenum filter : {GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR}) {
      CAPTURE(filter);
      checkSameBytes([filter] {
        if (filter == GL_LINEAR_MIPMAP_LINEAR) glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        glass::test::useGeneratedTexture(filter);
        blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      });
    }
  }
  SUBCASE("fog") {
    checkSameBytes([] {
      glass::test::useLinearFog();
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("stippled smooth lines") {
    checkSameBytes([] {
      glEnable(GL_LINE_STIPPLE);
      glLineStipple(3, 0x3F0F);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("attenuated point sizes") {
    checkSameBytes([] {
      const float attenuation[3] = {0.2f, 0.9f, 0.0f};
      glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
      glPointParameterf(GL_POINT_SIZE_MIN, 0.5f);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("perspective projection") {
    checkSameBytes([] {
      glass::test::usePerspectiveView();
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
}

TEST_CASE("smooth lines and points: neighbouring states keep the reference path's bytes") {
  SUBCASE("alpha test on the weighed alpha") {
    checkSameBytes([] {
      glEnable(GL_ALPHA_TEST);
      glAlphaFunc(GL_GREATER, 0.3f);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
  SUBCASE("logic op") {
    checkSameBytes([] {
      glEnable(GL_COLOR_LOGIC_OP);
      glLogicOp(GL_XOR);
    });
  }
  SUBCASE("partial colour mask") {
    checkSameBytes([] {
      glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
      blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    });
  }
}
