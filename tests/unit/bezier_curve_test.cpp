// Bezier curves: evaluation against the Bernstein form, subdivision, derivatives (quotient rule for
// rational curves), degree elevation, bounds.
#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/de_casteljau.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <vector>

using glass::geometry::BezierCurve;
using glass::geometry::binomial;

namespace {

// The rational Bernstein form, equation (13) generalised to degree n.
glm::dvec3 bernsteinPoint(const std::vector<glm::dvec3>& p, const std::vector<double>& w, double t) {
  const int n = static_cast<int>(p.size()) - 1;
  glm::dvec3 numerator(0.0);
  double denominator = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double b = binomial(n, i) * std::pow(t, i) * std::pow(1.0 - t, n - i);
    numerator += b * w[i] * p[i];
    denominator += b * w[i];
  }
  return numerator / denominator;
}

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

const std::vector<glm::dvec3> kQuintic = {{0, 0, 0}, {1, 2, -1}, {3, 3, 0.5}, {4, -1, 2}, {6, 1, 1}, {7, 0, -2}};
const std::vector<double> kQuinticWeights = {1.0, 2.5, 0.4, 1.7, 0.9, 1.2};

}  // namespace

TEST_CASE("bezier curve: de Casteljau agrees with the Bernstein form, integral and rational") {
  const BezierCurve integral(kQuintic);
  const BezierCurve rational(kQuintic, kQuinticWeights);
  const std::vector<double> ones(kQuintic.size(), 1.0);
  CHECK(integral.degree() == 5);
  CHECK_FALSE(integral.isRational());
  CHECK(rational.isRational());
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 100.0;
    CHECK(distance(integral.evaluate(t), bernsteinPoint(kQuintic, ones, t)) < 1e-12);
    CHECK(distance(rational.evaluate(t), bernsteinPoint(kQuintic, kQuinticWeights, t)) < 1e-12);
  }
  // End point interpolation, exactly.
  CHECK(rational.evaluate(0.0) == rational.controlPoint(0));
  CHECK(integral.evaluate(1.0) == kQuintic.back());
}

TEST_CASE("bezier curve: the study guide's quadratic and cubic formulas (10), (12)") {
  const std::vector<glm::dvec3> q = {{0, 0, 0}, {1, 2, 0}, {3, 0, 0}};
  const BezierCurve quadratic(q);
  const double t = 1.0 / 3.0;  // the t of Figure 2.5
  const glm::dvec3 formula = (1 - t) * (1 - t) * q[0] + 2 * (1 - t) * t * q[1] + t * t * q[2];
  CHECK(distance(quadratic.evaluate(t), formula) < 1e-15);
}

TEST_CASE("bezier curve: subdivision reproduces both halves") {
  const BezierCurve curve(kQuintic, kQuinticWeights);
  for (double split : {0.5, 0.3, 0.91}) {
    const auto [left, right] = curve.subdivide(split);
    CHECK(left.degree() == 5);
    for (int k = 0; k <= 20; ++k) {
      const double s = k / 20.0;
      CHECK(distance(left.evaluate(s), curve.evaluate(split * s)) < 1e-12);
      CHECK(distance(right.evaluate(s), curve.evaluate(split + (1 - split) * s)) < 1e-12);
    }
  }
  const BezierCurve middle = curve.segment(0.2, 0.7);
  for (int k = 0; k <= 20; ++k) {
    const double s = k / 20.0;
    CHECK(distance(middle.evaluate(s), curve.evaluate(0.2 + 0.5 * s)) < 1e-12);
  }
}

TEST_CASE("bezier curve: derivatives match finite differences, rational by the quotient rule") {
  const BezierCurve curve(kQuintic, kQuinticWeights);
  const double h = 1e-5;
  for (double t : {0.1, 0.37, 0.5, 0.8}) {
    const glm::dvec3 central = (curve.evaluate(t + h) - curve.evaluate(t - h)) / (2 * h);
    CHECK(distance(curve.derivative(t, 1), central) < 1e-6 * glm::length(central) + 1e-8);
    const glm::dvec3 second = (curve.evaluate(t + h) - 2.0 * curve.evaluate(t) + curve.evaluate(t - h)) / (h * h);
    CHECK(distance(curve.derivative(t, 2), second) < 1e-3 * glm::length(second) + 1e-4);
  }
  // Beyond the degree the derivative of an integral curve vanishes.
  const BezierCurve cubic(std::vector<glm::dvec3>{{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}});
  CHECK(glm::length(cubic.derivative(0.4, 4)) == 0.0);
}

TEST_CASE("bezier curve: quotient rule on the quarter circle gives the exact circle derivative") {
  // (1, 0), (1, 1), (0, 1) with weights 1, sqrt2/2, 1 is the quarter unit circle. Its speed is not
  // constant, but the derivative must be tangent to the circle, and the second derivative of a
  // circle satisfies p . p'' = -|p'|^2.
  const std::vector<glm::dvec3> p = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<double> w = {1.0, std::sqrt(2.0) / 2.0, 1.0};
  const BezierCurve arc(p, w);
  for (int k = 0; k <= 50; ++k) {
    const double t = k / 50.0;
    const auto d = arc.derivatives(t, 2);
    CHECK(std::abs(glm::length(d[0]) - 1.0) < 1e-14);
    CHECK(std::abs(glm::dot(d[0], d[1])) < 1e-13);
    CHECK(std::abs(glm::dot(d[0], d[2]) + glm::dot(d[1], d[1])) < 1e-12);
    CHECK(std::abs(arc.curvature(t) - 1.0) < 1e-12);
    // The principal normal of a circle points to its centre.
    CHECK(distance(arc.principalNormal(t), -d[0]) < 1e-12);
  }
  // At t = 0 the derivative is 2 w1 / w0 (P1 - P0) = sqrt2 (0, 1).
  CHECK(distance(arc.derivative(0.0), glm::dvec3(0, std::sqrt(2.0), 0)) < 1e-14);
}

TEST_CASE("bezier curve: degree elevation keeps the curve") {
  const BezierCurve curve(kQuintic, kQuinticWeights);
  BezierCurve raised = curve.elevated();
  CHECK(raised.degree() == 6);
  raised = raised.elevated().elevated();
  CHECK(raised.degree() == 8);
  for (int k = 0; k <= 40; ++k) {
    const double t = k / 40.0;
    CHECK(distance(raised.evaluate(t), curve.evaluate(t)) < 1e-12);
  }
}

TEST_CASE("bezier curve: the bounding box holds the curve, reversed runs backwards") {
  const BezierCurve curve(kQuintic, kQuinticWeights);
  const auto box = curve.bounds();
  const BezierCurve back = curve.reversed();
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    CHECK(box.contains(curve.evaluate(t), 1e-12));
    CHECK(distance(back.evaluate(t), curve.evaluate(1.0 - t)) < 1e-12);
  }
  CHECK(box.min.x == 0.0);
  CHECK(box.max.x == doctest::Approx(7.0).epsilon(1e-15));
  // A zero weight: the box can no longer be trusted.
  const BezierCurve half(std::vector<glm::dvec3>{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}, std::vector<double>{1, 0, 1});
  CHECK(std::isinf(half.bounds().max.x));
}

TEST_CASE("bezier curve: a homogeneous control point at infinity gives the half circle") {
  // Control "point" 1 is the direction (0, 1) with weight 0: the end tangents are parallel.
  const BezierCurve half = BezierCurve::fromHomogeneous({{1, 0, 0, 1}, {0, 1, 0, 0}, {-1, 0, 0, 1}});
  for (int k = 0; k <= 100; ++k) {
    const glm::dvec3 p = half.evaluate(k / 100.0);
    CHECK(std::abs(glm::length(p) - 1.0) < 1e-14);
    CHECK(p.y >= 0.0);
  }
  CHECK(distance(half.evaluate(0.5), glm::dvec3(0, 1, 0)) < 1e-15);
}

TEST_CASE("bezier curve: degenerate inputs do not crash") {
  const BezierCurve empty;
  CHECK(empty.degree() == -1);
  CHECK(empty.bounds().empty());
  const BezierCurve point(std::vector<glm::dvec3>{{1, 2, 3}});
  CHECK(point.evaluate(0.3) == glm::dvec3(1, 2, 3));
  CHECK(glm::length(point.derivative(0.3)) == 0.0);
  CHECK(point.tangent(0.3) == glm::dvec3(0.0));
}
