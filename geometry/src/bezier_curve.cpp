#include "glass/geometry/bezier_curve.h"

#include "glass/geometry/de_casteljau.h"
#include "rational_derivatives.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cassert>
#include <limits>

namespace glass::geometry {

BezierCurve::BezierCurve(std::span<const glm::dvec3> controlPoints) {
  homogeneous_.reserve(controlPoints.size());
  for (const glm::dvec3& p : controlPoints) homogeneous_.emplace_back(p, 1.0);
}

BezierCurve::BezierCurve(std::span<const glm::dvec3> controlPoints, std::span<const double> weights) {
  assert(controlPoints.size() == weights.size());
  const std::size_t count = std::min(controlPoints.size(), weights.size());
  homogeneous_.reserve(count);
  for (std::size_t i = 0; i < count; ++i) homogeneous_.emplace_back(weights[i] * controlPoints[i], weights[i]);
}

BezierCurve BezierCurve::fromHomogeneous(std::vector<glm::dvec4> homogeneous) {
  BezierCurve curve;
  curve.homogeneous_ = std::move(homogeneous);
  return curve;
}

bool BezierCurve::isRational() const {
  return std::any_of(homogeneous_.begin(), homogeneous_.end(), [](const glm::dvec4& h) { return h.w != 1.0; });
}

bool BezierCurve::hasPositiveWeights() const {
  return std::all_of(homogeneous_.begin(), homogeneous_.end(), [](const glm::dvec4& h) { return h.w > 0.0; });
}

glm::dvec3 BezierCurve::controlPoint(std::size_t i) const {
  const glm::dvec4& h = homogeneous_[i];
  return h.w == 0.0 ? glm::dvec3(h) : glm::dvec3(h) / h.w;
}

glm::dvec4 BezierCurve::evaluateHomogeneous(double t) const {
  return deCasteljau(std::span<const glm::dvec4>(homogeneous_), t);
}

glm::dvec3 BezierCurve::evaluate(double t) const {
  const glm::dvec4 h = evaluateHomogeneous(t);
  return glm::dvec3(h) / h.w;
}

std::vector<glm::dvec3> BezierCurve::derivatives(double t, int maxOrder) const {
  std::vector<glm::dvec4> homogeneousDerivatives(static_cast<std::size_t>(maxOrder) + 1);
  for (int k = 0; k <= maxOrder; ++k)
    homogeneousDerivatives[k] = deCasteljauDerivative(std::span<const glm::dvec4>(homogeneous_), t, k);
  return detail::projectDerivatives(homogeneousDerivatives);
}

glm::dvec3 BezierCurve::derivative(double t, int order) const { return derivatives(t, order)[order]; }

glm::dvec3 BezierCurve::tangent(double t) const {
  const glm::dvec3 d = derivative(t, 1);
  const double length = glm::length(d);
  return length > 0.0 ? d / length : glm::dvec3(0.0);
}

glm::dvec3 BezierCurve::principalNormal(double t) const {
  const std::vector<glm::dvec3> d = derivatives(t, 2);
  const glm::dvec3 binormal = glm::cross(d[1], d[2]);
  // Relative test: the cross product of two parallel derivatives is rounding noise.
  if (glm::length(binormal) <= 1e-12 * glm::length(d[1]) * glm::length(d[2])) return glm::dvec3(0.0);
  const glm::dvec3 n = glm::cross(binormal, d[1]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

double BezierCurve::curvature(double t) const {
  const std::vector<glm::dvec3> d = derivatives(t, 2);
  const double speed = glm::length(d[1]);
  if (speed == 0.0) return std::numeric_limits<double>::infinity();
  return glm::length(glm::cross(d[1], d[2])) / (speed * speed * speed);
}

std::pair<BezierCurve, BezierCurve> BezierCurve::subdivide(double t) const {
  auto [left, right] = deCasteljauSplit(std::span<const glm::dvec4>(homogeneous_), t);
  return {fromHomogeneous(std::move(left)), fromHomogeneous(std::move(right))};
}

BezierCurve BezierCurve::segment(double t0, double t1) const {
  // Cut at t1, then cut the left piece at t0 / t1 (where t0 lands after the first cut).
  BezierCurve left = t1 < 1.0 ? subdivide(t1).first : *this;
  if (t0 <= 0.0) return left;
  const double local = t1 > 0.0 ? t0 / t1 : 0.0;
  return left.subdivide(local).second;
}

BezierCurve BezierCurve::elevated() const {
  return fromHomogeneous(elevateDegree(std::span<const glm::dvec4>(homogeneous_)));
}

BezierCurve BezierCurve::reversed() const {
  return fromHomogeneous(std::vector<glm::dvec4>(homogeneous_.rbegin(), homogeneous_.rend()));
}

AxisAlignedBox BezierCurve::bounds() const {
  AxisAlignedBox box;
  if (!hasPositiveWeights()) {
    const double inf = std::numeric_limits<double>::infinity();
    box.min = glm::dvec3(-inf);
    box.max = glm::dvec3(inf);
    return box;
  }
  for (std::size_t i = 0; i < homogeneous_.size(); ++i) box.include(controlPoint(i));
  return box;
}

}  // namespace glass::geometry
