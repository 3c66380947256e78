// The study guide's line algorithms (section 2.1, Listings 1-3), for all eight octants.
//
// Generalisation. The guide's loop steps x and decides when to step y, for slopes in [0, 1]. Here
// the major axis is the one with the larger |delta| (x when they are equal); the loop steps it by
// +-1 from the first endpoint to the second, both included, and decides when to step the minor
// coordinate by sign(minor delta). With n = |major delta| and m = |minor delta|, after i steps the
// true line's minor offset is i m / n, and every algorithm draws the square nearest to it.
//
// Ties and symmetry. When i m / n is exactly halfway between two squares, the square with the
// larger minor coordinate is taken (up for x-major lines, right for y-major lines). That rule
// looks only at the grid, not at the direction of travel, so drawing from (x1, y1) to (x0, y0)
// visits the same squares in reverse order (Figure 2.2's requirement). In the error-term form of
// the listings it means: when the minor coordinate increases along the travel, step on a tie
// (e >= 1/2); when it decreases, do not (e > 1/2).
//
// The three versions make the same decisions:
//   Listing 1 (float):     e += m / n;       step when e >= 1/2 (or > 1/2);  then e -= 1
//   Listing 2 (integer):   e starts at n; e += 2m;  step when e >= 2n (> 2n);  then e -= 2n
//   Listing 3 (Bresenham): e starts at 2m - n; step when e >= 0 (> 0), e -= 2n; then e += 2m
// Listing 2 is Listing 1 multiplied by 2n and shifted by n; Listing 3 moves the update after the
// test and shifts by 2n, so the tests compare the same quantities. The float version works in
// double: m / n is rounded and the sum drifts, so its tests allow a drift of 1e-9, far below the
// smallest gap between a non-tie value and 1/2 (1 / (2n)) for any segment shorter than 10^8.
#include "glass/raster/teaching_lines.h"

#include <algorithm>
#include <cstdlib>

#include "diamond_exit.h"

namespace glass::raster {
namespace {

// The walk shared by the three listings: sets up major/minor axes and calls step(i) to ask whether
// the minor coordinate moves before square i + 1 is drawn.
struct Octant {
  int n, m;              // |major delta|, |minor delta|
  int majorStepX, majorStepY, minorStepX, minorStepY;
  bool minorIncreases;   // the minor coordinate grows along the travel

  Octant(int x0, int y0, int x1, int y1) {
    const int dx = x1 - x0, dy = y1 - y0;
    const int sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
    if (std::abs(dx) >= std::abs(dy)) {
      n = std::abs(dx), m = std::abs(dy);
      majorStepX = sx, majorStepY = 0, minorStepX = 0, minorStepY = sy;
      minorIncreases = dy > 0;
    } else {
      n = std::abs(dy), m = std::abs(dx);
      majorStepX = 0, majorStepY = sy, minorStepX = sx, minorStepY = 0;
      minorIncreases = dx > 0;
    }
  }
};

template <class Decide>
int walk(int x0, int y0, int x1, int y1, GridPixel* out, Decide&& decide) {
  const Octant o(x0, y0, x1, y1);
  int x = x0, y = y0;
  for (int i = 0; i <= o.n; ++i) {
    out[i] = GridPixel{x, y};
    x += o.majorStepX;
    y += o.majorStepY;
    if (decide(o)) {
      x += o.minorStepX;
      y += o.minorStepY;
    }
  }
  return o.n + 1;
}

int lineLength(int x0, int y0, int x1, int y1) {
  return std::max(std::abs(x1 - x0), std::abs(y1 - y0)) + 1;
}

template <int (*Into)(int, int, int, int, GridPixel*)>
std::vector<GridPixel> collect(int x0, int y0, int x1, int y1) {
  std::vector<GridPixel> pixels(static_cast<size_t>(lineLength(x0, y0, x1, y1)));
  pixels.resize(static_cast<size_t>(Into(x0, y0, x1, y1, pixels.data())));
  return pixels;
}

}  // namespace

int lineFloatInto(int x0, int y0, int x1, int y1, GridPixel* out) {
  const Octant o(x0, y0, x1, y1);
  const double slope = o.n == 0 ? 0.0 : double(o.m) / double(o.n);
  constexpr double kDrift = 1e-9;
  double e = 0.0;  // -1/2 <= e < 1/2: the true line's offset from the square drawn
  return walk(x0, y0, x1, y1, out, [&](const Octant& oct) {
    e += slope;
    const bool step = oct.minorIncreases ? e >= 0.5 - kDrift : e > 0.5 + kDrift;
    if (step) e -= 1.0;
    return step;
  });
}

int lineIntegerInto(int x0, int y0, int x1, int y1, GridPixel* out) {
  const Octant o(x0, y0, x1, y1);
  long long e = o.n;  // 0 <= e < 2n
  return walk(x0, y0, x1, y1, out, [&](const Octant& oct) {
    e += 2LL * oct.m;
    const bool step = oct.minorIncreases ? e >= 2LL * oct.n : e > 2LL * oct.n;
    if (step) e -= 2LL * oct.n;
    return step;
  });
}

int lineBresenhamInto(int x0, int y0, int x1, int y1, GridPixel* out) {
  const Octant o(x0, y0, x1, y1);
  long long e = 2LL * o.m - o.n;  // 2m - n <= e < 2m + n
  return walk(x0, y0, x1, y1, out, [&](const Octant& oct) {
    const bool step = oct.minorIncreases ? e >= 0 : e > 0;
    if (step) e -= 2LL * oct.n;
    e += 2LL * oct.m;
    return step;
  });
}

std::vector<GridPixel> lineFloat(int x0, int y0, int x1, int y1) {
  return collect<lineFloatInto>(x0, y0, x1, y1);
}
std::vector<GridPixel> lineInteger(int x0, int y0, int x1, int y1) {
  return collect<lineIntegerInto>(x0, y0, x1, y1);
}
std::vector<GridPixel> lineBresenham(int x0, int y0, int x1, int y1) {
  return collect<lineBresenhamInto>(x0, y0, x1, y1);
}

// GL's exact rule (diamond_exit.h) between square centres: in 24.8 fixed point the centre of
// square (x, y) is (256 x + 128, 256 y + 128).
std::vector<GridPixel> lineDiamondExit(int x0, int y0, int x1, int y1) {
  std::vector<GridPixel> pixels;
  walkDiamondExitLine(int64_t(x0) * 256 + 128, int64_t(y0) * 256 + 128, int64_t(x1) * 256 + 128,
                      int64_t(y1) * 256 + 128, [&](int x, int y) { pixels.push_back({x, y}); });
  return pixels;
}

}  // namespace glass::raster
