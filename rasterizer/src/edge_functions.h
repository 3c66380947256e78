// A triangle's three edge functions (or a convex quadrilateral's four), evaluated at pixel
// centres with the fill rule applied.
//
// Setup gives E_i(X, Y) = A_i X + B_i Y + C_i in 24.8 fixed point (triangle.h). At the centre of
// pixel (px, py), X = 256 px + 128 and Y = 256 py + 128, so
//   E_i = (256 A_i) px + (256 B_i) py + (128 A_i + 128 B_i + C_i),
// an affine function of the pixel indices with integer steps. The fill rule: a centre exactly on
// an edge is covered only when the edge owns its centres (A > 0, or A == 0 and B > 0; see
// triangle_rasterize.cpp). "E > 0, or E == 0 on an owning edge" is "E + bias - 1 >= 0" with bias
// 1 on owning edges, so the functions here include that -1 on the other edges, and a pixel is
// inside when all three (four) values are non-negative.
//
// Everything is exact 64-bit integer arithmetic (|A|, |B| < 2^28, pixel indices < 2^20), so the
// value at a pixel is the same whichever way it is reached: by steps across a block or directly.
#pragma once

#include <algorithm>
#include <cstdint>

#include "glass/raster/triangle.h"
#include "subpixel.h"

namespace glass::raster {

// The kEdges edge functions of a setup whose edgeCount is kEdges: 3 for a triangle, 4 for a
// convex quadrilateral (setupQuad).
template <int kEdges = 3>
struct PixelEdgeFunctions {
  static_assert(kEdges <= TriangleSetup::kMaxEdges);
  int64_t stepX[kEdges], stepY[kEdges], atOrigin[kEdges];  // E_i(px, py) = stepX px + stepY py + atOrigin

  explicit PixelEdgeFunctions(const TriangleSetup& setup) {
    for (int i = 0; i < kEdges; ++i) {
      const int64_t a = setup.edgeA[i], b = setup.edgeB[i];
      const bool ownsCentres = a > 0 || (a == 0 && b > 0);
      stepX[i] = a * kSubpixelOne;
      stepY[i] = b * kSubpixelOne;
      atOrigin[i] = (a + b) * kSubpixelHalf + setup.edgeC[i] + (ownsCentres ? 0 : -1);
    }
  }

  int64_t at(int i, int px, int py) const { return stepX[i] * px + stepY[i] * py + atOrigin[i]; }

  // The largest and smallest value of edge i over the pixel centres of the w x h pixels whose
  // lower-left pixel is (px, py): an affine function takes its extremes at corners.
  int64_t maxOver(int i, int px, int py, int w, int h) const {
    return at(i, px, py) + std::max<int64_t>(stepX[i] * (w - 1), 0) +
           std::max<int64_t>(stepY[i] * (h - 1), 0);
  }
  int64_t minOver(int i, int px, int py, int w, int h) const {
    return at(i, px, py) + std::min<int64_t>(stepX[i] * (w - 1), 0) +
           std::min<int64_t>(stepY[i] * (h - 1), 0);
  }

  // No pixel centre of the rectangle is inside: some edge is negative at all of them.
  bool rejects(int px, int py, int w, int h) const {
    for (int i = 0; i < kEdges; ++i)
      if (maxOver(i, px, py, w, h) < 0) return true;
    return false;
  }
};

}  // namespace glass::raster
