// The study guide's line algorithms (float, integer, Bresenham) in all octants, their symmetry and
// agreement, and GL's diamond-exit rule between square centres.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "glass/raster/teaching_lines.h"

using namespace glass::raster;

namespace {

using Algorithm = std::vector<GridPixel> (*)(int, int, int, int);
const Algorithm kAlgorithms[] = {lineFloat, lineInteger, lineBresenham};
const char* const kNames[] = {"float", "integer", "Bresenham"};

std::vector<GridPixel> reversed(std::vector<GridPixel> v) {
  std::reverse(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("teaching lines: a known line in each of the eight octants") {
  // (0,0)-(5,2): minor offsets 0, 0.4, 0.8, 1.2, 1.6, 2 round to 0 0 1 1 2 2 (no ties). Every
  // octant is this line reflected; the reflections of the expected squares are expected.
  const std::vector<GridPixel> base = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
  for (int octant = 0; octant < 8; ++octant) {
    auto map = [octant](GridPixel p) {
      if (octant & 4) std::swap(p.x, p.y);
      if (octant & 1) p.x = -p.x;
      if (octant & 2) p.y = -p.y;
      return p;
    };
    std::vector<GridPixel> expected;
    for (GridPixel p : base) expected.push_back(map(p));
    const GridPixel end = map({5, 2});
    for (int a = 0; a < 3; ++a) {
      CAPTURE(octant);
      CAPTURE(kNames[a]);
      CHECK(kAlgorithms[a](0, 0, end.x, end.y) == expected);
      CHECK(kAlgorithms[a](end.x, end.y, 0, 0) == reversed(expected));
    }
  }
}

TEST_CASE("teaching lines: horizontal, vertical, diagonal and single-square lines") {
  for (int a = 0; a < 3; ++a) {
    CAPTURE(kNames[a]);
    CHECK(kAlgorithms[a](2, 3, 6, 3) == std::vector<GridPixel>{{2, 3}, {3, 3}, {4, 3}, {5, 3}, {6, 3}});
    CHECK(kAlgorithms[a](4, 5, 4, 2) == std::vector<GridPixel>{{4, 5}, {4, 4}, {4, 3}, {4, 2}});
    CHECK(kAlgorithms[a](0, 0, -3, 3) == std::vector<GridPixel>{{0, 0}, {-1, 1}, {-2, 2}, {-3, 3}});
    CHECK(kAlgorithms[a](7, 7, 7, 7) == std::vector<GridPixel>{{7, 7}});
  }
}

TEST_CASE("teaching lines: ties go to the larger minor coordinate, whatever the direction") {
  // (0,0)-(2,1): at x = 1 the line is at y = 1/2, halfway between (1,0) and (1,1).
  for (int a = 0; a < 3; ++a) {
    CAPTURE(kNames[a]);
    CHECK(kAlgorithms[a](0, 0, 2, 1) == std::vector<GridPixel>{{0, 0}, {1, 1}, {2, 1}});
    CHECK(kAlgorithms[a](2, 1, 0, 0) == std::vector<GridPixel>{{2, 1}, {1, 1}, {0, 0}});
    // Falling: at x = 1 the line is at y = 1/2 again; (1,1) is the larger.
    CHECK(kAlgorithms[a](0, 1, 2, 0) == std::vector<GridPixel>{{0, 1}, {1, 1}, {2, 0}});
    // y-major: at y = 1 the line is at x = 1/2; the tie goes right, to (1,1).
    CHECK(kAlgorithms[a](0, 0, 1, 2) == std::vector<GridPixel>{{0, 0}, {1, 1}, {1, 2}});
  }
}

TEST_CASE("teaching lines: symmetric and in agreement over every segment of a 16x16 grid") {
  int checked = 0;
  for (int x0 = 0; x0 < 16; ++x0)
    for (int y0 = 0; y0 < 16; ++y0)
      for (int x1 = 0; x1 < 16; ++x1)
        for (int y1 = 0; y1 < 16; ++y1) {
          const std::vector<GridPixel> f = lineFloat(x0, y0, x1, y1);
          const std::vector<GridPixel> i = lineInteger(x0, y0, x1, y1);
          const std::vector<GridPixel> b = lineBresenham(x0, y0, x1, y1);
          if (f != i || i != b || f != reversed(lineFloat(x1, y1, x0, y0)) ||
              i != reversed(lineInteger(x1, y1, x0, y0)) || b != reversed(lineBresenham(x1, y1, x0, y0))) {
            FAIL_CHECK("segment (" << x0 << "," << y0 << ")-(" << x1 << "," << y1 << ")");
          }
          ++checked;
        }
  CHECK(checked == 65536);
}

TEST_CASE("teaching lines: nearest squares, connected, endpoints included, on long random lines") {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> coord(-1000, 1000);
  std::vector<GridPixel> buffer(4096);
  for (int trial = 0; trial < 2000; ++trial) {
    const int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
    const std::vector<GridPixel> f = lineFloat(x0, y0, x1, y1);
    REQUIRE(f == lineInteger(x0, y0, x1, y1));
    REQUIRE(f == lineBresenham(x0, y0, x1, y1));
    REQUIRE(f == reversed(lineBresenham(x1, y1, x0, y0)));
    const int n = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    REQUIRE(f.size() == size_t(n + 1));
    CHECK(f.front() == GridPixel{x0, y0});
    CHECK(f.back() == GridPixel{x1, y1});
    for (size_t k = 1; k < f.size(); ++k) {
      CHECK(std::abs(f[k].x - f[k - 1].x) <= 1);
      CHECK(std::abs(f[k].y - f[k - 1].y) <= 1);
    }
    // Each square is within half a square of the true line along the minor axis.
    const bool xMajor = std::abs(x1 - x0) >= std::abs(y1 - y0);
    for (const GridPixel& p : f) {
      double offset;
      if (xMajor) offset = y0 + double(p.x - x0) * (y1 - y0) / (x1 - x0) - p.y;
      else offset = x0 + double(p.y - y0) * (x1 - x0) / (y1 - y0) - p.x;
      CHECK(std::fabs(offset) <= 0.5 + 1e-12);
    }
    // The allocation-free variants write the same squares.
    CHECK(lineFloatInto(x0, y0, x1, y1, buffer.data()) == n + 1);
    CHECK(std::equal(f.begin(), f.end(), buffer.begin()));
    CHECK(lineIntegerInto(x0, y0, x1, y1, buffer.data()) == n + 1);
    CHECK(std::equal(f.begin(), f.end(), buffer.begin()));
    CHECK(lineBresenhamInto(x0, y0, x1, y1, buffer.data()) == n + 1);
    CHECK(std::equal(f.begin(), f.end(), buffer.begin()));
  }
}

TEST_CASE("diamond exit: cases from the specification (section 3.4.1)") {
  // A horizontal segment between pixel centres: the first pixel's diamond contains the start,
  // which the segment leaves, so it is drawn; the last pixel's diamond contains the end, so not.
  CHECK(lineDiamondExit(0, 0, 4, 0) == std::vector<GridPixel>{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  CHECK(lineDiamondExit(4, 0, 0, 0) == std::vector<GridPixel>{{4, 0}, {3, 0}, {2, 0}, {1, 0}});
  CHECK(lineDiamondExit(2, 5, 2, 2) == std::vector<GridPixel>{{2, 5}, {2, 4}, {2, 3}});
  CHECK(lineDiamondExit(0, 0, 3, 3) == std::vector<GridPixel>{{0, 0}, {1, 1}, {2, 2}});
  CHECK(lineDiamondExit(3, 3, 3, 3).empty());
  // Consecutive segments of a strip share their vertex's pixel exactly once.
  std::vector<GridPixel> strip = lineDiamondExit(0, 0, 5, 2);
  const std::vector<GridPixel> second = lineDiamondExit(5, 2, 9, 7);
  strip.insert(strip.end(), second.begin(), second.end());
  CHECK(std::count(strip.begin(), strip.end(), GridPixel{5, 2}) == 1);
  // Ties: (0,0)-(2,1) passes exactly through the corner of the diamonds of (1,0) and (1,1); the
  // rule's perturbation moves the line left and down, and a rising line then passes above that
  // corner: (1,1). A falling line passes below it.
  CHECK(lineDiamondExit(0, 0, 2, 1) == std::vector<GridPixel>{{0, 0}, {1, 1}});
  CHECK(lineDiamondExit(0, 1, 2, 0) == std::vector<GridPixel>{{0, 1}, {1, 0}});
  // A y-major tie goes left: (0,0)-(1,2) at y = 1 is at x = 1/2.
  CHECK(lineDiamondExit(0, 0, 1, 2) == std::vector<GridPixel>{{0, 0}, {0, 1}});
  // Every segment: one square per step along the major axis, the last one left out.
  for (int x1 = -6; x1 <= 6; ++x1)
    for (int y1 = -6; y1 <= 6; ++y1) {
      const size_t n = size_t(std::max(std::abs(x1), std::abs(y1)));
      CHECK(lineDiamondExit(0, 0, x1, y1).size() == n);
    }
}
