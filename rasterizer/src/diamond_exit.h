// The pixels of a width-1 line segment by GL's diamond-exit rule (OpenGL 1.5 spec, section 3.4.1),
// shared by the GL line rasterizer (line.cpp) and the teaching function lineDiamondExit.
//
// The rule: fragment f is produced when the segment from pa to pb meets the open diamond
// R_f = {|x - x_f| + |y - y_f| < 1/2} around f's centre, unless pb lies in R_f; ties (a segment
// touching a diamond's boundary) are settled by moving both endpoints by (-eps, -eps^2) for an
// infinitesimal eps.
//
// Endpoints are in 24.8 fixed point (1/256 pixel). The walk exploits two facts:
//  * For an x-major segment (|dx| >= |dy|) the distance |x - x_f| + |y(x) - y_f| along the line is
//    smallest at x = x_f, so the line meets at most one diamond per column: the one whose centre
//    is nearest to the line's height y* at the column centre. When y* is exactly halfway between
//    two centres, the perturbed line passes at y* + s eps - eps^2 (s the slope): above the halfway
//    point when s > 0 (take the upper pixel), below it otherwise. A y-major segment is the same
//    with rows; there the perturbed line passes at x* - eps + s' eps^2, so a tie takes the left
//    pixel.
//  * Columns that lie entirely within the segment's x-range certainly meet their diamond, and the
//    end point is not in it. Only the one or two columns at each end need the exact test, which is
//    done with the perturbation carried symbolically: every quantity is v + e1 eps + e2 eps^2 with
//    integer v, e1, e2, compared lexicographically, so no tie is ever decided by rounding.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace glass::raster {

namespace diamond_exit_detail {

// v + e1 eps + e2 eps^2 for an infinitesimal eps > 0.
struct Perturbed {
  int64_t v, e1, e2;
};
inline bool greaterThan(const Perturbed& a, int64_t k) {
  if (a.v != k) return a.v > k;
  if (a.e1 != 0) return a.e1 > 0;
  return a.e2 > 0;
}
inline bool lessThan(const Perturbed& a, int64_t k) {
  if (a.v != k) return a.v < k;
  if (a.e1 != 0) return a.e1 < 0;
  return a.e2 < 0;
}

inline int64_t floorDiv(int64_t n, int64_t d) {  // d > 0
  const int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
inline int64_t ceilDiv(int64_t n, int64_t d) { return -floorDiv(-n, d); }  // d > 0

struct Segment {
  int64_t xa, ya, xb, yb;  // 24.8 fixed point
  int64_t dx, dy;

  // Projections of the perturbed endpoints p' = (x - eps, y - eps^2) on the diamond's two edge
  // normals (1, 1), (1, -1) and on the segment's normal (-dy, dx).
  Perturbed sum(int64_t x, int64_t y) const { return {x + y, -1, -1}; }
  Perturbed difference(int64_t x, int64_t y) const { return {x - y, -1, 1}; }
  Perturbed normal(int64_t x, int64_t y) const { return {-dy * x + dx * y, dy, -dx}; }

  // Exact test for the pixel (px, py): does the perturbed segment meet its diamond while its
  // perturbed end point lies outside it? Separating axes: an open diamond and a closed segment
  // are disjoint exactly when their projections on one of the three normals do not overlap.
  bool produces(int64_t px, int64_t py) const {
    const int64_t cx = px * 256 + 128, cy = py * 256 + 128, h = 128;
    auto overlaps = [](const Perturbed& a, const Perturbed& b, int64_t lo, int64_t hi) {
      return (greaterThan(a, lo) || greaterThan(b, lo)) && (lessThan(a, hi) || lessThan(b, hi));
    };
    const int64_t s = cx + cy, d = cx - cy, n = -dy * cx + dx * cy;
    const int64_t reach = h * std::max(std::abs(dx), std::abs(dy));
    const bool meets = overlaps(sum(xa, ya), sum(xb, yb), s - h, s + h) &&
                       overlaps(difference(xa, ya), difference(xb, yb), d - h, d + h) &&
                       overlaps(normal(xa, ya), normal(xb, yb), n - reach, n + reach);
    if (!meets) return false;
    const Perturbed endSum = sum(xb, yb), endDifference = difference(xb, yb);
    const bool endInside = greaterThan(endSum, s - h) && lessThan(endSum, s + h) &&
                           greaterThan(endDifference, d - h) && lessThan(endDifference, d + h);
    return !endInside;
  }
};

}  // namespace diamond_exit_detail

// Calls visit(x, y) for every pixel of the width-1 segment from (xa, ya) to (xb, yb) (24.8 fixed
// point window coordinates), in order of travel. Coordinates must be within +-2^27 (2^19 pixels).
template <class Visit>
void walkDiamondExitLine(int64_t xa, int64_t ya, int64_t xb, int64_t yb, Visit&& visit) {
  using namespace diamond_exit_detail;
  const Segment seg{xa, ya, xb, yb, xb - xa, yb - ya};
  if (seg.dx == 0 && seg.dy == 0) return;  // pb lies in every diamond pa lies in
  const bool xMajor = std::abs(seg.dx) >= std::abs(seg.dy);

  // Along the major axis: a = major coordinate, b = minor coordinate.
  const int64_t a0 = xMajor ? xa : ya, b0 = xMajor ? ya : xa;
  const int64_t a1 = xMajor ? xb : yb;
  const int64_t da = a1 - a0, db = xMajor ? seg.dy : seg.dx;
  const int step = da > 0 ? 1 : -1;
  // Minor coordinate of the line at major coordinate 256 k + 128, as n(k) / (256 |da|):
  //   n(k) = b0 |da| + (256 k + 128 - a0) sign(da) db
  const int64_t absDa = std::abs(da), signedDb = da > 0 ? db : -db;
  const int64_t denominator = 256 * absDa;
  // Ties: x-major lines go up when the slope is positive and down otherwise; y-major lines go left.
  const bool tieUp = xMajor && (seg.dx > 0) == (seg.dy > 0) && seg.dy != 0;
  auto minorAt = [&](int64_t k) {
    const int64_t n = b0 * absDa + (256 * k + 128 - a0) * signedDb;
    return tieUp ? floorDiv(n, denominator) : ceilDiv(n, denominator) - 1;
  };

  // Candidate pixels along the major axis: those whose open span (256 k, 256 k + 256) meets the
  // perturbed range (every endpoint moves by -eps along x and -eps^2 along y, both "down").
  const int64_t first = floorDiv(a0 - 1, 256), last = floorDiv(a1 - 1, 256);
  const int64_t lo = std::min(a0, a1), hi = std::max(a0, a1);
  for (int64_t k = first;; k += step) {
    const int64_t minor = minorAt(k);
    const int64_t px = xMajor ? k : minor, py = xMajor ? minor : k;
    const bool inner = 256 * k > lo && 256 * k + 256 < hi;
    if (inner || seg.produces(px, py)) visit(static_cast<int>(px), static_cast<int>(py));
    if (k == last) break;
  }
}

}  // namespace glass::raster
