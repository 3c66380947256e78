// Level of detail (spec 3.8.8 and 3.8.9) against values worked out by hand: the 2x2 pixel quads
// and the differences of the texture coordinates across them, the scale factor rho, lambda and
// its clamping, the magnification switch-over point c and the mipmap levels a lambda selects.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>

#include "pipeline_test_support.h"
#include "texture/texture_lod.h"

using glass::gl::levelOfDetail;
using glass::gl::magnificationSwitchOverPoint;
using glass::gl::MipmapLevels;
using glass::gl::PixelQuad;
using glass::gl::pixelQuadOf;
using glass::gl::quadTexCoordDifferences;
using glass::gl::selectMipmapLevels;
using glass::gl::TexCoordDerivatives;
using glass::gl::textureScaleFactor;

TEST_CASE("pixels pair into 2x2 quads counted from the top row of the window") {
  // An even height: quads {2i, 2i + 1} x {2j, 2j + 1}; the upper row of a quad is the odd one.
  const PixelQuad a = pixelQuadOf(5, 298, 300);
  CHECK(a.left == 4);
  CHECK(a.top == 299);
  CHECK(pixelQuadOf(4, 299, 300).top == 299);
  CHECK(pixelQuadOf(0, 0, 300).top == 1);
  CHECK(pixelQuadOf(1, 1, 300).left == 0);
  // An odd height: the top row 300 pairs with 299, and the bottom row 0 with the row below the
  // window (which the planes can still evaluate).
  CHECK(pixelQuadOf(7, 300, 301).top == 300);
  CHECK(pixelQuadOf(7, 299, 301).top == 300);
  CHECK(pixelQuadOf(7, 298, 301).top == 298);
  CHECK(pixelQuadOf(7, 0, 301).top == 0);
}

namespace {

// Attribute planes with s in varying 0, t in 1 and q in 3: value/w = a0 + dx x + dy y.
glass::raster::AttributePlanes planesOf(const double s[3], const double t[3], const double q[3]) {
  glass::raster::AttributePlanes p{};
  const double* planes[4] = {s, t, q, q};
  for (int k = 0; k < 4; ++k) {
    p.a0[k] = planes[k][0];
    p.dx[k] = planes[k][1];
    p.dy[k] = planes[k][2];
  }
  return p;
}

}  // namespace

TEST_CASE("quad differences are differences of s/q and t/q between the quad's pixel centres") {
  // s/w = 2x, q/w = 1 + x/2 (projective texture coordinates on an orthographic quad), t/w = 1/4.
  // Quad (left 0, top 1): upper-left centre (0.5, 1.5), upper-right (1.5, 1.5), lower-left
  // (0.5, 0.5). s/q = 2x / (1 + x/2): 1 / 1.25 = 0.8 at x = 0.5, 3 / 1.75 = 1.714286 at x = 1.5.
  const double s[3] = {0.0, 2.0, 0.0}, t[3] = {0.25, 0.0, 0.0}, q[3] = {1.0, 0.5, 0.0};
  const glass::raster::AttributePlanes planes = planesOf(s, t, q);
  TexCoordDerivatives d = quadTexCoordDifferences(planes, 0, 1, 3, PixelQuad{0, 1}, true);
  CHECK(d.dsdx == doctest::Approx(1.714286 - 0.8).epsilon(1e-6));
  CHECK(d.dsdy == 0.0);  // nothing varies with y
  CHECK(d.dtdx == doctest::Approx(0.25 / 1.75 - 0.25 / 1.25).epsilon(1e-6));
  CHECK(d.dtdy == 0.0);
  // The next quad to the right: x = 2.5 and 3.5, s/q = 5 / 2.25 = 2.222222, 7 / 2.75 = 2.545455.
  d = quadTexCoordDifferences(planes, 0, 1, 3, PixelQuad{2, 1}, false);
  CHECK(d.dsdx == doctest::Approx(2.545455 - 2.222222).epsilon(1e-5));
  CHECK(d.dtdx == 0.0);  // t skipped (a 1D texture)
}

TEST_CASE("the vertical difference runs from the quad's lower pixel to its upper one") {
  // s/w = 0.2 + 0.1 y, q/w = 1 + 0.25 y. Quad (left 2, top 5): the upper-left centre (2.5, 5.5)
  // has s/q = 0.75 / 2.375 = 0.315789, the lower-left (2.5, 4.5) 0.65 / 2.125 = 0.305882.
  const double s[3] = {0.2, 0.0, 0.1}, t[3] = {0.0, 0.0, 0.0}, q[3] = {1.0, 0.0, 0.25};
  const TexCoordDerivatives d =
      quadTexCoordDifferences(planesOf(s, t, q), 0, 1, 3, PixelQuad{2, 5}, true);
  CHECK(d.dsdy == doctest::Approx(0.315789 - 0.305882).epsilon(1e-4));
  CHECK(d.dsdx == 0.0);
  // rho for a 64-texel-wide texture: 64 * 0.0099071 = 0.634, lambda = log2 0.634 = -0.657: a
  // magnified quad.
  CHECK(textureScaleFactor(d, 64, 64) == doctest::Approx(0.634054).epsilon(1e-5));
}

TEST_CASE("every pixel of a 2x2 quad takes the quad's mipmap level") {
  // A 4 x 2 window and a 16 x 16 texture whose five levels are luminance 0, 60, 120, 180, 240.
  // Projective texture coordinates along x: (s, q) = (0, 1) at x = 0 and (8, 3) at x = 4, so
  // s/w = 2x and q/w = 1 + x/2 as in the test above, and s/q = 2x / (1 + x/2).
  //   Exact derivatives at the pixel centres: ds/dx = 2 / (1 + x/2)^2, rho = 16 ds/dx =
  //   20.5, 10.4, 6.3, 4.2 at x = 0.5, 1.5, 2.5, 3.5: lambda 4.36, 3.39, 2.66, 2.08, nearest
  //   levels 4, 3, 3, 2.
  //   Per quad: rho = 16 (1.714286 - 0.8) = 14.63 (lambda 3.87, level 4) for pixels 0 and 1,
  //   16 (2.545455 - 2.222222) = 5.17 (lambda 2.37, level 2) for pixels 2 and 3.
  glass::test::ScopedContext context(4, 2);
  glass::test::pixelProjection(4, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLubyte texels[16 * 16];
  for (int level = 0, size = 16; size >= 1; ++level, size /= 2) {
    for (GLubyte& texel : texels) texel = static_cast<GLubyte>(60 * level);
    glTexImage2D(GL_TEXTURE_2D, level, GL_LUMINANCE, size, size, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                 texels);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord4f(0.0f, 0.0f, 0.0f, 1.0f);
  glVertex2i(0, 0);
  glTexCoord4f(8.0f, 0.0f, 0.0f, 3.0f);
  glVertex2i(4, 0);
  glTexCoord4f(8.0f, 0.0f, 0.0f, 3.0f);
  glVertex2i(4, 2);
  glTexCoord4f(0.0f, 0.0f, 0.0f, 1.0f);
  glVertex2i(0, 2);
  glEnd();
  const int expected[4] = {240, 240, 120, 120};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      INFO("pixel (" << x << ", " << y << ")");
      CHECK(glass::test::pixelAt(x, y).r == expected[x]);
    }
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("rho of a texture shrunk four times along x is 4, lambda 2") {
  // A 64-texel-wide texture spread over 16 pixels: ds/dx = 1/16, du/dx = 64/16 = 4.
  TexCoordDerivatives d;
  d.dsdx = 1.0 / 16.0;
  d.dtdy = 1.0 / 64.0;  // one texel per pixel vertically: dv/dy = 1
  CHECK(textureScaleFactor(d, 64, 64) == doctest::Approx(4.0));
  CHECK(levelOfDetail(4.0, -1000.0f, 1000.0f) == doctest::Approx(2.0f));
}

TEST_CASE("one texel per pixel gives rho 1 and lambda 0") {
  TexCoordDerivatives d;
  d.dsdx = 1.0 / 256.0;
  d.dtdy = 1.0 / 128.0;
  CHECK(textureScaleFactor(d, 256, 128) == doctest::Approx(1.0));
  CHECK(levelOfDetail(1.0, -1000.0f, 1000.0f) == doctest::Approx(0.0f));
}

TEST_CASE("rho takes the longer of the two screen-axis footprints, each a Euclidean length") {
  // x footprint: (du/dx, dv/dx) = (3, 4), length 5; y footprint: (du/dy, dv/dy) = (0.5, 0).
  TexCoordDerivatives d;
  d.dsdx = 3.0 / 64.0;
  d.dtdx = 4.0 / 32.0;
  d.dsdy = 0.5 / 64.0;
  CHECK(textureScaleFactor(d, 64, 32) == doctest::Approx(5.0));
  CHECK(levelOfDetail(5.0, -1000.0f, 1000.0f) == doctest::Approx(2.321928f));  // log2 5

  // The y footprint wins when it is longer: (du/dy, dv/dy) = (6, 8), length 10.
  d.dsdy = 6.0 / 64.0;
  d.dtdy = 8.0 / 32.0;
  CHECK(textureScaleFactor(d, 64, 32) == doctest::Approx(10.0));
}

TEST_CASE("a one-dimensional texture ignores t") {
  TexCoordDerivatives d;
  d.dsdx = 2.0 / 32.0;
  d.dtdx = 100.0;  // t does not exist for a 1D texture: height 0
  CHECK(textureScaleFactor(d, 32, 0) == doctest::Approx(2.0));
}

TEST_CASE("a perspective-divided footprint: a floor seen at a grazing angle") {
  // u = 256 s with s = a / w along a scanline; hand-computed at the pixel where
  // ds/dx = 0.001 and ds/dy = 0.03, dt/dx = 0.0005, dt/dy = 0.04 on a 256 x 256 texture:
  // x footprint sqrt(0.256^2 + 0.128^2) = 0.286217, y footprint sqrt(7.68^2 + 10.24^2) = 12.8.
  TexCoordDerivatives d;
  d.dsdx = 0.001;
  d.dsdy = 0.03;
  d.dtdx = 0.0005;
  d.dtdy = 0.04;
  CHECK(textureScaleFactor(d, 256, 256) == doctest::Approx(12.8));
  CHECK(levelOfDetail(12.8, -1000.0f, 1000.0f) == doctest::Approx(3.678072f));  // log2 12.8
}

TEST_CASE("lambda is clamped to [TEXTURE_MIN_LOD, TEXTURE_MAX_LOD]") {
  CHECK(levelOfDetail(64.0, -1000.0f, 2.5f) == doctest::Approx(2.5f));
  CHECK(levelOfDetail(0.25, 0.5f, 1000.0f) == doctest::Approx(0.5f));
  CHECK(levelOfDetail(0.25, -1000.0f, 1000.0f) == doctest::Approx(-2.0f));
  // rho = 0 (a constant texture coordinate) is infinitely magnified: lambda = min LOD.
  CHECK(levelOfDetail(0.0, -1000.0f, 1000.0f) == doctest::Approx(-1000.0f));
}

TEST_CASE("the switch-over point c is 1/2 only for a LINEAR magnification with NEAREST_MIPMAP_*") {
  CHECK(magnificationSwitchOverPoint(GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR) == 0.5f);
  CHECK(magnificationSwitchOverPoint(GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR) == 0.5f);
  CHECK(magnificationSwitchOverPoint(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR) == 0.0f);
  CHECK(magnificationSwitchOverPoint(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR) == 0.0f);
  CHECK(magnificationSwitchOverPoint(GL_NEAREST, GL_LINEAR) == 0.0f);
  CHECK(magnificationSwitchOverPoint(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST) == 0.0f);
}

TEST_CASE("*_MIPMAP_NEAREST picks the level nearest to lambda: base + ceil(lambda + 1/2) - 1") {
  const auto level = [](float lambda) {
    return selectMipmapLevels(lambda, GL_NEAREST_MIPMAP_NEAREST, 0, 6).level1;
  };
  CHECK(level(0.3f) == 0);
  CHECK(level(0.5f) == 0);
  CHECK(level(0.6f) == 1);   // ceil(1.1) - 1
  CHECK(level(1.5f) == 1);   // ceil(2.0) - 1
  CHECK(level(1.51f) == 2);  // ceil(2.01) - 1
  CHECK(level(5.4f) == 5);
  CHECK(level(6.4f) == 6);   // base + lambda = 6.4 <= q + 1/2
  CHECK(level(9.0f) == 6);   // beyond the last level: q
  // With TEXTURE_BASE_LEVEL 2 and q = 4 levels count from 2.
  CHECK(selectMipmapLevels(1.2f, GL_LINEAR_MIPMAP_NEAREST, 2, 4).level1 == 3);
  CHECK(selectMipmapLevels(3.0f, GL_LINEAR_MIPMAP_NEAREST, 2, 4).level1 == 4);
}

TEST_CASE("*_MIPMAP_LINEAR blends levels floor(lambda) and floor(lambda) + 1 by frac(lambda)") {
  MipmapLevels m = selectMipmapLevels(1.25f, GL_LINEAR_MIPMAP_LINEAR, 0, 6);
  CHECK(m.level1 == 1);
  CHECK(m.level2 == 2);
  CHECK(m.weight2 == doctest::Approx(0.25f));
  m = selectMipmapLevels(0.75f, GL_NEAREST_MIPMAP_LINEAR, 0, 6);
  CHECK(m.level1 == 0);
  CHECK(m.level2 == 1);
  CHECK(m.weight2 == doctest::Approx(0.75f));
  // base + lambda >= q: the last level alone.
  m = selectMipmapLevels(6.0f, GL_LINEAR_MIPMAP_LINEAR, 0, 6);
  CHECK(m.level1 == 6);
  CHECK(m.level2 == 6);
  m = selectMipmapLevels(5.5f, GL_LINEAR_MIPMAP_LINEAR, 1, 6);
  CHECK(m.level1 == 6);
  CHECK(m.weight2 == 0.0f);
}
