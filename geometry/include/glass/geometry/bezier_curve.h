// Bezier curves of any degree, integral or rational (study guide, section 2.4).
//
// A rational curve is stored by its homogeneous control points H(i) = (w(i) p(i), w(i)): the
// numerator and the denominator of equation (13) are then one integral curve in 4D, and de
// Casteljau, subdivision and degree elevation work on it unchanged. The point of the curve is the
// projection p(t) = H(t).xyz / H(t).w. An integral curve is the case of all weights 1 (dividing by 1
// is exact, so it evaluates to the same bits as the polynomial form).
#pragma once

#include "glass/geometry/axis_aligned_box.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace glass::geometry {

class BezierCurve {
 public:
  BezierCurve() = default;
  // An integral curve: all weights 1.
  explicit BezierCurve(std::span<const glm::dvec3> controlPoints);
  // A rational curve: control point i carries weights[i], H(i) = (w(i) p(i), w(i)) as in equation
  // (13); a weight 0 drops its point from both sums.
  BezierCurve(std::span<const glm::dvec3> controlPoints, std::span<const double> weights);
  // From homogeneous control points (w x, w y, w z, w). A point with w = 0 is a direction (a point
  // at infinity), as in the half circle (1, 0, 0, 1), (0, 1, 0, 0), (-1, 0, 0, 1).
  static BezierCurve fromHomogeneous(std::vector<glm::dvec4> homogeneous);

  // -1 for the empty curve.
  int degree() const { return static_cast<int>(homogeneous_.size()) - 1; }
  std::size_t controlPointCount() const { return homogeneous_.size(); }
  // Some weight differs from 1.
  bool isRational() const;
  // Every weight is positive: then the curve lies in the convex hull of its control points.
  bool hasPositiveWeights() const;

  // The control point in 3D (H.xyz / H.w); for weight 0 the direction H.xyz.
  glm::dvec3 controlPoint(std::size_t i) const;
  double weight(std::size_t i) const { return homogeneous_[i].w; }
  std::span<const glm::dvec4> homogeneousControlPoints() const { return homogeneous_; }

  glm::dvec4 evaluateHomogeneous(double t) const;
  glm::dvec3 evaluate(double t) const;
  // The derivative of the projected point p(t) of the given order (0 gives the point). For a
  // rational curve this is the quotient rule, in its general form from Leibniz's rule on
  // H = w p:  p^(k) = (H.xyz^(k) - sum_{i=1..k} C(k, i) w^(i) p^(k-i)) / w.
  glm::dvec3 derivative(double t, int order = 1) const;
  // p, p', ..., p^(maxOrder) at t.
  std::vector<glm::dvec3> derivatives(double t, int maxOrder) const;
  // The unit tangent, or the zero vector where the first derivative vanishes.
  glm::dvec3 tangent(double t) const;
  // The unit principal normal (p' x p'') x p', pointing to the centre of curvature; the zero vector
  // where the curvature vanishes (straight pieces) or the tangent is undefined.
  glm::dvec3 principalNormal(double t) const;
  // |p' x p''| / |p'|^3.
  double curvature(double t) const;

  // The pieces on [0, t] and [t, 1], each parametrised by [0, 1].
  std::pair<BezierCurve, BezierCurve> subdivide(double t) const;
  // The piece on [t0, t1] (t0 < t1), parametrised by [0, 1].
  BezierCurve segment(double t0, double t1) const;
  // The same curve with degree + 1.
  BezierCurve elevated() const;
  // The same point set traversed from t = 1 to t = 0.
  BezierCurve reversed() const;
  // The box around the control points, which holds the curve when all weights are positive (the
  // convex hull property). With a weight <= 0 the curve can leave that hull, and the box is
  // unbounded (all infinite).
  AxisAlignedBox bounds() const;

 private:
  std::vector<glm::dvec4> homogeneous_;
};

}  // namespace glass::geometry
