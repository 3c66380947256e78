#include "primitive/polygon_offset.h"

#include <algorithm>
#include <cmath>

namespace glass::gl {

namespace {

double doubleArea(const raster::WindowVertex& a, const raster::WindowVertex& b,
                  const raster::WindowVertex& c) {
  return (static_cast<double>(b.x) - a.x) * (static_cast<double>(c.y) - a.y) -
         (static_cast<double>(c.x) - a.x) * (static_cast<double>(b.y) - a.y);
}

}  // namespace

double maxDepthSlope(const raster::WindowVertex& a, const raster::WindowVertex& b,
                     const raster::WindowVertex& c) {
  const double area = doubleArea(a, b, c);
  if (area == 0.0) return 0.0;
  const double x1 = static_cast<double>(b.x) - a.x, y1 = static_cast<double>(b.y) - a.y;
  const double x2 = static_cast<double>(c.x) - a.x, y2 = static_cast<double>(c.y) - a.y;
  const double z1 = static_cast<double>(b.z) - a.z, z2 = static_cast<double>(c.z) - a.z;
  // The plane z = z_a + dzdx (x - x_a) + dzdy (y - y_a) through the three vertices.
  const double dzdx = (z1 * y2 - z2 * y1) / area;
  const double dzdy = (x1 * z2 - x2 * z1) / area;
  return std::max(std::fabs(dzdx), std::fabs(dzdy));
}

double polygonOffset(float factor, float units, const raster::WindowVertex* v, int count) {
  double slope = 0.0;
  double largestArea = 0.0;
  for (int i = 1; i + 1 < count; ++i) {
    const double area = std::fabs(doubleArea(v[0], v[i], v[i + 1]));
    if (area > largestArea) {
      largestArea = area;
      slope = maxDepthSlope(v[0], v[i], v[i + 1]);
    }
  }
  return slope * factor + kMinimumResolvableDepth * units;
}

}  // namespace glass::gl
