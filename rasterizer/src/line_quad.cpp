// A GL line segment as the quadrilateral whose covered pixel centres are its fragments.
//
// Along the segment this is GL's diamond-exit rule (spec 3.4.1): for an x-major segment the rule
// produces, in each column, the pixel whose centre is nearest the line's height at the column
// centre, which is the pixel whose centre lies in the band of height 1 around the line; the fill
// rule shared with triangles (left and bottom edges own their centres) settles the case of a line
// exactly halfway between two centres the way the rule's (-eps, -eps^2) perturbation does (upper
// pixel for a rising line, lower pixel otherwise). A wide line is the band of height w (spec
// 3.4.2: a column of w fragments per x).
//
// At the ends, the band is cut by a vertical (x-major) or horizontal (y-major) edge, placed so
// that the first pixel is drawn when the segment leaves its diamond and the last pixel is not.
// The construction is Mesa's (llvmpipe's line setup, Mesa 22.3), step for step, because pictures
// from glass are compared pixel for pixel with Mesa's: the same float operations in the same
// order on the unsnapped endpoints, the same rounding to 1/256 pixel, with rows numbered
// downwards from the top of the framebuffer as Mesa numbers them (y = H - y_window). It departs
// from the exact rule (as perturbed by (-eps, -eps^2)) in systematic ways:
//  1. An endpoint's pixel is (floor(x), floor(y)) in downward rows: an endpoint exactly on a
//     vertical pixel border belongs to the pixel on its right, where the perturbation puts it in
//     the pixel on its left. A horizontal segment from x = 3 to x = 36 along a row of centres
//     draws columns 3..35 in Mesa and glass; the exact rule draws 2..34.
//  2. When the start point lies before its pixel's centre and moves away from the centre row,
//     the crossing of the column centre is tested as frac(y) + offset * slope, with the offset's
//     sign reversed from the geometric frac(y) - offset * slope.
//  3. Where the band already reaches an end pixel that the test says not to draw (or does not
//     reach one it should draw), the end edge is moved to the pixel's border, which in some
//     configurations keeps the pixel anyway.
//  4. Whether the band "already reaches" the end pixel is judged with <= where the band's own
//     edge rule needs <: an end exactly on a column of pixel centres (x-major, travelling right)
//     or on a row of centres (y-major, travelling up) counts as reached although the band's end
//     edge, which does not own its centres there, leaves it out. The test then disagrees with the
//     band, and the end edge is moved by rule 3 half a pixel back along the segment. That keeps
//     the same columns (rows), but the moved corner, at y + (-1/2) * slope, is rounded to 1/256
//     pixel, so the long sides tilt by up to 1/512 pixel over the segment's length. Wherever the
//     segment passes exactly halfway between two pixel centres (a tie), that tilt, not the fill
//     rule, decides which of the two is drawn. This is why Mesa's choice at ties depends on the
//     direction of travel and on the slope: a segment from (98.5, 185.5) to (188.5, 100.5) takes
//     the upper pixel at its ties (its right end moved, rounded down by 0.11/256), the same
//     segment drawn the other way the lower one.
//  5. Corners are rounded to 1/256 pixel half away from zero, adding one half in float and
//     truncating (Mesa's util_iround), after the end moves of rules 3 and 4.
// Measured on random segments (endpoints on the grids of 1, 1/2, 1/4, 1/256 and 2^-15 pixel and
// arbitrary floats, every octant, widths 1 to 3, strips and loops), the pixels are Mesa's for
// every segment whose window coordinates are Mesa's; the exact rule agrees with Mesa on about 91%.
// The decisions use float arithmetic, so the same inputs give the same pixels on every machine.
#include "line_quad.h"

#include <cmath>

namespace glass::raster {
namespace {

// Mesa's rounding to 1/256 pixel: 256 v rounded half away from zero, with the half added in float.
inline int64_t snapLikeMesa(float v) {
  const float scaled = 256.0f * v;
  return static_cast<int64_t>(scaled >= 0.0f ? scaled + 0.5f : scaled - 0.5f);
}
inline float fraction(float v) { return v - std::floor(v); }
inline bool nonNegative(float v) { return v >= 0.0f; }

// Lines wider than this are drawn this wide (GL clamps the width to the implementation's range
// first; this only keeps the fixed-point arithmetic in range).
constexpr float kMaxLineWidth = 4096.0f;

}  // namespace

bool makeLineQuad(float xa, float upYa, float xb, float upYb, float width, int framebufferHeight,
                  LineQuad& quad) {
  // Rows numbered downwards from the top of the framebuffer, as in Mesa; the corners are turned
  // back to GL's upward rows at the end.
  const float top = static_cast<float>(framebufferHeight);
  const float ya = top - upYa, yb = top - upYb;
  // Mesa's differences run from the end point back to the start point.
  const float dx = xa - xb, dy = ya - yb;
  if (dx * dx + dy * dy == 0.0f) return false;
  // Offsets of the endpoints from the centres of the pixels that contain them, in [-1/2, 1/2).
  float startX = xa - std::floor(xa) - 0.5f, startY = ya - std::floor(ya) - 0.5f;
  float endX = xb - std::floor(xb) - 0.5f, endY = yb - std::floor(yb) - 0.5f;
  // The width rounded half away from zero (3.4.2: rounded to an integer), at least 1.
  const float clampedWidth = std::fmin(std::fmax(width, 1.0f), kMaxLineWidth);
  const int64_t halfWidth = static_cast<int64_t>(clampedWidth + 0.5f) * 256 / 2;

  // Moves of the start and the end along the segment (rule 3), zero when the end edge passes
  // through the endpoint.
  float startShiftX = 0, startShiftY = 0, endShiftX = 0, endShiftY = 0;
  quad.xMajor = std::fabs(dx) >= std::fabs(dy);
  if (quad.xMajor) {
    const float slope = dy / dx;
    if (endY == -0.5f && dy < 0.0f) endY = 0.5f;

    bool drawStart, drawEnd;
    if (std::fabs(startX) + std::fabs(startY) < 0.5f) drawStart = true;   // starts inside
    else if (nonNegative(startX) == nonNegative(-dx)) drawStart = false;  // past the centre
    else if (nonNegative(-startY) != nonNegative(dy)) drawStart = true;   // towards centre row
    else {
      const float crossing = fraction(ya) + startX * slope;  // rule 2
      drawStart = crossing < 1.0f && crossing > 0.0f;
    }
    if (std::fabs(endX) + std::fabs(endY) < 0.5f) drawEnd = false;  // ends inside
    else if (nonNegative(endX) != nonNegative(-dx)) drawEnd = false;
    else if (nonNegative(-endY) == nonNegative(dy)) drawEnd = true;
    else {
      const float crossing = fraction(yb) + endX * slope;
      drawEnd = crossing < 1.0f && crossing > 0.0f;
    }

    // The band's left end edge owns the centres on it, its right end edge does not; so the band
    // reaches the left end's pixel when its centre is at or right of the endpoint and the right
    // end's pixel when its centre is left of it. For the right end (the end point of a segment
    // travelling right) Mesa also counts a centre exactly on the endpoint (rule 4).
    const bool rightwards = dx < 0.0f;
    const bool bandHasStart = rightwards ? startX <= 0.0f : startX > 0.0f;
    const bool bandHasEnd = rightwards ? endX >= 0.0f : endX <= 0.0f;
    // Rule 3: move the end edge to the pixel's border, the one on the far side of its centre.
    if (bandHasStart != drawStart) {
      startShiftX = rightwards ? -startX - 0.5f : -startX + 0.5f;
      startShiftY = startShiftX * slope;
    }
    if (bandHasEnd != drawEnd) {
      endShiftX = rightwards ? -endX - 0.5f : -endX + 0.5f;
      endShiftY = endShiftX * slope;
    }

    // Corners: the right end's lower and upper corner (in downward rows), then the left end's.
    const float rightX = rightwards ? xb + endShiftX : xa + startShiftX;
    const float rightY = rightwards ? yb + endShiftY : ya + startShiftY;
    const float leftX = rightwards ? xa + startShiftX : xb + endShiftX;
    const float leftY = rightwards ? ya + startShiftY : yb + endShiftY;
    const int64_t x0 = snapLikeMesa(rightX - 0.5f), x1 = snapLikeMesa(leftX - 0.5f);
    const int64_t y0 = snapLikeMesa(rightY - 0.5f), y1 = snapLikeMesa(leftY - 0.5f);
    quad.x[0] = x0, quad.y[0] = y0 - halfWidth;
    quad.x[1] = x1, quad.y[1] = y1 - halfWidth;
    quad.x[2] = x1, quad.y[2] = y1 + halfWidth;
    quad.x[3] = x0, quad.y[3] = y0 + halfWidth;
  } else {
    const float inverseSlope = dx / dy;
    if (endX == -0.5f && dx < 0.0f) endX = 0.5f;

    bool drawStart, drawEnd;
    if (std::fabs(startX) + std::fabs(startY) < 0.5f) drawStart = true;
    else if (nonNegative(-startY) == nonNegative(dy)) drawStart = false;
    else if (nonNegative(startX) != nonNegative(-dx)) drawStart = true;
    else {
      const float crossing = fraction(xa) + startY * inverseSlope;
      drawStart = crossing < 1.0f && crossing > 0.0f;
    }
    if (std::fabs(endX) + std::fabs(endY) < 0.5f) drawEnd = false;
    else if (nonNegative(-endY) != nonNegative(dy)) drawEnd = false;
    else if (nonNegative(endX) == nonNegative(-dx)) drawEnd = true;
    else {
      const float crossing = fraction(xb) + endY * inverseSlope;
      drawEnd = crossing < 1.0f && crossing >= 0.0f;
    }

    // In downward rows the band's lower end edge (larger y, GL's bottom) owns its centres and
    // the upper one does not. A segment travelling up the screen (dy > 0) ends at the upper edge,
    // where Mesa also counts a centre exactly on the endpoint as reached (rule 4).
    const bool upwards = dy > 0.0f;
    const bool bandHasStart = upwards ? startY >= 0.0f : startY < 0.0f;
    const bool bandHasEnd = upwards ? endY <= 0.0f : endY >= 0.0f;
    if (bandHasStart != drawStart) {
      startShiftY = upwards ? -startY + 0.5f : -startY - 0.5f;
      startShiftX = startShiftY * inverseSlope;
    }
    if (bandHasEnd != drawEnd) {
      endShiftY = upwards ? -endY + 0.5f : -endY - 0.5f;
      endShiftX = endShiftY * inverseSlope;
    }

    // Corners: the upper end's left and right corner, then the lower end's.
    const float upperX = upwards ? xb + endShiftX : xa + startShiftX;
    const float upperY = upwards ? yb + endShiftY : ya + startShiftY;
    const float lowerX = upwards ? xa + startShiftX : xb + endShiftX;
    const float lowerY = upwards ? ya + startShiftY : yb + endShiftY;
    const int64_t x0 = snapLikeMesa(upperX - 0.5f), x1 = snapLikeMesa(lowerX - 0.5f);
    const int64_t y0 = snapLikeMesa(upperY - 0.5f), y1 = snapLikeMesa(lowerY - 0.5f);
    quad.x[0] = x0 - halfWidth, quad.y[0] = y0;
    quad.x[1] = x1 - halfWidth, quad.y[1] = y1;
    quad.x[2] = x1 + halfWidth, quad.y[2] = y1;
    quad.x[3] = x0 + halfWidth, quad.y[3] = y0;
  }
  // Downward row m (centre at H - (m + 1/2) in window y) is GL row H - 1 - m, whose centre is at
  // 256 (H - 1 - m) in the fixed-point frame: y_up = 256 (H - 1) - y_down.
  const int64_t flip = 256 * (int64_t{framebufferHeight} - 1);
  for (int64_t& y : quad.y) y = flip - y;
  return true;
}

}  // namespace glass::raster
