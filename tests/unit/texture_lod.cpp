// Level of detail (spec 3.8.8 and 3.8.9) against values worked out by hand: the scale factor rho,
// lambda and its clamping, the magnification switch-over point c and the mipmap levels a lambda
// selects.
#include <doctest/doctest.h>

#include <cmath>

#include "texture/texture_lod.h"

using glass::gl::levelOfDetail;
using glass::gl::magnificationSwitchOverPoint;
using glass::gl::MipmapLevels;
using glass::gl::selectMipmapLevels;
using glass::gl::TexCoordDerivatives;
using glass::gl::textureScaleFactor;

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
