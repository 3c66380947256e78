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
// Which end pixels are drawn follows Mesa's llvmpipe, because pictures from glass are compared
// pixel for pixel with Mesa's. llvmpipe decides with float arithmetic on the unsnapped endpoints,
// with rows numbered downwards (y = -y_window here), and departs from the exact rule (as
// perturbed by (-eps, -eps^2)) systematically:
//  1. An endpoint's pixel is (floor(x), floor(y)) in downward rows: an endpoint exactly on a
//     vertical pixel border belongs to the pixel on its right, where the perturbation puts it in
//     the pixel on its left. A horizontal segment from x = 3 to x = 36 along a row of centres
//     draws columns 3..35 in Mesa and glass; the exact rule draws 2..34.
//  2. When the start point lies before its pixel's centre and moves away from the centre row,
//     the crossing of the column centre is tested as frac(y) + offset * slope, with the offset's
//     sign reversed from the geometric frac(y) - offset * slope.
//  3. Where the band already reaches an end pixel that the test says not to draw, the end edge is
//     moved to the pixel's border, which in some configurations keeps the pixel anyway.
// On random segments with 1/256-pixel endpoints the exact rule agrees with Mesa on about 91% of
// segments and this construction on about 99.6%; the rest differ in single pixels where the line
// passes exactly halfway between two centres: there llvmpipe's choice depends on the direction
// of travel and on the slope in a way not reproduced here (glass takes the pixel the exact rule
// takes).
// The corners are snapped to 1/256 pixel after the ends are moved, as llvmpipe does; the
// decisions use float arithmetic in the same order, so the same inputs give the same pixels on
// every machine.
#include "line_quad.h"

#include <cmath>

namespace glass::raster {
namespace {

// Round to the nearest 1/256, ties to even, after the float arithmetic of the caller.
inline int64_t snap(float v) { return static_cast<int64_t>(std::nearbyint(256.0f * v)); }
inline float fraction(float v) { return v - std::floor(v); }
inline bool nonNegative(float v) { return v >= 0.0f; }

}  // namespace

bool makeLineQuad(float xa, float upYa, float xb, float upYb, float width, LineQuad& quad) {
  // llvmpipe works with rows numbered downwards; so does this function (y = -y_window), and the
  // corners are turned back to GL's upward rows at the end.
  const float ya = -upYa, yb = -upYb;
  // Offsets of the endpoints from the centres of the pixels that contain them, in [-1/2, 1/2).
  float startX = xa - std::floor(xa) - 0.5f, startY = ya - std::floor(ya) - 0.5f;
  float endX = xb - std::floor(xb) - 0.5f, endY = yb - std::floor(yb) - 0.5f;
  // Travel direction; all arithmetic below stays in float, in the order llvmpipe uses.
  const float travelX = xb - xa, travelY = yb - ya;
  if (travelX == 0.0f && travelY == 0.0f) return false;
  const int halfWidth = static_cast<int>(std::nearbyint(std::fmax(width, 1.0f))) * 256 / 2;

  // "first" is the end with the larger major coordinate for x-major lines and the smaller one
  // for y-major lines; the quadrilateral runs first -> second along one long side.
  float firstOffsetX = 0, firstOffsetY = 0, secondOffsetX = 0, secondOffsetY = 0;
  float firstX, firstY, secondX, secondY;
  quad.xMajor = std::fabs(travelX) >= std::fabs(travelY);
  if (quad.xMajor) {
    const float slope = (-travelY) / (-travelX);
    if (endY == -0.5f && travelY > 0.0f) endY = 0.5f;

    bool drawStart, drawEnd;
    if (std::fabs(startX) + std::fabs(startY) < 0.5f) drawStart = true;        // starts inside
    else if (nonNegative(startX) == nonNegative(travelX)) drawStart = false;   // past the centre
    else if (nonNegative(-startY) != nonNegative(-travelY)) drawStart = true;  // towards centre row
    else {
      const float crossing = fraction(ya) + startX * slope;
      drawStart = crossing < 1.0f && crossing > 0.0f;
    }
    if (std::fabs(endX) + std::fabs(endY) < 0.5f) drawEnd = false;           // ends inside
    else if (nonNegative(endX) != nonNegative(travelX)) drawEnd = false;
    else if (nonNegative(-endY) == nonNegative(-travelY)) drawEnd = true;
    else {
      const float crossing = fraction(yb) + endX * slope;
      drawEnd = crossing < 1.0f && crossing > 0.0f;
    }

    if (travelX > 0.0f) {  // first = end point (right), second = start point (left)
      if ((startX <= 0.0f) != drawStart) {
        secondOffsetX = -startX - 0.5f;
        secondOffsetY = secondOffsetX * slope;
      }
      if ((endX > 0.0f) != drawEnd) {
        firstOffsetX = -endX - 0.5f;
        firstOffsetY = firstOffsetX * slope;
      }
      firstX = xb, firstY = yb, secondX = xa, secondY = ya;
    } else {  // first = start point (right), second = end point (left)
      if ((startX > 0.0f) != drawStart) {
        firstOffsetX = -startX + 0.5f;
        firstOffsetY = firstOffsetX * slope;
      }
      if ((endX <= 0.0f) != drawEnd) {
        secondOffsetX = -endX + 0.5f;
        secondOffsetY = secondOffsetX * slope;
      }
      firstX = xa, firstY = ya, secondX = xb, secondY = yb;
    }
    const int64_t x0 = snap(firstX + firstOffsetX - 0.5f), x1 = snap(secondX + secondOffsetX - 0.5f);
    const int64_t y0 = snap(firstY + firstOffsetY - 0.5f), y1 = snap(secondY + secondOffsetY - 0.5f);
    quad.x[0] = x0, quad.y[0] = y0 - halfWidth;
    quad.x[1] = x1, quad.y[1] = y1 - halfWidth;
    quad.x[2] = x1, quad.y[2] = y1 + halfWidth;
    quad.x[3] = x0, quad.y[3] = y0 + halfWidth;
  } else {
    const float inverseSlope = (-travelX) / (-travelY);
    if (endX == -0.5f && travelX > 0.0f) endX = 0.5f;

    bool drawStart, drawEnd;
    if (std::fabs(startX) + std::fabs(startY) < 0.5f) drawStart = true;
    else if (nonNegative(-startY) == nonNegative(-travelY)) drawStart = false;
    else if (nonNegative(startX) != nonNegative(travelX)) drawStart = true;
    else {
      const float crossing = fraction(xa) + startY * inverseSlope;
      drawStart = crossing < 1.0f && crossing > 0.0f;
    }
    if (std::fabs(endX) + std::fabs(endY) < 0.5f) drawEnd = false;
    else if (nonNegative(-endY) != nonNegative(-travelY)) drawEnd = false;
    else if (nonNegative(endX) == nonNegative(travelX)) drawEnd = true;
    else {
      const float crossing = fraction(xb) + endY * inverseSlope;
      drawEnd = crossing < 1.0f && crossing >= 0.0f;
    }

    // Rows numbered downwards: the edge at the larger y (GL's bottom edge) owns its centres.
    if (travelY < 0.0f) {  // first = end point (smaller y), second = start point
      if ((startY >= 0.0f) != drawStart) {
        secondOffsetY = -startY + 0.5f;
        secondOffsetX = secondOffsetY * inverseSlope;
      }
      if ((endY < 0.0f) != drawEnd) {
        firstOffsetY = -endY + 0.5f;
        firstOffsetX = firstOffsetY * inverseSlope;
      }
      firstX = xb, firstY = yb, secondX = xa, secondY = ya;
    } else {  // first = start point (smaller y), second = end point
      if ((startY < 0.0f) != drawStart) {
        firstOffsetY = -startY - 0.5f;
        firstOffsetX = firstOffsetY * inverseSlope;
      }
      if ((endY >= 0.0f) != drawEnd) {
        secondOffsetY = -endY - 0.5f;
        secondOffsetX = secondOffsetY * inverseSlope;
      }
      firstX = xa, firstY = ya, secondX = xb, secondY = yb;
    }
    const int64_t x0 = snap(firstX + firstOffsetX - 0.5f), x1 = snap(secondX + secondOffsetX - 0.5f);
    const int64_t y0 = snap(firstY + firstOffsetY - 0.5f), y1 = snap(secondY + secondOffsetY - 0.5f);
    quad.x[0] = x0 - halfWidth, quad.y[0] = y0;
    quad.x[1] = x1 - halfWidth, quad.y[1] = y1;
    quad.x[2] = x1 + halfWidth, quad.y[2] = y1;
    quad.x[3] = x0 + halfWidth, quad.y[3] = y0;
  }
  // Row m numbered downwards (centre at -(m + 1/2) in window y) is GL row -1 - m, whose centre is
  // at 256 (-1 - m) in the fixed-point frame: y_up = -256 - y_down.
  for (int64_t& y : quad.y) y = -256 - y;
  return true;
}

}  // namespace glass::raster
