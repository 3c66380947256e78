// GL line segments (rasterizeLine) and points (rasterizePoint).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "glass/raster/line.h"
#include "glass/raster/teaching_lines.h"
#include "raster_test_support.h"

using namespace glass::raster;
using glass::raster::test::rect;
using glass::raster::test::RecordingSink;
using glass::raster::test::windowVertex;

namespace {

LineSettings lineSettings(PixelRect bounds = rect(0, 0, 64, 64)) {
  LineSettings s;
  s.bounds = bounds;
  return s;
}

std::vector<GridPixel> drawnInOrder(const WindowVertex& a, const WindowVertex& b, const LineSettings& s) {
  RecordingSink sink;
  rasterizeLine(a, b, s, sink);
  std::vector<GridPixel> pixels;
  for (const Fragment& f : sink.fragments) pixels.push_back({f.x, f.y});
  return pixels;
}

}  // namespace

TEST_CASE("GL lines: width 1 between pixel centres is the diamond-exit rule but for exact ties") {
  // Between pixel centres glass's rule and the exact rule choose the same pixels, except where the
  // line passes exactly halfway between two centres: there glass follows Mesa, whose choice
  // depends on the rounding of a corner moved along the segment (line_quad.cpp, rule 4). Check
  // every segment of a 16x16 grid: the pixel sets may differ only in such tie columns (rows), and
  // then by one pixel across the major axis.
  int ties = 0;
  for (int x0 = 0; x0 < 16; ++x0)
    for (int y0 = 0; y0 < 16; ++y0)
      for (int x1 = 0; x1 < 16; ++x1)
        for (int y1 = 0; y1 < 16; ++y1) {
          const auto drawn = drawnInOrder(windowVertex(x0 + 0.5f, y0 + 0.5f), windowVertex(x1 + 0.5f, y1 + 0.5f), lineSettings());
          const auto exact = lineDiamondExit(x0, y0, x1, y1);
          REQUIRE(drawn.size() == exact.size());
          const int n = std::abs(x1 - x0), m = std::abs(y1 - y0);
          const bool xMajor = n >= m;
          const int major = xMajor ? n : m, minor = xMajor ? m : n;
          for (size_t i = 0; i < drawn.size(); ++i) {
            if (drawn[i] == exact[i]) continue;
            // Step i is a tie when i * minor / major is an odd multiple of 1/2.
            const bool tie = (2 * int(i) * minor) % (2 * major) == major;
            CHECK(tie);
            CHECK(std::abs(drawn[i].x - exact[i].x) + std::abs(drawn[i].y - exact[i].y) == 1);
            ++ties;
          }
        }
  // On this grid glass draws exactly Mesa's pixels (all 65536 segments compared with Mesa 22.3's
  // llvmpipe); Mesa departs from the exact rule at 3808 of the grid's 34496 tie steps.
  CHECK(ties == 3808);
}

TEST_CASE("GL lines: endpoints on pixel centres and on pixel borders") {
  // Centre to centre: the first pixel is drawn, the last is not.
  auto row = [](int from, int to, int y) {
    std::vector<GridPixel> v;
    for (int x = from; from <= to ? x <= to : x >= to; x += from <= to ? 1 : -1) v.push_back({x, y});
    return v;
  };
  CHECK(drawnInOrder(windowVertex(2.5f, 3.5f), windowVertex(7.5f, 3.5f), lineSettings()) == row(2, 6, 3));
  CHECK(drawnInOrder(windowVertex(7.5f, 3.5f), windowVertex(2.5f, 3.5f), lineSettings()) == row(7, 3, 3));
  // Endpoints on the vertical pixel borders x = 3 and x = 36, along a row of centres. The exact
  // rule would draw columns 2..34 (its perturbation puts x = 3 in pixel 2); glass, like Mesa,
  // puts an endpoint on a border in the pixel to its right and draws 3..35.
  CHECK(drawnInOrder(windowVertex(3.0f, 58.5f), windowVertex(36.0f, 58.5f), lineSettings()) == row(3, 35, 58));
  // A horizontal segment exactly on the border between two rows takes the lower row.
  CHECK(drawnInOrder(windowVertex(2.5f, 10.0f), windowVertex(6.5f, 10.0f), lineSettings()) == row(2, 5, 9));
  // A vertical segment exactly on the border between two columns takes the left column.
  const auto vertical = drawnInOrder(windowVertex(16.0f, 39.5f), windowVertex(16.0f, 43.5f), lineSettings());
  REQUIRE(vertical.size() == 4);
  for (const GridPixel& p : vertical) CHECK(p.x == 15);
  // Zero length: nothing.
  CHECK(drawnInOrder(windowVertex(5.25f, 5.25f), windowVertex(5.25f, 5.25f), lineSettings()).empty());
}

// The cases below are pictures Mesa (llvmpipe, 22.3) draws in a 256 x 256 framebuffer; each would
// come out differently without the step of Mesa's construction it names (line_quad.cpp).
TEST_CASE("GL lines: ties follow the direction of travel, as Mesa's moved and rounded corner decides") {
  LineSettings s = lineSettings(rect(0, 0, 256, 256));
  s.framebufferHeight = 256;
  // At x = 107.5 the segment passes through y = 177.0, halfway between rows 176 and 177, and so at
  // columns 125, 143, 161 and 179. Drawn from the left, the end lies on a column of centres, so
  // Mesa moves it half a pixel back (rule 4) and rounds the moved corner 0.11/256 pixel up the
  // screen, which tilts the band up: the upper row at every tie. Drawn from the right, both ends
  // are moved (rule 3) and both corners round 0.11/256 pixel down the screen: the lower row.
  const int ties[5][2] = {{107, 177}, {125, 160}, {143, 143}, {161, 126}, {179, 109}};
  auto rowAt = [](const std::vector<GridPixel>& pixels, int x) {
    for (const GridPixel& p : pixels)
      if (p.x == x) return p.y;
    return -1;
  };
  const auto forwards = drawnInOrder(windowVertex(98.5f, 185.5f), windowVertex(188.5f, 100.5f), s);
  const auto backwards = drawnInOrder(windowVertex(188.5f, 100.5f), windowVertex(98.5f, 185.5f), s);
  for (const auto& [x, y] : ties) {
    CHECK(rowAt(forwards, x) == y);
    CHECK(rowAt(backwards, x) == y - 1);
  }
  // A y-major segment travelling up with its end on a row of centres: the same move, in x.
  const auto up = drawnInOrder(windowVertex(47.5f, 114.5f), windowVertex(34.5f, 190.5f), s);
  CHECK(std::count(up.begin(), up.end(), GridPixel{41, 152}) == 1);
}

TEST_CASE("GL lines: Mesa's rounding to 1/256 pixel, in rows numbered from the top") {
  LineSettings s = lineSettings(rect(0, 0, 256, 256));
  s.framebufferHeight = 256;
  // The end corner lands exactly halfway between two 1/256 steps; rounded half away from zero (as
  // Mesa does, not to even) the band takes pixel (15, 15).
  CHECK(drawnInOrder(windowVertex(15.5f, 16.0f), windowVertex(16.5f, 16.75390625f), s) ==
        std::vector<GridPixel>{{15, 15}});
  // The start corner, moved half a pixel back, is y = 143.2558... in Mesa's downward rows, where a
  // float keeps 16 bits of fraction: the rounding makes it exactly halfway between two 1/256 steps
  // and it rounds up, which puts the first pixel in row 112. Numbered from y = 0 the same corner
  // keeps more bits, rounds down, and the first pixel would be in row 113.
  const auto fromTop = drawnInOrder(windowVertex(97.5f, 113.0f), windowVertex(172.25f, 151.25f), s);
  REQUIRE(!fromTop.empty());
  CHECK(fromTop.front() == GridPixel{97, 112});
  s.framebufferHeight = 0;
  CHECK(drawnInOrder(windowVertex(97.5f, 113.0f), windowVertex(172.25f, 151.25f), s).front() ==
        GridPixel{97, 113});
}

TEST_CASE("GL lines: a segment shorter than a pixel whose moved ends cross draws nothing") {
  // Both ends are moved half a pixel along the segment (rule 3), past each other: Mesa's edge
  // functions then enclose no pixel centre.
  LineSettings s = lineSettings(rect(0, 0, 256, 256));
  s.framebufferHeight = 256;
  CHECK(drawnInOrder(windowVertex(109.25f, 54.75f), windowVertex(109.0f, 54.5f), s).empty());
}

TEST_CASE("GL lines: every octant gives one pixel per column or row, 8-connected") {
  const float cx = 32.3f, cy = 31.7f;
  for (int k = 0; k < 64; ++k) {
    const double angle = 2 * std::numbers::pi * (k + 0.5) / 64;
    const WindowVertex a = windowVertex(cx, cy);
    const WindowVertex b = windowVertex(float(cx + 25 * std::cos(angle)), float(cy + 25 * std::sin(angle)));
    const auto pixels = drawnInOrder(a, b, lineSettings());
    const bool xMajor = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
    std::set<int> majors;
    for (const GridPixel& p : pixels) majors.insert(xMajor ? p.x : p.y);
    CHECK(majors.size() == pixels.size());
    for (size_t i = 1; i < pixels.size(); ++i) {
      CHECK(std::abs(pixels[i].x - pixels[i - 1].x) <= 1);
      CHECK(std::abs(pixels[i].y - pixels[i - 1].y) <= 1);
    }
    // Every pixel's centre is within half a pixel of the line along the minor axis.
    for (const GridPixel& p : pixels) {
      const double px = p.x + 0.5, py = p.y + 0.5;
      const double off = xMajor ? a.y + (px - a.x) * (b.y - a.y) / (b.x - a.x) - py
                                : a.x + (py - a.y) * (b.x - a.x) / (b.y - a.y) - px;
      CHECK(std::fabs(off) <= 0.5 + 1.0 / 256);  // endpoints snap to 1/256
    }
  }
}

TEST_CASE("GL lines: a strip draws each shared vertex once") {
  // Vertices inside their pixels' diamonds. (A vertex exactly on a diamond's boundary, such as
  // (20.6, 9.1), is drawn by both segments, in Mesa as in glass.)
  const WindowVertex v[4] = {windowVertex(3.2f, 4.7f), windowVertex(20.6f, 9.3f), windowVertex(25.3f, 30.4f), windowVertex(3.9f, 28.2f)};
  RecordingSink sink;
  for (int i = 0; i < 3; ++i) rasterizeLine(v[i], v[i + 1], lineSettings(), sink);
  for (const auto& [pixel, count] : sink.writes) CHECK(count == 1);
}

TEST_CASE("GL lines: depth linear and varyings perspective-correct along the segment") {
  WindowVertex a = windowVertex(2.5f, 5.5f, 0.0f, 1.0f), b = windowVertex(42.5f, 15.5f, 1.0f, 0.25f);
  a.varyings[0] = 0.0f;
  b.varyings[0] = 1.0f;
  LineSettings s = lineSettings();
  s.varyingCount = 1;
  RecordingSink sink;
  rasterizeLine(a, b, s, sink);
  REQUIRE(sink.fragments.size() == 40);
  for (const Fragment& f : sink.fragments) {
    const double t = std::clamp((f.x + 0.5 - 2.5) / 40.0, 0.0, 1.0);
    CHECK(f.depth == static_cast<uint32_t>(std::floor(t * kDepthMax + 0.5)));
    const double expected = (t * 1.0 * 0.25) / ((1 - t) * 1.0 + t * 0.25);
    CHECK(f.varyings[0] == doctest::Approx(expected).epsilon(1e-6));
  }
  // The first fragment's centre (10.5) lies before the start (10.8): its values are extrapolated
  // (t = -0.03), as equation 3.6 and Mesa give them, not clamped to the start's.
  WindowVertex c = windowVertex(10.8f, 5.5f, 0.5f), d = windowVertex(20.8f, 5.5f, 0.5f);
  c.varyings[0] = 0.0f;
  d.varyings[0] = 1.0f;
  RecordingSink early;
  rasterizeLine(c, d, s, early);
  REQUIRE(!early.fragments.empty());
  CHECK(early.fragments.front().x == 10);
  CHECK(early.fragments.front().varyings[0] == doctest::Approx(-0.03).epsilon(1e-5));
  // Without perspective correction the varying follows t itself.
  s.perspectiveCorrect = false;
  RecordingSink affine;
  rasterizeLine(a, b, s, affine);
  for (const Fragment& f : affine.fragments)
    CHECK(f.varyings[0] == doctest::Approx(std::clamp((f.x + 0.5 - 2.5) / 40.0, 0.0, 1.0)).epsilon(1e-6));
}

TEST_CASE("GL lines: wide lines are runs of w pixels across the major axis") {
  for (int width = 1; width <= 5; ++width) {
    LineSettings s = lineSettings();
    s.width = float(width);
    RecordingSink sink;
    rasterizeLine(windowVertex(4.3f, 20.2f), windowVertex(40.8f, 31.9f), s, sink);  // x-major
    std::map<int, std::vector<int>> columns;
    for (const Fragment& f : sink.fragments) columns[f.x].push_back(f.y);
    CHECK(columns.size() == 37);
    for (auto& [x, ys] : columns) {
      CHECK(ys.size() == size_t(width));
      std::sort(ys.begin(), ys.end());
      CHECK(ys.back() - ys.front() == width - 1);
      // The run is centred on the line: its middle is within half a pixel of it.
      const double lineY = 20.2 + (x + 0.5 - 4.3) * (31.9 - 20.2) / (40.8 - 4.3);
      CHECK(std::fabs((ys.front() + ys.back()) / 2.0 + 0.5 - lineY) <= 0.5 + 1e-3);
    }
    RecordingSink ySink;
    rasterizeLine(windowVertex(30.5f, 2.5f), windowVertex(30.5f, 12.5f), s, ySink);  // vertical
    CHECK(ySink.fragments.size() == size_t(10 * width));
    for (const Fragment& f : ySink.fragments) CHECK(std::abs(f.x - 30) <= width / 2);
  }
  // A width halfway between two integers is rounded up (away from zero), as Mesa rounds it.
  LineSettings s = lineSettings();
  s.width = 2.5f;
  RecordingSink sink;
  rasterizeLine(windowVertex(30.5f, 2.5f), windowVertex(30.5f, 12.5f), s, sink);
  CHECK(sink.fragments.size() == 30u);
}

TEST_CASE("GL lines: stipple pattern, repeat factor, and a counter carried across segments") {
  LineSettings s = lineSettings();
  s.stippleFactor = 2;
  s.stipplePattern = 0x00F0;  // bits 4-7 set: with factor 2, fragments 8-15 of every 32
  int counter = 0;
  s.stippleCounter = &counter;
  const auto first = drawnInOrder(windowVertex(0.5f, 1.5f), windowVertex(20.5f, 1.5f), s);
  CHECK(counter == 20);
  std::vector<GridPixel> expected;
  for (int x = 8; x < 16; ++x) expected.push_back({x, 1});
  CHECK(first == expected);
  // The strip's next segment continues at s = 20: fragments with s in 40..47 only, 20 further on.
  const auto second = drawnInOrder(windowVertex(20.5f, 1.5f), windowVertex(60.5f, 1.5f), s);
  CHECK(counter == 60);
  expected.clear();
  for (int x = 40; x < 48; ++x) expected.push_back({x, 1});
  CHECK(second == expected);
  // Factor 0 turns stipple off.
  s.stippleFactor = 0;
  CHECK(drawnInOrder(windowVertex(0.5f, 1.5f), windowVertex(20.5f, 1.5f), s).size() == 20);
}

TEST_CASE("GL lines: fragments stay inside the bounds, in batches of at most 64") {
  RecordingSink sink;
  rasterizeLine(windowVertex(-20.0f, -3.0f), windowVertex(300.0f, 70.0f), lineSettings(rect(10, 5, 200, 40)), sink);
  CHECK(!sink.fragments.empty());
  for (const Fragment& f : sink.fragments) {
    CHECK(f.x >= 10);
    CHECK(f.x < 200);
    CHECK(f.y >= 5);
    CHECK(f.y < 40);
  }
  for (int size : sink.batchSizes) CHECK(size <= 64);
}

TEST_CASE("points: size rounded, square centred as section 3.3 says, clipped to the bounds") {
  PointSettings s;
  s.bounds = rect(0, 0, 32, 32);
  s.varyingCount = 2;
  WindowVertex v = windowVertex(2.3f, 4.7f, 0.25f);
  v.varyings[0] = 0.5f;
  v.varyings[1] = 0.75f;
  auto drawn = [&](float size) {
    s.size = size;
    RecordingSink sink;
    rasterizePoint(v, s, sink);
    std::set<std::pair<int, int>> pixels;
    for (const Fragment& f : sink.fragments) {
      pixels.insert({f.x, f.y});
      CHECK(f.depth == static_cast<uint32_t>(std::floor(0.25f * double(kDepthMax) + 0.5)));
      CHECK(f.varyings[0] == 0.5f);
      CHECK(f.varyings[1] == 0.75f);
    }
    return pixels;
  };
  auto square = [](int x0, int y0, int w) {
    std::set<std::pair<int, int>> p;
    for (int y = y0; y < y0 + w; ++y)
      for (int x = x0; x < x0 + w; ++x) p.insert({x, y});
    return p;
  };
  CHECK(drawn(1.0f) == square(2, 4, 1));   // the pixel holding the point
  CHECK(drawn(0.2f) == square(2, 4, 1));   // at least one pixel
  CHECK(drawn(2.0f) == square(1, 4, 2));   // even: centred on (floor(x + 1/2), floor(y + 1/2)) = (2, 5)
  CHECK(drawn(3.0f) == square(1, 3, 3));   // odd: centred on the pixel (2, 4)
  CHECK(drawn(3.4f) == square(1, 3, 3));   // rounded to 3
  CHECK(drawn(4.0f) == square(0, 3, 4));
  // Near the corner of the bounds, the square is cut.
  v.x = 0.5f;
  v.y = 31.5f;
  CHECK(drawn(3.0f) == std::set<std::pair<int, int>>{{0, 30}, {1, 30}, {0, 31}, {1, 31}});
}
