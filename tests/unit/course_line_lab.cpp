// Homework 1 of the study guide (section 2.1): the line lab's symmetry check over every segment
// of the 32 x 32 grid, the float, integer and Bresenham versions choosing the same squares, and
// the speed measurement's bookkeeping.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>

#include "glass/course/line_lab.h"

namespace c = glass::course;
using glass::raster::GridPixel;

TEST_CASE("course homework 1: swapping the endpoints gives the same squares, for every segment of 32 x 32") {
  for (c::LineAlgorithm algorithm : c::kAllLineAlgorithms) {
    const c::SymmetryReport report = c::checkSymmetry(algorithm, 32);
    CAPTURE(c::formatSymmetryReport(report));
    CHECK(report.segmentsChecked == 1024u * 1023u / 2u);
    CHECK(report.failureCount == 0);
  }
}

TEST_CASE("course homework 1: Listings 1, 2 and 3 choose the same squares") {
  // Listing 2 is Listing 1 with the error scaled by 2 dx, Listing 3 the same with the test moved:
  // the same decisions, so the same squares, for every segment.
  for (const c::GridSegment& s : c::randomSegments(20000, 64, 17)) {
    const auto byFloat = c::lineSquares(c::LineAlgorithm::Float, s);
    CHECK(byFloat == c::lineSquares(c::LineAlgorithm::Integer, s));
    CHECK(byFloat == c::lineSquares(c::LineAlgorithm::Bresenham, s));
  }
}

TEST_CASE("course homework 1: the squares are the nearest ones, one per column or row") {
  for (const c::GridSegment& s : c::randomSegments(5000, 32, 23)) {
    for (c::LineAlgorithm algorithm : {c::LineAlgorithm::Float, c::LineAlgorithm::Bresenham}) {
      const auto squares = c::lineSquares(algorithm, s);
      const int dx = s.x1 - s.x0, dy = s.y1 - s.y0;
      const bool xMajor = std::abs(dx) >= std::abs(dy);
      REQUIRE(squares.size() == static_cast<std::size_t>(std::max(std::abs(dx), std::abs(dy)) + 1));
      CHECK(squares.front() == GridPixel{s.x0, s.y0});
      CHECK(squares.back() == GridPixel{s.x1, s.y1});
      for (const GridPixel& p : squares) {
        // Distance along the minor axis from the true line: at most 1/2.
        const double off = xMajor ? (p.y - (s.y0 + static_cast<double>(dy) * (p.x - s.x0) / dx))
                                  : (p.x - (s.x0 + static_cast<double>(dx) * (p.y - s.y0) / dy));
        CHECK(std::abs(off) <= 0.5 + 1e-12);
      }
    }
  }
}

TEST_CASE("course homework 1: without ties, Bresenham and GL's rule choose the same squares") {
  // Where no step of the segment passes exactly halfway between two squares, the nearest square
  // is unique, and GL's diamond-exit rule finds it too (less the last square). The two differ
  // only at ties, which they break differently.
  int withoutTies = 0;
  for (const c::GridSegment& s : c::randomSegments(20000, 32, 31)) {
    const int dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    const int major = std::abs(dx) >= std::abs(dy) ? dx : dy, minor = std::abs(dx) >= std::abs(dy) ? dy : dx;
    bool tie = false;
    for (int k = 1; k < std::abs(major); ++k) tie = tie || std::llabs(2LL * minor * k) % (2 * std::abs(major)) == std::abs(major);
    if (tie) continue;
    ++withoutTies;
    auto bresenham = c::lineSquares(c::LineAlgorithm::Bresenham, s);
    bresenham.pop_back();
    CHECK(c::sortedSquares(bresenham) == c::sortedSquares(c::lineSquares(c::LineAlgorithm::DiamondExit, s)));
  }
  CHECK(withoutTies > 10000);
}

TEST_CASE("course homework 1: GL's rule leaves out the last square") {
  const auto squares = c::lineSquares(c::LineAlgorithm::DiamondExit, {0, 0, 5, 2});
  REQUIRE_FALSE(squares.empty());
  CHECK(squares.front() == GridPixel{0, 0});
  for (const GridPixel& p : squares) CHECK_FALSE(p == GridPixel{5, 2});
  CHECK(squares.size() == 5);
}

TEST_CASE("course homework 1: the speed comparison counts every square and agrees on the checksum") {
  const c::SpeedReport report = c::measureLineSpeed(2000, 100, 5, 1);
  REQUIRE(report.results.size() == 3);
  std::uint64_t expectedSquares = 0;
  for (const c::GridSegment& s : c::randomSegments(2000, 100, 5)) {
    expectedSquares += static_cast<std::uint64_t>(std::max(std::abs(s.x1 - s.x0), std::abs(s.y1 - s.y0)) + 1);
  }
  for (const c::SpeedResult& r : report.results) {
    CHECK(r.squares == expectedSquares);
    CHECK(r.checksum == report.results[0].checksum);  // the same squares, so the same sum
    CHECK(r.nsPerLine > 0.0);
  }
  const std::string text = c::formatSpeedReport(report);
  CHECK(text.find("never drawn") != std::string::npos);
  CHECK(text.find("ns/line") != std::string::npos);
}

TEST_CASE("course homework 1: random segments are reproducible and have distinct endpoints") {
  const auto a = c::randomSegments(1000, 32, 9), b = c::randomSegments(1000, 32, 9);
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].x0 == b[i].x0);
    CHECK(a[i].y1 == b[i].y1);
    CHECK((a[i].x0 != a[i].x1 || a[i].y0 != a[i].y1));
    CHECK(a[i].x0 >= 0);
    CHECK(a[i].x1 < 32);
  }
  CHECK(c::parseLineAlgorithm("gl") == c::LineAlgorithm::DiamondExit);
  CHECK_FALSE(c::parseLineAlgorithm("dda").has_value());
}
