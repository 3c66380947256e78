// NURBS curves and surfaces split into their Bezier pieces by knot insertion (Boehm's
// algorithm): every distinct knot of the valid parameter range is inserted until it has
// multiplicity equal to the order, after which the control points of each knot span are the
// Bezier control points of the piece over that span. The control points are kept as they are
// given, homogeneous or not, with any number of coordinates: knot insertion is linear, so a
// rational curve's homogeneous points (w x, w y, w z, w) split the same way.
//
// GLU's NURBS renderer (pipeline/src/glu/nurbs_*.cpp) draws the pieces with the GL evaluators.
#pragma once

#include <span>
#include <vector>

namespace glass::geometry {

// What is wrong with a knot vector, in the order GLU checks (GLU_NURBS_ERROR1 to 5).
enum class KnotVectorError {
  None,
  UnsupportedOrder,      // order < 2 or above kMaxNurbsOrder
  TooFewKnots,           // fewer than 2 * order knots
  EmptyRange,            // knot[order - 1] == knot[count - order]: nothing to draw
  Decreasing,            // knot[i + 1] < knot[i]
  MultiplicityTooHigh,   // a knot repeated more than order times
};

inline constexpr int kMaxNurbsOrder = 24;

KnotVectorError checkKnotVector(int order, std::span<const float> knots);

// One Bezier piece of a curve over [u0, u1]: `order` points of `dimension` coordinates each.
struct BezierCurvePiece {
  double u0 = 0.0;
  double u1 = 0.0;
  std::vector<double> points;
};

// The pieces of a B-spline curve with `knots.size() - order` control points of `dimension`
// coordinates, point k at points[k * dimension]. The knot vector must pass checkKnotVector.
// `extraBreakpoints` inside the valid range split the pieces further (so that curves with
// different knots over the same range split at the same parameters).
std::vector<BezierCurvePiece> bezierPiecesOfCurve(int order, std::span<const float> knots,
                                                  int dimension, std::span<const double> points,
                                                  std::span<const double> extraBreakpoints = {});

// One Bezier piece of a tensor-product surface over [u0, u1] x [v0, v1]: uOrder x vOrder points
// of `dimension` coordinates, point (i, j) (i along u) at points[(i * vOrder + j) * dimension].
struct BezierSurfacePiece {
  double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
  std::vector<double> points;
};

// The pieces of a B-spline surface whose control point (i, j) is at
// points[(i * vCount + j) * dimension], vCount = vKnots.size() - vOrder. Pieces are listed with u
// as the outer index.
std::vector<BezierSurfacePiece> bezierPiecesOfSurface(
    int uOrder, std::span<const float> uKnots, int vOrder, std::span<const float> vKnots,
    int dimension, std::span<const double> points, std::span<const double> extraUBreakpoints = {},
    std::span<const double> extraVBreakpoints = {});

// The distinct knots of the valid range [knots[order - 1], knots[count - order]].
std::vector<double> breakpointsOf(int order, std::span<const float> knots);

}  // namespace glass::geometry
