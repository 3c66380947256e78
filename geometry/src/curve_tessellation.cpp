// Polylines from Bezier curves, uniform or by recursive halving until flat.
#include "glass/geometry/tessellation.h"

#include "flatness.h"

#include <algorithm>

namespace glass::geometry {
namespace {

// Appends the end points of the flat pieces of the curve on [t0, t1] (the start point is already
// in the polyline). The end of a piece is its last control point, the curve point at t1.
void halveUntilFlat(const BezierCurve& piece, double t0, double t1, int depth, const AdaptiveOptions& options,
                    Polyline& polyline) {
  if (depth >= options.maxDepth || detail::isFlatEnough(piece, options)) {
    polyline.points.push_back(piece.evaluate(1.0));
    polyline.parameters.push_back(t1);
    return;
  }
  const double middle = 0.5 * (t0 + t1);
  const auto [left, right] = piece.subdivide(0.5);
  halveUntilFlat(left, t0, middle, depth + 1, options, polyline);
  halveUntilFlat(right, middle, t1, depth + 1, options, polyline);
}

}  // namespace

Polyline tessellateUniform(const BezierCurve& curve, int segments) {
  Polyline polyline;
  if (segments < 1 || curve.controlPointCount() == 0) return polyline;
  for (int i = 0; i <= segments; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(segments);
    polyline.points.push_back(curve.evaluate(t));
    polyline.parameters.push_back(t);
  }
  return polyline;
}

Polyline tessellateAdaptive(const BezierCurve& curve, const AdaptiveOptions& requested) {
  Polyline polyline;
  if (curve.controlPointCount() == 0) return polyline;
  AdaptiveOptions options = requested;
  options.maxDepth = std::clamp(options.maxDepth, 0, 30);
  polyline.points.push_back(curve.evaluate(0.0));
  polyline.parameters.push_back(0.0);
  halveUntilFlat(curve, 0.0, 1.0, 0, options, polyline);
  return polyline;
}

}  // namespace glass::geometry
