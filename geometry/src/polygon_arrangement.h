// Step 1 of polygon tessellation (glass/geometry/polygon_tessellation.h): the planar graph of a
// polygon's contours, with coincident vertices merged and crossing edges split.
#pragma once

#include <vector>

#include "glass/geometry/polygon_tessellation.h"

namespace glass::geometry {

// An edge of the graph between two distinct vertices, from < to. `count` is the number of
// contour edges running from `from` to `to`, minus those running from `to` to `from`; edges whose
// count is 0 are left out (the winding number is the same on both sides).
struct ArrangementEdge {
  int from = 0;
  int to = 0;
  int count = 0;
};

struct PolygonArrangement {
  std::vector<PlanarPoint> points;      // input vertices, then created ones
  std::vector<CreatedVertex> created;   // created[i] is vertex inputCount + i
  std::vector<ArrangementEdge> edges;
};

PolygonArrangement arrangeContours(const std::vector<std::vector<PlanarPoint>>& contours);

// Twice the signed area of triangle (a, b, c): positive when counter-clockwise.
inline double orientation(const PlanarPoint& a, const PlanarPoint& b, const PlanarPoint& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace glass::geometry
