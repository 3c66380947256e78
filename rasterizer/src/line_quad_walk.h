// Visits the pixel centres covered by a line quadrilateral, in order of travel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <climits>

#include "line_quad.h"

namespace glass::raster {

namespace line_quad_detail {
inline int64_t floorDiv(int64_t n, int64_t d) {  // d > 0
  const int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
inline int64_t ceilDiv(int64_t n, int64_t d) { return -floorDiv(-n, d); }

// floor(n / d) for n advancing by a fixed step, kept as quotient and remainder so that each step
// costs additions instead of a 64-bit division.
struct SteppedFloorDivision {
  int64_t quotient = 0, remainder = 0, divisor = 1, stepQuotient = 0, stepRemainder = 0;
  void start(int64_t n, int64_t d, int64_t step) {
    divisor = d;
    quotient = floorDiv(n, d);
    remainder = n - quotient * d;
    stepQuotient = floorDiv(step, d);
    stepRemainder = step - stepQuotient * d;
  }
  // Without a branch: whether the remainder carries follows the segment's slope, which a branch
  // predictor guesses wrong about every other run.
  void advance() {
    quotient += stepQuotient;
    remainder += stepRemainder;
    const bool carries = remainder >= divisor;
    quotient += carries;
    remainder -= carries ? divisor : 0;
  }
};
}  // namespace line_quad_detail

// The runs and pixels a walk visits: runs with major coordinate in [majorLow, majorHigh], and in
// them the pixels with minor coordinate in [minorLow, minorHigh] (a tile, or the scissor box).
struct LineQuadClip {
  int64_t majorLow = INT64_MIN, majorHigh = INT64_MAX, minorLow = INT64_MIN, minorHigh = INT64_MAX;
};

// How far a walk must count the runs that hold a pixel (the stipple counter steps once per run,
// inside the clip or not): not at all, up to the clip's last run, or to the end of the segment.
enum class RunCount { None, ThroughClip, All };

// Calls visit(major, minorFirst, minorLast, run) for each run of pixels inside the clip whose
// centres the quad covers, with the same edge functions and ownership rule as triangles (left and
// bottom edges own their centres). A run lies across the major axis (a column of an x-major line,
// a row of a y-major one): the pixels at major coordinate `major` (x for an x-major line) and
// minor coordinates minorFirst to minorLast, at least one. Runs go in increasing major coordinate
// when `increasing` is true, decreasing otherwise. `run` is the number of non-empty runs before
// this one in order of travel, counted from the segment's start when `count` is not
// RunCount::None (0 otherwise). Returns the number of non-empty runs counted.
//
// Each run's extent comes from the four edges by exact integer division, and the walk starts at
// the first run the clip and the count need, so the work is proportional to those runs: with
// RunCount::None a segment drawn tile by tile is walked once in all. Starting later changes no
// pixel: each bound is floor(n_k / d) for the exact integer n_k of its run k, computed directly at
// the first run and kept exact by SteppedFloorDivision from there on.
namespace line_quad_detail {
// Narrows the runs [low, high] (major coordinates) to those where the quad reaches the clip's
// minor range. A long side with Q > 0 bounds a run's pixels from below, so it must hold at the
// clip's highest minor coordinate, and one with Q < 0 at the lowest. Edge i at run k and minor
// coordinate m is 256 P k + 256 Q m + C >= 0, so the runs where it holds at m are k >= ceil(r /
// 256 P) for P > 0 and k <= floor(-r / -256 P) for P < 0, with r = -C - 256 Q m: exact integers,
// so exactly the runs whose pixels the clip would all remove are dropped. Done only where the
// quad's corners reach beyond the minor range (a segment crossing a tile's lower or upper side,
// for an x-major one), and for clip bounds within 2^20 pixels of the origin, where no product
// overflows.
inline void narrowToMinorClip(const int64_t P[4], const int64_t Q[4], const int64_t C[4],
                              const int64_t minorCoord[4], const LineQuadClip& clip, int64_t& low,
                              int64_t& high) {
  constexpr int64_t kNear = int64_t{1} << 20;
  if (clip.minorLow < -kNear || clip.minorHigh > kNear) return;
  const int64_t lowest = *std::min_element(minorCoord, minorCoord + 4);
  const int64_t highest = *std::max_element(minorCoord, minorCoord + 4);
  if (lowest >= 256 * clip.minorLow && highest < 256 * (clip.minorHigh + 1)) return;
  for (int i = 0; i < 4; ++i) {
    if (Q[i] == 0) continue;
    const int64_t m = Q[i] > 0 ? clip.minorHigh : clip.minorLow;
    const int64_t r = -C[i] - 256 * Q[i] * m, p = 256 * P[i];
    if (p > 0) low = std::max(low, ceilDiv(r, p));
    else if (p < 0) high = std::min(high, floorDiv(-r, -p));
    else if (r > 0) high = low - 1;  // holds at no run
  }
}
}  // namespace line_quad_detail

template <class Visit>
int64_t walkLineQuad(const LineQuad& quad, bool increasing, const LineQuadClip& clip,
                     RunCount count, Visit&& visit) {
  using namespace line_quad_detail;
  int64_t X[4], Y[4];
  const int64_t area2 = (quad.x[1] - quad.x[0]) * (quad.y[2] - quad.y[0]) -
                        (quad.x[2] - quad.x[0]) * (quad.y[1] - quad.y[0]) +
                        (quad.x[2] - quad.x[0]) * (quad.y[3] - quad.y[0]) -
                        (quad.x[3] - quad.x[0]) * (quad.y[2] - quad.y[0]);
  // makeLineQuad gives the corners counter-clockwise. When the moves of the ends cross over (a
  // segment shorter than a pixel), the quad is turned inside out: its edge functions, as Mesa
  // evaluates them, then have no pixel centre inside all four, and nothing is drawn.
  if (area2 <= 0) return 0;
  for (int i = 0; i < 4; ++i) {
    X[i] = quad.x[i];
    Y[i] = quad.y[i];
  }
  // Edge i: A x + B y + C + bias >= 0 inside, bias = 0 on an owning edge and -1 otherwise.
  int64_t A[4], B[4], C[4];
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    A[i] = Y[i] - Y[j];
    B[i] = X[j] - X[i];
    const bool owns = A[i] > 0 || (A[i] == 0 && B[i] > 0);
    C[i] = X[i] * Y[j] - Y[i] * X[j] + (owns ? 0 : -1);
  }
  // In terms of (major, minor) coordinates: edge value = P major + Q minor + C.
  const int64_t* P = quad.xMajor ? A : B;
  const int64_t* Q = quad.xMajor ? B : A;
  const int64_t* majorCoord = quad.xMajor ? X : Y;
  int64_t lowMajor = ceilDiv(*std::min_element(majorCoord, majorCoord + 4), 256);
  int64_t highMajor = floorDiv(*std::max_element(majorCoord, majorCoord + 4), 256);
  // An edge with Q == 0 (an end of the quad, across the major axis) holds for whole runs: at run
  // k, P 256 k + C >= 0 means k >= ceil(-C / (256 P)) when P > 0, k <= floor(C / (-256 P)) when
  // P < 0, every k or none when P == 0. A run it fails is empty, neither visited nor counted, so
  // such edges narrow the range of runs, and the walk tests only the other edges run by run.
  for (int i = 0; i < 4; ++i) {
    if (Q[i] != 0) continue;
    if (P[i] > 0) lowMajor = std::max(lowMajor, ceilDiv(-C[i], 256 * P[i]));
    else if (P[i] < 0) highMajor = std::min(highMajor, floorDiv(C[i], -256 * P[i]));
    else if (C[i] < 0) return 0;
  }
  if (lowMajor > highMajor) return 0;
  // The runs to walk, as positions n = 0 .. runs - 1 in order of travel: the clipped ones, from
  // the segment's start when runs before them are counted, to its end when all are counted.
  const int64_t runs = highMajor - lowMajor + 1;
  int64_t clipLow = std::max(lowMajor, clip.majorLow);
  int64_t clipHigh = std::min(highMajor, clip.majorHigh);
  if (count == RunCount::None) narrowToMinorClip(P, Q, C, quad.xMajor ? Y : X, clip, clipLow, clipHigh);
  int64_t firstN = 0, lastN = runs - 1;  // RunCount::All
  if (count != RunCount::All) {
    if (clipLow > clipHigh) {
      if (count == RunCount::None) return 0;
      // Nothing to visit; count the runs that lie before the clip in order of travel.
      lastN = increasing ? std::min(runs, clipLow - lowMajor) - 1
                         : std::min(runs, highMajor - clipHigh) - 1;
    } else {
      lastN = increasing ? clipHigh - lowMajor : highMajor - clipLow;
    }
    if (count == RunCount::None) firstN = increasing ? clipLow - lowMajor : highMajor - clipHigh;
  }
  const int64_t dk = increasing ? 1 : -1;
  const int64_t firstK = (increasing ? lowMajor : highMajor) + dk * firstN;

  // Edge i at run k: need Q * 256 m + P * 256 k + C >= 0. With Q > 0 that is a lower bound
  // m >= ceil(-(P 256 k + C) / (256 Q)), with Q < 0 an upper bound m <= floor((P 256 k + C) /
  // (-256 Q)) (Q == 0 was settled above). The quad is a parallelogram whose ends lie across the
  // major axis (line_quad.h), so with a positive area its two long sides are the only edges with
  // Q != 0, of opposite signs: one lower bound and one upper bound, stepped from run to run.
  SteppedFloorDivision lower, upper;
  for (int i = 0; i < 4; ++i) {
    const int64_t rest = P[i] * 256 * firstK + C[i], restStep = P[i] * 256 * dk;
    if (Q[i] > 0) {  // ceil(-rest / D) = floor((-rest + D - 1) / D)
      const int64_t d = 256 * Q[i];
      lower.start(-rest + d - 1, d, -restStep);
    } else if (Q[i] < 0) {
      upper.start(rest, -256 * Q[i], restStep);
    }
  }
  // The clip's bounds in locals, which the visits' stores cannot change; without counting, every
  // run walked lies inside the major range.
  const int64_t majorLow = clip.majorLow, majorHigh = clip.majorHigh;
  const int64_t minorLow = clip.minorLow, minorHigh = clip.minorHigh;
  const bool walksOutside = count != RunCount::None;
  int64_t counted = 0;
  for (int64_t n = firstN, k = firstK; n <= lastN; ++n, k += dk) {
    const int64_t lo = lower.quotient, hi = upper.quotient;
    lower.advance();
    upper.advance();
    if (lo > hi) continue;
    const int64_t run = counted;
    if (walksOutside) {
      ++counted;
      if (k < majorLow || k > majorHigh) continue;
    }
    const int64_t first = std::max(lo, minorLow), last = std::min(hi, minorHigh);
    if (first <= last)
      visit(static_cast<int>(k), static_cast<int>(first), static_cast<int>(last), run);
  }
  return counted;
}

}  // namespace glass::raster
