// Convex quadrilaterals (setupQuad, TiledRasterizer::quad): the two triangles of an antialiased
// line's or point's rectangle walked in one pass. Random convex quadrilaterals (rectangles at
// any angle, as thin as a line's and as wide as a point's, and general convex shapes, on the
// 1/256 grid and off it, some with a corner on a pixel centre) are drawn both ways: in one pass
// the pixels must be those of the two triangles (v0, v1, v2) and (v2, v3, v0), each once; the
// first triangle's pixels must get its fragments to the bit, the second's the values of the same
// plane (within rounding); and tile by tile, at 1 and 2 threads, the same fragments as the
// quadrilateral set up whole.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include "glass/raster/framebuffer.h"
#include "glass/raster/tiled_rasterizer.h"
#include "glass/raster/triangle.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::RecordingSink;

namespace {

constexpr int kWidth = 200, kHeight = 150;
constexpr int kVaryings = 3;

struct Quad {
  WindowVertex v[4];
  bool rectangle = false;  // else any convex shape, whose first triangle may be a sliver
};

// A corner of a quadrilateral whose values are planes in window x, y, as an antialiased line's
// rectangle carries them: depth, 1/w and, when perspective-correct, each varying times 1/w
// (otherwise each varying itself), at the corner snapped to 1/256 pixel. Rounded to float, the
// corners' values fit their planes all but exactly.
WindowVertex planeVertex(float x, float y, const double (&coefficients)[2 + kVaryings][3], bool perspectiveCorrect) {
  WindowVertex v{};
  v.x = x;
  v.y = y;
  // At the position the rasterizer snaps the corner to, where its planes are fitted.
  const double sx = std::nearbyint(double(x) * 256.0) / 256.0, sy = std::nearbyint(double(y) * 256.0) / 256.0;
  auto at = [&](int k) { return coefficients[k][0] + coefficients[k][1] * sx + coefficients[k][2] * sy; };
  v.z = static_cast<float>(at(0));
  v.invW = static_cast<float>(at(1));
  for (int k = 0; k < kVaryings; ++k)
    v.varyings[k] = static_cast<float>(perspectiveCorrect ? at(2 + k) / at(1) : at(2 + k));
  return v;
}

class RandomQuads {
 public:
  explicit RandomQuads(unsigned seed) : rng_(seed) {}

  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(rng_); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  float onGrid(double v) {
    switch (pick(3)) {
      case 0: return static_cast<float>(std::round(v * 256.0) / 256.0);
      case 1: return static_cast<float>(std::round(v * 2.0) / 2.0);  // pixel borders and centres
      default: return static_cast<float>(v);
    }
  }

  Quad next(bool perspectiveCorrect) {
    double coefficients[2 + kVaryings][3];
    coefficients[0][0] = uniform(0.2, 0.8);
    coefficients[0][1] = uniform(-0.002, 0.002);
    coefficients[0][2] = uniform(-0.002, 0.002);
    coefficients[1][0] = uniform(0.5, 2.0);  // 1/w stays positive over the window
    coefficients[1][1] = uniform(-0.002, 0.002);
    coefficients[1][2] = uniform(-0.002, 0.002);
    for (int k = 2; k < 2 + kVaryings; ++k)
      for (double& c : coefficients[k]) c = uniform(-1.0, 1.0);
    const double cx = uniform(-20.0, kWidth + 20.0), cy = uniform(-20.0, kHeight + 20.0);
    double x[4], y[4];
    const bool rectangle = pick(2) == 0;
    if (rectangle) {  // a rectangle at any angle: a line's (long and 2 to 4 wide) or a point's
      const double angle = uniform(0.0, 2.0 * std::numbers::pi);
      const double length = pick(2) == 0 ? uniform(1.0, 90.0) : uniform(1.0, 8.0), width = uniform(1.0, 4.0);
      const double dx = std::cos(angle), dy = std::sin(angle);
      const double along[4] = {-1, 1, 1, -1}, across[4] = {-1, -1, 1, 1};
      for (int i = 0; i < 4; ++i) {
        x[i] = cx + along[i] * length / 2 * dx - across[i] * width / 2 * dy;
        y[i] = cy + along[i] * length / 2 * dy + across[i] * width / 2 * dx;
      }
    } else {  // four points on an ellipse in order: convex
      double angles[4];
      for (double& a : angles) a = uniform(0.0, 2.0 * std::numbers::pi);
      std::sort(angles, angles + 4);
      const double rx = uniform(2.0, 60.0), ry = uniform(2.0, 60.0);
      for (int i = 0; i < 4; ++i) {
        x[i] = cx + rx * std::cos(angles[i]);
        y[i] = cy + ry * std::sin(angles[i]);
      }
    }
    const int start = pick(4), direction = pick(2) == 0 ? 1 : 3;  // any first corner, either way round
    // A corner on a pixel centre, where the fill rule decides for both edges at once.
    if (pick(3) == 0) {
      x[start] = std::floor(x[start]) + 0.5;
      y[start] = std::floor(y[start]) + 0.5;
    }
    Quad q;
    q.rectangle = rectangle;
    for (int i = 0; i < 4; ++i) {
      const int c = (start + direction * i) % 4;
      q.v[i] = planeVertex(onGrid(x[c]), onGrid(y[c]), coefficients, perspectiveCorrect);
    }
    return q;
  }

 private:
  std::mt19937 rng_;
};

TriangleSettings settingsFor(const PixelRect& bounds, bool perspectiveCorrect) {
  TriangleSettings s;
  s.bounds = bounds;
  s.varyingCount = kVaryings;
  s.perspectiveCorrect = perspectiveCorrect;
  return s;
}

std::vector<Fragment> sortedByPixel(std::vector<Fragment> fragments) {
  std::sort(fragments.begin(), fragments.end(), [](const Fragment& f, const Fragment& g) {
    return std::tie(f.x, f.y) < std::tie(g.x, g.y);
  });
  return fragments;
}

bool sameBits(const Fragment& f, const Fragment& g) {
  return f.x == g.x && f.y == g.y && f.depth == g.depth &&
         std::memcmp(f.varyings, g.varyings, sizeof(float) * kVaryings) == 0;
}

std::vector<Fragment> drawnQuad(const Quad& q, const TriangleSettings& s) {
  RecordingSink sink;
  TriangleSetup setup;
  if (setupQuad(q.v[0], q.v[1], q.v[2], q.v[3], s, setup)) rasterizeTriangle(setup, sink);
  return sink.fragments;
}

std::vector<Fragment> drawnTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                                    const TriangleSettings& s) {
  RecordingSink sink;
  TriangleSetup setup;
  if (setupTriangle(a, b, c, s, setup)) rasterizeTriangle(setup, sink);
  return sink.fragments;
}

}  // namespace

TEST_CASE("quad: one pass covers its two triangles' pixels, with the first triangle's values") {
  RandomQuads random(2026);
  const PixelRect window{0, 0, kWidth, kHeight};
  int quads = 0, fromFirst = 0, fromSecond = 0, rectangleSecond = 0, cornersCovered = 0, cornersLeft = 0;
  for (int n = 0; n < 3000; ++n) {
    const bool perspectiveCorrect = random.pick(2) == 0;
    const Quad q = random.next(perspectiveCorrect);
    if (!quadIsConvex(q.v[0], q.v[1], q.v[2], q.v[3])) continue;  // a corner snapped straight
    ++quads;
    const TriangleSettings s = settingsFor(window, perspectiveCorrect);
    const std::vector<Fragment> quad = sortedByPixel(drawnQuad(q, s));
    const std::vector<Fragment> first = drawnTriangle(q.v[0], q.v[1], q.v[2], s);
    const std::vector<Fragment> second = drawnTriangle(q.v[2], q.v[3], q.v[0], s);
    CAPTURE(n);
    for (size_t i = 1; i < quad.size(); ++i)
      REQUIRE((quad[i].x != quad[i - 1].x || quad[i].y != quad[i - 1].y));  // each pixel once
    auto find = [&](int x, int y) -> const Fragment* {
      const auto it = std::lower_bound(quad.begin(), quad.end(), std::make_pair(x, y),
                                       [](const Fragment& f, const std::pair<int, int>& p) {
                                         return std::tie(f.x, f.y) < std::tie(p.first, p.second);
                                       });
      return it != quad.end() && it->x == x && it->y == y ? &*it : nullptr;
    };
    // Centres exactly on a corner where the two triangles meet (v0, v2): the fill rule decides
    // them for the quadrilateral's two edges there as for the triangles' four.
    for (const WindowVertex* corner : {&q.v[0], &q.v[2]}) {
      const double cx = std::nearbyint(double(corner->x) * 256.0) / 256.0 - 0.5;
      const double cy = std::nearbyint(double(corner->y) * 256.0) / 256.0 - 0.5;
      if (cx == std::floor(cx) && cy == std::floor(cy) && cx >= 0 && cx < kWidth && cy >= 0 && cy < kHeight)
        ++(find(int(cx), int(cy)) != nullptr ? cornersCovered : cornersLeft);
    }
    for (const Fragment& f : first) {
      const Fragment* g = find(f.x, f.y);
      REQUIRE(g != nullptr);
      REQUIRE(sameBits(f, *g));
      ++fromFirst;
    }
    for (const Fragment& f : second) {
      const Fragment* g = find(f.x, f.y);
      REQUIRE(g != nullptr);
      ++fromSecond;
      // The same planes fitted through other corners: equal but for rounding, which the
      // first triangle's planes carry over the second as far as its shape allows (a sliver
      // of a general quadrilateral magnifies it; a rectangle's halves do not).
      if (!q.rectangle) continue;
      ++rectangleSecond;
      REQUIRE(std::abs(double(f.depth) - double(g->depth)) <= 2.0);
      for (int k = 0; k < kVaryings; ++k)
        REQUIRE(std::abs(f.varyings[k] - g->varyings[k]) <= 1e-5f * std::max(1.0f, std::abs(f.varyings[k])));
    }
    // The triangles never share a pixel, so that is all the quadrilateral's pixels.
    REQUIRE(first.size() + second.size() == quad.size());
  }
  MESSAGE(quads, " quadrilaterals, ", fromFirst, " pixels of first triangles, ", fromSecond,
          " of second ones; centres on v0 or v2: ", cornersCovered, " covered, ", cornersLeft, " not");
  CHECK(quads > 2500);
  CHECK(fromFirst > 100000);
  CHECK(fromSecond > 100000);
  CHECK(rectangleSecond > 20000);
  CHECK(cornersCovered > 50);
  CHECK(cornersLeft > 50);
}

TEST_CASE("quad: only strictly convex corners, in either order round, make a quadrilateral") {
  using glass::raster::test::windowVertex;
  const WindowVertex a = windowVertex(10, 10), b = windowVertex(30, 10), c = windowVertex(30, 20),
                     d = windowVertex(10, 20);
  CHECK(quadIsConvex(a, b, c, d));
  CHECK(quadIsConvex(d, c, b, a));  // clockwise
  CHECK(quadIsConvex(b, c, d, a));
  CHECK_FALSE(quadIsConvex(a, c, b, d));  // crossed: a bow tie
  CHECK_FALSE(quadIsConvex(a, windowVertex(20, 12), c, d) == false);  // still convex
  CHECK_FALSE(quadIsConvex(a, windowVertex(20, 18), b, c));            // a dart: one corner turns back
  CHECK_FALSE(quadIsConvex(a, windowVertex(20, 10), b, c));            // three corners in a line
  CHECK_FALSE(quadIsConvex(a, a, c, d));                               // two corners the same
  // Corners closer than 1/512 pixel snap together.
  CHECK_FALSE(quadIsConvex(a, windowVertex(10.001f, 10.0f), c, d));
  CHECK_FALSE(quadIsConvex(a, b, c, windowVertex(NAN, 20)));
  CHECK_FALSE(quadIsConvex(a, b, c, windowVertex(1e7f, 20)));
  TriangleSetup setup;
  CHECK_FALSE(setupQuad(a, windowVertex(20, 18), b, c, settingsFor({0, 0, kWidth, kHeight}, true), setup));
  CHECK_FALSE(setupQuad(a, b, c, d, settingsFor({40, 40, kWidth, kHeight}, true), setup));  // outside the bounds
  REQUIRE(setupQuad(d, c, b, a, settingsFor({0, 0, kWidth, kHeight}, true), setup));
  CHECK(setup.edgeCount == 4);
  CHECK(setup.box.x0 == 10);
  CHECK(setup.box.x1 == 30);
  CHECK(setup.box.y0 == 10);
  CHECK(setup.box.y1 == 20);
}

// With one thread or two, every quadrilateral is binned and drawn tile by tile; a corner
// snapped straight is drawn as the two triangles.
void checkQuadsDrawnTileByTile(int threads) {
  CAPTURE(threads);
  Framebuffer framebuffer(kWidth, kHeight);
  RandomQuads random(77);
  const PixelRect window{0, 0, kWidth, kHeight};
  const PixelRect scissor{37, 23, 171, 131};
  int compared = 0;
  for (int n = 0; n < 600; ++n) {
    const bool perspectiveCorrect = random.pick(2) == 0;
    Quad q = random.next(perspectiveCorrect);
    if (n % 50 == 0) q.v[1] = q.v[2];  // not convex: the triangles (v0, v1, v2) empty, (v2, v3, v0)
    const TriangleSettings s = settingsFor(random.pick(3) == 0 ? scissor : window, perspectiveCorrect);
    RecordingSink tiledSink;
    {
      TiledRasterizer tiled(framebuffer, threads);
      tiled.quad(q.v[0], q.v[1], q.v[2], q.v[3], s, tiledSink);
      tiled.finish();
    }
    std::vector<Fragment> whole;
    if (quadIsConvex(q.v[0], q.v[1], q.v[2], q.v[3])) {
      whole = drawnQuad(q, s);
    } else {
      whole = drawnTriangle(q.v[0], q.v[1], q.v[2], s);
      const std::vector<Fragment> second = drawnTriangle(q.v[2], q.v[3], q.v[0], s);
      whole.insert(whole.end(), second.begin(), second.end());
    }
    const std::vector<Fragment> expected = sortedByPixel(whole), got = sortedByPixel(tiledSink.fragments);
    CAPTURE(n);
    REQUIRE(expected.size() == got.size());
    for (size_t i = 0; i < got.size(); ++i) REQUIRE(sameBits(expected[i], got[i]));
    compared += static_cast<int>(got.size());
  }
  CHECK(compared > 50000);
}

TEST_CASE("quad: tile by tile, the fragments of the quadrilateral set up whole") {
  checkQuadsDrawnTileByTile(1);
  checkQuadsDrawnTileByTile(2);
}
