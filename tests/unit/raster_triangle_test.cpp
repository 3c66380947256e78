// Triangle rasterization: the fill rule (no double writes, no gaps), orientation independence,
// block batching, depth and perspective-correct attributes.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include "glass/raster/depth_value.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/triangle.h"
#include "hidden_block_odds.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::RecordingSink;
using glass::raster::test::rect;
using glass::raster::test::windowVertex;

namespace {

TriangleSettings settingsFor(PixelRect bounds, int varyingCount = 0) {
  TriangleSettings s;
  s.bounds = bounds;
  s.varyingCount = varyingCount;
  return s;
}

void drawTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                  const TriangleSettings& settings, RecordingSink& sink) {
  TriangleSetup setup;
  if (setupTriangle(a, b, c, settings, setup)) rasterizeTriangle(setup, sink);
}

// A random coordinate on the 1/256 grid, so that tests can reason about it exactly.
float gridCoordinate(std::mt19937& rng, float lo, float hi) {
  std::uniform_real_distribution<double> d(lo, hi);
  return static_cast<float>(std::round(d(rng) * 256.0) / 256.0);
}

}  // namespace

TEST_CASE("triangle: a fan of thin triangles covers every pixel of its square exactly once") {
  // The outer vertices walk around the boundary of the square [x0, x1] x [y0, y1]; the fan's
  // union is the square, so every pixel centre inside it must be written exactly once, whatever
  // the orientation each triangle is given in.
  std::mt19937 rng(12345);
  const double x0 = 3.3, x1 = 60.7, y0 = 5.1, y1 = 58.9;
  std::vector<WindowVertex> ring;
  auto addSide = [&](double ax, double ay, double bx, double by, int count) {
    std::vector<double> ts{0.0};
    for (int i = 0; i < count; ++i) ts.push_back(std::uniform_real_distribution<double>(0, 1)(rng));
    std::sort(ts.begin(), ts.end());
    for (double t : ts)
      ring.push_back(windowVertex(float(ax + t * (bx - ax)), float(ay + t * (by - ay))));
  };
  addSide(x0, y0, x1, y0, 60);
  addSide(x1, y0, x1, y1, 60);
  addSide(x1, y1, x0, y1, 60);
  addSide(x0, y1, x0, y0, 60);
  // Vertices on a vertical or horizontal side are exact in float only if the side's coordinate is;
  // force them onto the side.
  for (WindowVertex& v : ring) {
    if (std::fabs(v.x - float(x0)) < 1e-3f) v.x = float(x0);
    if (std::fabs(v.x - float(x1)) < 1e-3f) v.x = float(x1);
    if (std::fabs(v.y - float(y0)) < 1e-3f) v.y = float(y0);
    if (std::fabs(v.y - float(y1)) < 1e-3f) v.y = float(y1);
  }
  const WindowVertex centre = windowVertex(31.5f, 31.5f);  // exactly on a pixel centre
  RecordingSink sink;
  const TriangleSettings settings = settingsFor(rect(0, 0, 64, 64));
  int drawn = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const WindowVertex& a = ring[i];
    const WindowVertex& b = ring[(i + 1) % ring.size()];
    if (a.x == b.x && a.y == b.y) continue;
    if (i % 2) drawTriangle(centre, a, b, settings, sink);
    else drawTriangle(b, a, centre, settings, sink);
    ++drawn;
  }
  CHECK(drawn > 200);
  // The square's sides are not on pixel centres after snapping to 1/256 (x0 = 3.3 snaps to
  // 845/256, whose centre test is unambiguous), so inside and outside are clear-cut.
  const double sx0 = std::nearbyint(x0 * 256) / 256, sx1 = std::nearbyint(x1 * 256) / 256;
  const double sy0 = std::nearbyint(y0 * 256) / 256, sy1 = std::nearbyint(y1 * 256) / 256;
  int wrong = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      const bool inside = cx > sx0 && cx < sx1 && cy > sy0 && cy < sy1;
      if (sink.writesAt(x, y) != (inside ? 1 : 0)) ++wrong;
    }
  CHECK(wrong == 0);
}

TEST_CASE("triangle: a fan around a point inside a circle has no double writes and no gaps") {
  // Thin triangles around a centre that is not on the pixel grid; the union is a convex polygon
  // (the ring), inside which every pixel must be written once.
  const int n = 500;
  const double cx = 40.37, cy = 39.81, r = 33.0;
  std::vector<WindowVertex> ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    ring.push_back(windowVertex(float(cx + r * std::cos(a)), float(cy + r * std::sin(a))));
  }
  RecordingSink sink;
  const TriangleSettings settings = settingsFor(rect(0, 0, 80, 80));
  const WindowVertex centre = windowVertex(float(cx), float(cy));
  for (int i = 0; i < n; ++i) drawTriangle(centre, ring[i], ring[(i + 1) % n], settings, sink);
  int doubles = 0, gaps = 0;
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 80; ++x) {
      const int w = sink.writesAt(x, y);
      if (w > 1) ++doubles;
      // Well inside the ring polygon (its inscribed radius is r cos(pi / n)).
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      if (d < r * std::cos(std::numbers::pi / n) - 0.01 && w != 1) ++gaps;
    }
  CHECK(doubles == 0);
  CHECK(gaps == 0);
}

TEST_CASE("triangle: a jittered mesh with random vertex orders writes each pixel once") {
  // A grid mesh with jittered inner vertices and randomly chosen diagonals; every triangle is
  // given in a random one of its six vertex orders (both orientations).
  std::mt19937 rng(777);
  const int cells = 9;
  const float lo = 2.2f, hi = 61.8f;
  WindowVertex grid[cells + 1][cells + 1];
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      float x = lo + (hi - lo) * i / cells, y = lo + (hi - lo) * j / cells;
      if (i > 0 && i < cells) x = gridCoordinate(rng, x - 2.5f, x + 2.5f);
      if (j > 0 && j < cells) y = gridCoordinate(rng, y - 2.5f, y + 2.5f);
      grid[j][i] = windowVertex(x, y);
    }
  RecordingSink sink;
  const TriangleSettings settings = settingsFor(rect(0, 0, 64, 64));
  auto drawAnyOrder = [&](WindowVertex a, WindowVertex b, WindowVertex c) {
    WindowVertex v[3] = {a, b, c};
    std::shuffle(v, v + 3, rng);
    drawTriangle(v[0], v[1], v[2], settings, sink);
  };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const WindowVertex &p00 = grid[j][i], &p10 = grid[j][i + 1], &p01 = grid[j + 1][i],
                         &p11 = grid[j + 1][i + 1];
      if (rng() % 2) {
        drawAnyOrder(p00, p10, p11);
        drawAnyOrder(p00, p11, p01);
      } else {
        drawAnyOrder(p00, p10, p01);
        drawAnyOrder(p10, p11, p01);
      }
    }
  const double slo = std::nearbyint(lo * 256.0) / 256.0, shi = std::nearbyint(hi * 256.0) / 256.0;
  int wrong = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool inside = x + 0.5 > slo && x + 0.5 < shi && y + 0.5 > slo && y + 0.5 < shi;
      if (sink.writesAt(x, y) != (inside ? 1 : 0)) ++wrong;
    }
  CHECK(wrong == 0);
}

TEST_CASE("triangle: two triangles sharing an edge, in every vertex order, never overlap or gap") {
  std::mt19937 rng(99);
  const TriangleSettings settings = settingsFor(rect(0, 0, 32, 32));
  for (int trial = 0; trial < 300; ++trial) {
    // Shared edge p-q, with r and s on opposite sides; half the trials put vertices on pixel
    // centres or pixel corners, where the fill rule decides.
    auto coord = [&](float lo, float hi) {
      const float v = gridCoordinate(rng, lo, hi);
      return (trial % 2) ? std::round(v * 2.0f) / 2.0f : v;
    };
    const WindowVertex p = windowVertex(coord(2, 30), coord(2, 30));
    const WindowVertex q = windowVertex(coord(2, 30), coord(2, 30));
    const WindowVertex r = windowVertex(coord(0, 32), coord(0, 32));
    const double side = windowSignedArea(p, q, r);
    if (side == 0) continue;
    // s: r reflected through the edge's midpoint, so it lies on the other side.
    const WindowVertex s = windowVertex(p.x + q.x - r.x, p.y + q.y - r.y);
    const WindowVertex t1[3] = {p, q, r}, t2[3] = {p, q, s};
    for (int order = 0; order < 6; ++order) {
      static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
      const int* o = perms[order];
      RecordingSink both, first, second;
      drawTriangle(t1[o[0]], t1[o[1]], t1[o[2]], settings, both);
      drawTriangle(t2[o[2]], t2[o[0]], t2[o[1]], settings, both);
      drawTriangle(t1[o[0]], t1[o[1]], t1[o[2]], settings, first);
      drawTriangle(t2[o[2]], t2[o[0]], t2[o[1]], settings, second);
      for (const auto& [pixel, count] : both.writes) REQUIRE(count == 1);
      // The parallelogram p r q s: every centre strictly inside it is written.
      const double px = p.x, py = p.y, qx = q.x, qy = q.y, rx = r.x, ry = r.y, sx = s.x, sy = s.y;
      auto cross = [](double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
      };
      const double sign = side > 0 ? 1.0 : -1.0;
      for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
          const double cx = x + 0.5, cy = y + 0.5;
          const bool inside = sign * cross(qx, qy, rx, ry, cx, cy) > 0 &&
                              sign * cross(rx, ry, px, py, cx, cy) > 0 &&
                              sign * cross(px, py, sx, sy, cx, cy) > 0 &&
                              sign * cross(sx, sy, qx, qy, cx, cy) > 0;
          if (inside) REQUIRE(both.writesAt(x, y) == 1);
        }
      CHECK(first.writes.size() + second.writes.size() == both.writes.size());
    }
  }
}

TEST_CASE("triangle: fill rule on edges through pixel centres (bottom and left edges own them)") {
  // The square [2.5, 5.5]^2 has all four sides on pixel centres. The left and bottom sides own
  // their centres, the right and top sides do not: columns 2-4 and rows 2-4.
  RecordingSink sink;
  const TriangleSettings settings = settingsFor(rect(0, 0, 16, 16));
  drawTriangle(windowVertex(2.5f, 2.5f), windowVertex(5.5f, 2.5f), windowVertex(5.5f, 5.5f), settings, sink);
  drawTriangle(windowVertex(2.5f, 2.5f), windowVertex(5.5f, 5.5f), windowVertex(2.5f, 5.5f), settings, sink);
  CHECK(sink.writes.size() == 9);
  for (int y = 2; y <= 4; ++y)
    for (int x = 2; x <= 4; ++x) CHECK(sink.writesAt(x, y) == 1);

  // A sloped edge through centres: the triangle (0.5,0.5) (8.5,0.5) (8.5,8.5); its hypotenuse
  // y = x is a left edge (interior to its right), so centres on it are written.
  sink.clear();
  drawTriangle(windowVertex(0.5f, 0.5f), windowVertex(8.5f, 0.5f), windowVertex(8.5f, 8.5f), settings, sink);
  for (int i = 0; i < 8; ++i) CHECK(sink.writesAt(i, i) == 1);
  CHECK(sink.writesAt(8, 8) == 0);  // on the right edge x = 8.5
  CHECK(sink.writesAt(3, 0) == 1);  // on the bottom edge y = 0.5
  // Its mirror image (0.5,0.5) (0.5,8.5) (8.5,8.5): the diagonal is now a right edge.
  sink.clear();
  drawTriangle(windowVertex(0.5f, 0.5f), windowVertex(8.5f, 8.5f), windowVertex(0.5f, 8.5f), settings, sink);
  for (int i = 0; i < 8; ++i) CHECK(sink.writesAt(i, i) == 0);
  CHECK(sink.writesAt(0, 3) == 1);  // left edge x = 0.5
  CHECK(sink.writesAt(3, 8) == 0);  // top edge y = 8.5
}

TEST_CASE("triangle: both orientations cover the same pixels; degenerate triangles draw nothing") {
  std::mt19937 rng(5);
  const TriangleSettings settings = settingsFor(rect(0, 0, 40, 40));
  for (int trial = 0; trial < 200; ++trial) {
    WindowVertex v[3];
    for (auto& p : v) p = windowVertex(gridCoordinate(rng, -5, 45), gridCoordinate(rng, -5, 45));
    RecordingSink ccw, cw;
    drawTriangle(v[0], v[1], v[2], settings, ccw);
    drawTriangle(v[0], v[2], v[1], settings, cw);
    CHECK(ccw.writes == cw.writes);
  }
  RecordingSink sink;
  TriangleSetup setup;
  CHECK_FALSE(setupTriangle(windowVertex(1, 1), windowVertex(5, 5), windowVertex(9, 9), settings, setup));
  CHECK_FALSE(setupTriangle(windowVertex(50, 50), windowVertex(60, 50), windowVertex(50, 60), settings, setup));
  CHECK_FALSE(setupTriangle(windowVertex(NAN, 1), windowVertex(5, 5), windowVertex(9, 1), settings, setup));
}

TEST_CASE("triangle: one batch per 8x8 block from the box's corner, all inside the bounds") {
  RecordingSink sink;
  const TriangleSettings settings = settingsFor(rect(3, 4, 29, 27));
  TriangleSetup setup;
  REQUIRE(setupTriangle(windowVertex(-10, -10), windowVertex(80, -9), windowVertex(-9, 80), settings, setup));
  CHECK(setup.box.x0 == 3);
  CHECK(setup.box.y1 == 27);
  rasterizeTriangle(setup, sink);
  // The triangle covers the whole bounds, so every pixel is written once.
  CHECK(sink.writes.size() == size_t(26 * 23));
  for (const auto& [pixel, count] : sink.writes) {
    CHECK(count == 1);
    CHECK(pixel.first >= 3);
    CHECK(pixel.first < 29);
    CHECK(pixel.second >= 4);
    CHECK(pixel.second < 27);
  }
  // Blocks start at the box's lower-left corner, moved left to an even column (x 2, 10, 18, 26;
  // y 4, 12, 20): each batch lies in one of them and holds at most 64 fragments.
  size_t index = 0;
  for (int size : sink.batchSizes) {
    CHECK(size > 0);
    CHECK(size <= 64);
    const int bx = (sink.fragments[index].x - 2) / 8, by = (sink.fragments[index].y - 4) / 8;
    for (int i = 0; i < size; ++i) {
      CHECK((sink.fragments[index + i].x - 2) / 8 == bx);
      CHECK((sink.fragments[index + i].y - 4) / 8 == by);
    }
    index += size;
  }
  CHECK(sink.batches == 12);  // 4 block columns, 3 block rows
}

TEST_CASE("triangle: a pixel's fragment does not depend on the bounds, nor on where blocks start") {
  // The walk starts its blocks at the corner of the triangle's box within the bounds, so a tile
  // of the tiled rasterizer, or any scissor, walks other blocks than the whole window does. The
  // fragments of the pixels both cover must be the same bits: coverage, depth and varyings are
  // evaluated from the pixel's own position.
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 40; ++trial) {
    WindowVertex v[3];
    for (WindowVertex& w : v) {
      w = windowVertex(gridCoordinate(rng, -8, 72), gridCoordinate(rng, -8, 72),
                       static_cast<float>(std::uniform_real_distribution<double>(0, 1)(rng)),
                       static_cast<float>(std::uniform_real_distribution<double>(0.1, 2)(rng)));
      for (int k = 0; k < 4; ++k)
        w.varyings[k] = static_cast<float>(std::uniform_real_distribution<double>(-1, 1)(rng));
    }
    RecordingSink whole;
    drawTriangle(v[0], v[1], v[2], settingsFor(rect(0, 0, 64, 64), 4), whole);
    std::map<std::pair<int, int>, Fragment> byPixel;
    for (const Fragment& f : whole.fragments) byPixel[{f.x, f.y}] = f;
    std::uniform_int_distribution<int> corner(0, 40), side(1, 24);
    for (int cut = 0; cut < 8; ++cut) {
      const int x0 = corner(rng), y0 = corner(rng);
      const PixelRect bounds = rect(x0, y0, x0 + side(rng), y0 + side(rng));
      RecordingSink part;
      drawTriangle(v[0], v[1], v[2], settingsFor(bounds, 4), part);
      size_t inside = 0;
      for (const auto& [pixel, count] : whole.writes)
        inside += pixel.first >= bounds.x0 && pixel.first < bounds.x1 && pixel.second >= bounds.y0 &&
                  pixel.second < bounds.y1;
      CHECK(part.fragments.size() == inside);
      for (const Fragment& f : part.fragments) {
        const auto found = byPixel.find({f.x, f.y});
        REQUIRE(found != byPixel.end());
        CHECK(found->second.depth == f.depth);
        for (int k = 0; k < 4; ++k) CHECK(std::bit_cast<uint32_t>(found->second.varyings[k]) == std::bit_cast<uint32_t>(f.varyings[k]));
      }
    }
  }
}

TEST_CASE("triangle: depth is the plane through the vertices, biased, clamped and rounded") {
  const TriangleSettings plain = settingsFor(rect(0, 0, 32, 32));
  const WindowVertex a = windowVertex(0, 0, 0.1f), b = windowVertex(32, 0, 0.9f), c = windowVertex(0, 32, 0.5f);
  RecordingSink sink;
  drawTriangle(a, b, c, plain, sink);
  REQUIRE(!sink.fragments.empty());
  for (const Fragment& f : sink.fragments) {
    const double x = f.x + 0.5, y = f.y + 0.5;
    const double z = double(0.1f) + (double(0.9f) - double(0.1f)) * x / 32 + (double(0.5f) - double(0.1f)) * y / 32;
    CHECK(f.depth == static_cast<uint32_t>(std::floor(z * kDepthMax + 0.5)));
  }
  TriangleSettings biased = plain;
  biased.depthBias = 0.25;
  RecordingSink biasedSink;
  drawTriangle(a, b, c, biased, biasedSink);
  REQUIRE(biasedSink.fragments.size() == sink.fragments.size());
  for (size_t i = 0; i < sink.fragments.size(); ++i) {
    const double z = double(sink.fragments[i].depth) / kDepthMax + 0.25;
    const uint32_t expected = z >= 1.0 ? kDepthMax : static_cast<uint32_t>(std::floor(z * kDepthMax + 0.5));
    CHECK(std::abs(int64_t(biasedSink.fragments[i].depth) - int64_t(expected)) <= 1);
  }
  // Depths at 0 and 1 exactly, and beyond (clamped).
  RecordingSink flat;
  drawTriangle(windowVertex(0, 0, 1.0f), windowVertex(8, 0, 1.0f), windowVertex(0, 8, 1.0f), plain, flat);
  drawTriangle(windowVertex(10, 0, 0.0f), windowVertex(18, 0, 0.0f), windowVertex(10, 8, 0.0f), plain, flat);
  TriangleSettings pushed = plain;
  pushed.depthBias = 2.0;
  drawTriangle(windowVertex(20, 0, 0.5f), windowVertex(28, 0, 0.5f), windowVertex(20, 8, 0.5f), pushed, flat);
  for (const Fragment& f : flat.fragments) CHECK(f.depth == (f.x < 10 || f.x >= 20 ? kDepthMax : 0u));
}

TEST_CASE("triangle: without a reader of depth, the same fragments with depth 0") {
  // TriangleSettings::depthUsed false (the depth test is off): the walk skips the depth plane,
  // and every fragment is the one it would be otherwise but for its depth, which is 0.
  std::mt19937 rng(61206);
  std::uniform_real_distribution<double> unit(0, 1), w(0.1, 2);
  for (int trial = 0; trial < 60; ++trial) {
    WindowVertex v[3];
    for (WindowVertex& vertex : v) {
      vertex = windowVertex(gridCoordinate(rng, -8, 72), gridCoordinate(rng, -8, 72), static_cast<float>(unit(rng)),
                            static_cast<float>(w(rng)));
      for (int k = 0; k < 4; ++k) vertex.varyings[k] = static_cast<float>(unit(rng));
    }
    TriangleSettings settings = settingsFor(rect(0, 0, 64, 64), 4);
    RecordingSink withDepth, without;
    drawTriangle(v[0], v[1], v[2], settings, withDepth);
    settings.depthUsed = false;
    drawTriangle(v[0], v[1], v[2], settings, without);
    REQUIRE(without.fragments.size() == withDepth.fragments.size());
    for (size_t i = 0; i < without.fragments.size(); ++i) {
      const Fragment &a = withDepth.fragments[i], &b = without.fragments[i];
      CHECK((a.x == b.x && a.y == b.y));
      CHECK(b.depth == 0u);
      for (int k = 0; k < 4; ++k) CHECK(std::bit_cast<uint32_t>(a.varyings[k]) == std::bit_cast<uint32_t>(b.varyings[k]));
    }
  }
}

TEST_CASE("triangle: varyings are perspective-correct and constants stay exact") {
  // Vertices with different w; the value at a pixel is sum(l_i a_i / w_i) / sum(l_i / w_i) with
  // l_i the screen-space barycentric coordinates of the pixel centre.
  const WindowVertex base[3] = {windowVertex(1.25f, 2.5f, 0.5f, 1.0f / 1.0f),
                                windowVertex(60.75f, 7.0f, 0.5f, 1.0f / 8.0f),
                                windowVertex(20.0f, 61.5f, 0.5f, 1.0f / 3.0f)};
  WindowVertex v[3] = {base[0], base[1], base[2]};
  const float values[3][3] = {{0.0f, 1.0f, 0.3f}, {1.0f, 0.0f, 0.3f}, {0.25f, 0.5f, 0.3f}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) v[i].varyings[k] = values[i][k];
  RecordingSink sink;
  drawTriangle(v[0], v[1], v[2], settingsFor(rect(0, 0, 64, 64), 3), sink);
  REQUIRE(sink.fragments.size() > 500);
  const double area = windowSignedArea(v[0], v[1], v[2]);
  double worst = 0;
  for (const Fragment& f : sink.fragments) {
    const double x = f.x + 0.5, y = f.y + 0.5;
    double l[3];
    for (int i = 0; i < 3; ++i) {
      const WindowVertex& p = v[(i + 1) % 3];
      const WindowVertex& q = v[(i + 2) % 3];
      l[i] = ((double(q.x) - p.x) * (y - p.y) - (x - p.x) * (double(q.y) - p.y)) / area;
    }
    for (int k = 0; k < 3; ++k) {
      double num = 0, den = 0;
      for (int i = 0; i < 3; ++i) {
        num += l[i] * values[i][k] * v[i].invW;
        den += l[i] * v[i].invW;
      }
      worst = std::max(worst, std::fabs(num / den - f.varyings[k]));
    }
    CHECK(f.varyings[2] == 0.3f);  // the same at every vertex: exact everywhere
  }
  CHECK(worst < 1e-6);

  // Not perspective-correct: affine in screen space.
  TriangleSettings affine = settingsFor(rect(0, 0, 64, 64), 3);
  affine.perspectiveCorrect = false;
  RecordingSink affineSink;
  drawTriangle(v[0], v[1], v[2], affine, affineSink);
  worst = 0;
  for (const Fragment& f : affineSink.fragments) {
    const double x = f.x + 0.5, y = f.y + 0.5;
    double l[3];
    for (int i = 0; i < 3; ++i) {
      const WindowVertex& p = v[(i + 1) % 3];
      const WindowVertex& q = v[(i + 2) % 3];
      l[i] = ((double(q.x) - p.x) * (y - p.y) - (x - p.x) * (double(q.y) - p.y)) / area;
    }
    double expected = 0;
    for (int i = 0; i < 3; ++i) expected += l[i] * values[i][0];
    worst = std::max(worst, std::fabs(expected - f.varyings[0]));
  }
  CHECK(worst < 1e-6);
}

TEST_CASE("triangle: attribute derivatives match finite differences of the exact value") {
  WindowVertex v[3] = {windowVertex(0, 0, 0.5f, 1.0f), windowVertex(64, 0, 0.5f, 0.25f),
                       windowVertex(0, 64, 0.5f, 0.5f)};
  v[0].varyings[0] = 0;
  v[1].varyings[0] = 10;
  v[2].varyings[0] = 4;
  TriangleSetup setup;
  REQUIRE(setupTriangle(v[0], v[1], v[2], settingsFor(rect(0, 0, 64, 64), 1), setup));
  auto value = [&](double x, double y) {
    const AttributePlanes& p = setup.planes;
    return (p.a0[0] + p.dx[0] * x + p.dy[0] * y) / (p.invW0 + p.invWdx * x + p.invWdy * y);
  };
  double ddx, ddy;
  setup.planes.derivatives(0, 10, 20, ddx, ddy);
  const double h = 1e-4;
  CHECK(ddx == doctest::Approx((value(10.5 + h, 20.5) - value(10.5 - h, 20.5)) / (2 * h)).epsilon(1e-6));
  CHECK(ddy == doctest::Approx((value(10.5, 20.5 + h) - value(10.5, 20.5 - h)) / (2 * h)).epsilon(1e-6));
  CHECK(ddx > 0);
}

TEST_CASE("triangle: the early depth test and its hidden blocks drop exactly the fragments that fail") {
  // Every ordering and the other comparisons, small triangles (one or a few blocks, tested for
  // being hidden when the odds say so) and large ones (their blocks' stored ranges looked at
  // whole), over stored depths made of constant blocks, planes and noise, with and without the
  // thread's private rectangle: the fragments must be those of the walk without the early test
  // that pass the comparison against the stored depth, pixel by pixel.
  constexpr int kWidth = 96, kHeight = 80;
  Framebuffer fb(kWidth, kHeight);
  std::mt19937 rng(2026);
  const DepthCompare compares[] = {DepthCompare::Less,         DepthCompare::LessEqual, DepthCompare::Greater,
                                   DepthCompare::GreaterEqual, DepthCompare::Equal,     DepthCompare::NotEqual};
  long mismatches = 0, dropped = 0, kept = 0;
  int hiddenFound = 0;
  for (int round = 0; round < 240; ++round) {
    // The stored depths: 8 x 8 patches of one value each, a plane, or noise.
    std::uniform_int_distribution<uint32_t> anyDepth(0, kDepthMax);
    const int kind = round % 3;
    const uint32_t base = anyDepth(rng);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        uint32_t value = anyDepth(rng);
        if (kind == 0) value = (base + 2654435761u * static_cast<uint32_t>((x / 8) * 31 + y / 8)) % (kDepthMax + 1);
        if (kind == 1) value = std::min<uint32_t>(kDepthMax, base / 2 + static_cast<uint32_t>(x * 40000 + y * 25000));
        *fb.depthAt(x, y) = value;
      }
    const DepthCompare compare = compares[round % 6];
    const bool large = round % 4 == 0;
    const float size = large ? 90.0f : 14.0f;
    const float x0 = gridCoordinate(rng, -4.0f, kWidth - (large ? 20.0f : 8.0f));
    const float y0 = gridCoordinate(rng, -4.0f, kHeight - (large ? 20.0f : 8.0f));
    std::uniform_real_distribution<float> depth(-0.1f, 1.1f);
    WindowVertex v[3];
    for (WindowVertex& corner : v)
      corner = windowVertex(x0 + gridCoordinate(rng, 0.0f, size), y0 + gridCoordinate(rng, 0.0f, size), depth(rng));
    TriangleSettings plain = settingsFor(rect(0, 0, kWidth, kHeight));
    RecordingSink all;
    drawTriangle(v[0], v[1], v[2], plain, all);
    std::vector<std::tuple<int, int, uint32_t>> expected;
    for (const Fragment& f : all.fragments)
      if (passesDepthCompare(compare, f.depth, *fb.depthAt(f.x, f.y))) expected.emplace_back(f.x, f.y, f.depth);
    dropped += static_cast<long>(all.fragments.size() - expected.size());
    kept += static_cast<long>(expected.size());
    std::sort(expected.begin(), expected.end());
    for (int variant = 0; variant < 3; ++variant) {
      TriangleSettings early = plain;
      early.earlyDepth = {&fb, compare};
      TriangleSetup setup;
      if (!setupTriangle(v[0], v[1], v[2], early, setup)) continue;
      // Always testing small triangles' blocks; testing when the odds say so; no private
      // rectangle (small triangles' blocks are then never tested).
      HiddenBlockOdds odds;
      if (variant == 0) odds.score = 64;
      if (variant < 2) {
        setup.privateRect = rect(0, 0, kWidth, kHeight);
        setup.hiddenBlockOdds = &odds;
      }
      RecordingSink sink;
      rasterizeTriangle(setup, sink);
      std::vector<std::tuple<int, int, uint32_t>> got;
      for (const Fragment& f : sink.fragments) got.emplace_back(f.x, f.y, f.depth);
      std::sort(got.begin(), got.end());
      if (got != expected) ++mismatches;
      if (variant == 0 && odds.score > 64 - 4) ++hiddenFound;
    }
  }
  CHECK(mismatches == 0);
  CHECK(dropped > 1000);  // the comparisons drop fragments, and keep others
  CHECK(kept > 1000);
  CHECK(hiddenFound > 5);  // small triangles' blocks were found hidden
}
