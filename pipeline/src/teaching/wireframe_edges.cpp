// The wireframe view's edges: a segment between two window positions, one pixel wide.
#include <algorithm>
#include <cmath>

#include "teaching/teaching_hooks.h"

namespace glass::gl {
namespace {

// Steps along the segment once per pixel of its longer axis, marking the pixel that holds each
// point (pixel (i, j) covers [i, i + 1) x [j, j + 1)). Points on the window's right or top border
// (clipping puts edges there) are taken into the last column or row, so that such edges show.
void markSegment(TeachingCanvas& canvas, float x0, float y0, float x1, float y1) {
  const double dx = static_cast<double>(x1) - x0, dy = static_cast<double>(y1) - y0;
  const int steps = static_cast<int>(std::ceil(std::max(std::fabs(dx), std::fabs(dy)))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const int x = std::clamp(static_cast<int>(std::floor(x0 + dx * t)), 0, canvas.width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(y0 + dy * t)), 0, canvas.height - 1);
    const double px = x0 + dx * t, py = y0 + dy * t;
    if (px < 0.0 || py < 0.0 || px > canvas.width || py > canvas.height) continue;
    canvas.edges[static_cast<std::size_t>(y) * static_cast<std::size_t>(canvas.width) +
                 static_cast<std::size_t>(x)] = 1;
  }
}

}  // namespace

void markTriangleEdges(TeachingCanvas& canvas, const raster::WindowVertex& a,
                       const raster::WindowVertex& b, const raster::WindowVertex& c) {
  if (canvas.edges.empty()) return;
  markSegment(canvas, a.x, a.y, b.x, b.y);
  markSegment(canvas, b.x, b.y, c.x, c.y);
  markSegment(canvas, c.x, c.y, a.x, a.y);
}

}  // namespace glass::gl
