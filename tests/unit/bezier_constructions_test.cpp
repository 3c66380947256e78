// The course's constructions: every sampled point lies on the exact conic or quadric within 1e-9,
// and the pieces cover the intended parameter ranges.
#include "glass/geometry/bezier_constructions.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace geo = glass::geometry;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kExact = 1e-9;
constexpr int kSamples = 64;

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

// Samples (u, v) on a (kSamples + 1)^2 grid.
template <class Check>
void forSamples(Check check) {
  for (int a = 0; a <= kSamples; ++a)
    for (int b = 0; b <= kSamples; ++b) check(a / double(kSamples), b / double(kSamples));
}

// The angle of (x, y) in [lo - slack, hi + slack] (angles continued past pi when needed).
bool angleWithin(double x, double y, double lo, double hi) {
  double angle = std::atan2(y, x);
  while (angle < lo - 1e-9) angle += 2 * kPi;
  return angle <= hi + 1e-9;
}

}  // namespace

TEST_CASE("constructions: the exam's arc 0 <= alpha <= 2 pi / 3 of the unit circle") {
  const geo::BezierCurve arc = geo::circularArc(0.0, 2 * kPi / 3);
  REQUIRE(arc.degree() == 2);
  CHECK(distance(arc.controlPoint(0), {1, 0, 0}) < 1e-15);
  CHECK(distance(arc.controlPoint(1), {1, std::sqrt(3.0), 0}) < 1e-14);
  CHECK(distance(arc.controlPoint(2), {-0.5, std::sqrt(3.0) / 2, 0}) < 1e-15);
  CHECK(arc.weight(0) == 1.0);
  CHECK(std::abs(arc.weight(1) - 0.5) < 1e-15);
  CHECK(arc.weight(2) == 1.0);
  for (int k = 0; k <= 1000; ++k) {
    const glm::dvec3 p = arc.evaluate(k / 1000.0);
    CHECK(std::abs(glm::length(p) - 1.0) < kExact);
    CHECK(p.z == 0.0);
    CHECK(angleWithin(p.x, p.y, 0.0, 2 * kPi / 3));
  }
  // The middle of the parameter range is the middle of the arc (the standard form is symmetric).
  CHECK(distance(arc.evaluate(0.5), {std::cos(kPi / 3), std::sin(kPi / 3), 0}) < kExact);
}

TEST_CASE("constructions: arcs of any angle below 180 degrees, anywhere in space") {
  geo::CirclePlacement circle;
  circle.center = {1, -2, 3};
  circle.radius = 2.5;
  circle.xAxis = glm::normalize(glm::dvec3(1, 1, 0));
  circle.yAxis = glm::normalize(glm::dvec3(-1, 1, 1));
  circle.yAxis = glm::normalize(circle.yAxis - glm::dot(circle.yAxis, circle.xAxis) * circle.xAxis);
  const glm::dvec3 normal = glm::cross(circle.xAxis, circle.yAxis);
  for (double span : {0.01, 0.5, 1.0, 2.0, 3.0, 3.14}) {
    const double start = -0.7;
    const geo::BezierCurve arc = geo::circularArc(start, start + span, circle);
    CHECK(arc.hasPositiveWeights());
    for (int k = 0; k <= 200; ++k) {
      const glm::dvec3 d = arc.evaluate(k / 200.0) - circle.center;
      CHECK(std::abs(glm::length(d) - circle.radius) < kExact);
      CHECK(std::abs(glm::dot(d, normal)) < kExact);
      CHECK(angleWithin(glm::dot(d, circle.xAxis), glm::dot(d, circle.yAxis), start, start + span));
    }
    CHECK(distance(arc.evaluate(1.0) - circle.center,
                   circle.radius * (std::cos(start + span) * circle.xAxis + std::sin(start + span) * circle.yAxis)) < kExact);
  }
}

TEST_CASE("constructions: a full circle from arcs") {
  for (int count : {3, 4, 7}) {
    const std::vector<geo::BezierCurve> arcs = geo::fullCircle(count);
    REQUIRE(arcs.size() == std::size_t(count));
    for (int a = 0; a < count; ++a) {
      // Consecutive arcs meet, the last closes the circle.
      CHECK(distance(arcs[a].evaluate(1.0), arcs[(a + 1) % count].evaluate(0.0)) < kExact);
      // The tangents agree where they meet (G1).
      CHECK(distance(arcs[a].tangent(1.0), arcs[(a + 1) % count].tangent(0.0)) < kExact);
      for (int k = 0; k <= 200; ++k) CHECK(std::abs(glm::length(arcs[a].evaluate(k / 200.0)) - 1.0) < kExact);
    }
  }
  CHECK(geo::fullCircle(2).empty());
}

TEST_CASE("constructions: the rational quadratic's middle weight picks the conic (Figure 2.6)") {
  // Standard form with P0 = (-1, 0), P1 = (0, 1), P2 = (1, 0): w = 1 is the parabola
  // y = (1 - x^2) / 2.
  const geo::BezierCurve parabola = geo::rationalQuadratic({-1, 0, 0}, {0, 1, 0}, {1, 0, 0}, 1.0);
  for (int k = 0; k <= 100; ++k) {
    const glm::dvec3 p = parabola.evaluate(k / 100.0);
    CHECK(std::abs(p.y - (1 - p.x * p.x) / 2) < kExact);
  }
  // The curve point at t = 1/2 moves towards P1 as the weight grows: w / (1 + w) of the way from
  // the chord's middle.
  for (double w : {0.0, 0.25, 0.5, 1.0, 2.0, 5.0}) {
    const geo::BezierCurve c = geo::rationalQuadratic({-1, 0, 0}, {0, 1, 0}, {1, 0, 0}, w);
    CHECK(std::abs(c.evaluate(0.5).y - w / (1 + w)) < kExact);
  }
}

TEST_CASE("constructions: the exam's curvilinear triangle, bi-degree (1, 2)") {
  const geo::BezierSurface triangle = geo::curvilinearTriangle();
  CHECK(triangle.degreeU() == 1);
  CHECK(triangle.degreeV() == 2);
  forSamples([&](double u, double v) {
    const glm::dvec3 p = triangle.evaluate(u, v);
    CHECK(p.z == 0.0);
    CHECK(p.x <= 1.0 + kExact);
    CHECK(p.y <= 1.0 + kExact);
    CHECK(p.x * p.x + p.y * p.y >= 1.0 - kExact);
    CHECK(p.x >= -kExact);
    CHECK(p.y >= -kExact);
    // Each point is on the segment from its arc point to the corner (1, 1).
    const glm::dvec3 c = triangle.evaluate(0.0, v);
    CHECK(distance(p, (1 - u) * c + u * glm::dvec3(1, 1, 0)) < kExact);
  });
  for (int k = 0; k <= kSamples; ++k) {
    const double t = k / double(kSamples);
    CHECK(std::abs(glm::length(triangle.evaluate(0.0, t)) - 1.0) < kExact);  // the arc
    CHECK(std::abs(triangle.evaluate(t, 0.0).x - 1.0) < kExact);              // on x = 1
    CHECK(std::abs(triangle.evaluate(t, 1.0).y - 1.0) < kExact);              // on y = 1
    CHECK(distance(triangle.evaluate(1.0, t), {1, 1, 0}) < kExact);          // the corner
  }
  // The sides are the whole segments: from (1, 0) and (0, 1) to the corner.
  CHECK(distance(triangle.evaluate(0, 0), {1, 0, 0}) < kExact);
  CHECK(distance(triangle.evaluate(0, 1), {0, 1, 0}) < kExact);
  // The patch covers the region: points of the region are hit (the ray from (1, 1) through the
  // point meets the arc at parameter v, and u follows).
  for (const glm::dvec3 q : {glm::dvec3(0.9, 0.9, 0), glm::dvec3(0.99, 0.3, 0), glm::dvec3(0.5, 0.95, 0)}) {
    bool found = false;
    for (int a = 0; a <= 400 && !found; ++a)
      for (int b = 0; b <= 400 && !found; ++b) found = distance(triangle.evaluate(a / 400.0, b / 400.0), q) < 0.01;
    CHECK(found);
  }
  // The normal is +z inside.
  CHECK(distance(triangle.normal(0.5, 0.5), {0, 0, 1}) < 1e-12);
}

TEST_CASE("constructions: cylinder and cone patches") {
  for (auto [start, end] : {std::pair{0.0, kPi / 2}, std::pair{-1.0, 2.0}}) {
    const geo::BezierSurface cylinder = geo::cylinderPatch(1.5, 3.0, start, end);
    const geo::BezierSurface cone = geo::conePatch(2.0, 4.0, start, end);
    forSamples([&](double u, double v) {
      const glm::dvec3 p = cylinder.evaluate(u, v);
      CHECK(std::abs(std::hypot(p.x, p.y) - 1.5) < kExact);
      CHECK(std::abs(p.z - 3.0 * v) < kExact);
      CHECK(angleWithin(p.x, p.y, start, end));
      // The outward normal of a cylinder is horizontal and radial.
      CHECK(distance(cylinder.normal(u, v), glm::dvec3(p.x / 1.5, p.y / 1.5, 0)) < 1e-9);
      const glm::dvec3 q = cone.evaluate(u, v);
      CHECK(std::abs(std::hypot(q.x, q.y) - 2.0 * (1 - q.z / 4.0)) < kExact);
      CHECK(q.z >= -kExact);
      CHECK(q.z <= 4.0 + kExact);
    });
  }
}

TEST_CASE("constructions: sphere patches and the whole sphere") {
  const geo::BezierSurface patch = geo::spherePatch(3.0, 0.2, 1.9, -1.2, 0.4);
  forSamples([&](double u, double v) {
    const glm::dvec3 p = patch.evaluate(u, v);
    CHECK(std::abs(glm::length(p) - 3.0) < kExact);
    CHECK(angleWithin(p.x, p.y, 0.2, 1.9));
    const double latitude = std::asin(p.z / 3.0);
    CHECK(latitude >= -1.2 - kExact);
    CHECK(latitude <= 0.4 + kExact);
    CHECK(distance(patch.normal(u, v), p / 3.0) < 1e-9);
  });
  const std::vector<geo::BezierSurface> sphere = geo::spherePatches(1.0);
  CHECK(sphere.size() == 8);
  for (const auto& s : sphere) forSamples([&](double u, double v) { CHECK(std::abs(glm::length(s.evaluate(u, v)) - 1.0) < kExact); });
}

namespace {

// The exam torus: x = (R + r cos t) sin f, y = r sin t, z = (R + r cos t) cos f, so
// (sqrt(x^2 + z^2) - R)^2 + y^2 = r^2.
double torusResidual(const glm::dvec3& p, double R, double r) {
  const double rho = std::hypot(p.x, p.z);
  return std::hypot(rho - R, p.y) - r;
}

}  // namespace

TEST_CASE("constructions: the exam's 1/16 torus (x >= 0, y <= 0, z >= 0) as a rational biquadratic") {
  const double R = 3.0, r = 1.0;
  const double s = std::sqrt(2.0) / 2.0;
  const geo::BezierSurface outer = geo::torusSixteenth(R, r);
  REQUIRE(outer.degreeU() == 2);
  REQUIRE(outer.degreeV() == 2);
  // The control net and weights printed by `glass math torus-patch` (see the header).
  const glm::dvec3 expected[3][3] = {{{0, -r, R}, {0, -r, R + r}, {0, 0, R + r}},
                                     {{R, -r, R}, {R + r, -r, R + r}, {R + r, 0, R + r}},
                                     {{R, -r, 0}, {R + r, -r, 0}, {R + r, 0, 0}}};
  const double weights[3][3] = {{1, s, 1}, {s, 0.5, s}, {1, s, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      CHECK(distance(outer.controlPoint(i, j), expected[i][j]) < 1e-14);
      CHECK(std::abs(outer.weight(i, j) - weights[i][j]) < 1e-15);
    }
  const geo::BezierSurface inner = geo::torusSixteenth(R, r, geo::TorusSixteenth::Inner);
  forSamples([&](double u, double v) {
    for (const geo::BezierSurface* patch : {&outer, &inner}) {
      const glm::dvec3 p = patch->evaluate(u, v);
      CHECK(std::abs(torusResidual(p, R, r)) < kExact);
      CHECK(p.x >= -kExact);
      CHECK(p.y <= kExact);
      CHECK(p.z >= -kExact);
    }
    // The outer piece is outside the circle of tube centres, the inner one inside.
    CHECK(std::hypot(outer.evaluate(u, v).x, outer.evaluate(u, v).z) >= R - kExact);
    CHECK(std::hypot(inner.evaluate(u, v).x, inner.evaluate(u, v).z) <= R + kExact);
  });
  // The corners are the corners of the region; the two pieces share the edge at theta = -pi/2.
  CHECK(distance(outer.evaluate(0, 1), {0, 0, R + r}) < kExact);
  CHECK(distance(outer.evaluate(1, 1), {R + r, 0, 0}) < kExact);
  CHECK(distance(inner.evaluate(0, 0), {0, 0, R - r}) < kExact);
  for (int k = 0; k <= 10; ++k) CHECK(distance(outer.evaluate(k / 10.0, 0.0), inner.evaluate(k / 10.0, 1.0)) < kExact);
  // Normals point out of the tube: away from the tube's centre circle.
  const glm::dvec3 p = outer.evaluate(0.5, 0.5);
  const glm::dvec3 centre = R * glm::normalize(glm::dvec3(p.x, 0, p.z));
  CHECK(distance(outer.normal(0.5, 0.5), glm::normalize(p - centre)) < 1e-9);
}

TEST_CASE("constructions: the whole torus from sixteen patches") {
  const double R = 2.0, r = 0.5;
  const std::vector<geo::BezierSurface> torus = geo::torusPatches(R, r);
  REQUIRE(torus.size() == 16);
  for (const auto& patch : torus)
    forSamples([&](double u, double v) { CHECK(std::abs(torusResidual(patch.evaluate(u, v), R, r)) < kExact); });
  // Neighbours in phi and in theta share their edges.
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l) {
      const auto& patch = torus[4 * k + l];
      const auto& nextPhi = torus[4 * ((k + 1) % 4) + l];
      const auto& nextTheta = torus[4 * k + (l + 1) % 4];
      for (int t = 0; t <= 8; ++t) {
        CHECK(distance(patch.evaluate(1.0, t / 8.0), nextPhi.evaluate(0.0, t / 8.0)) < kExact);
        CHECK(distance(patch.evaluate(t / 8.0, 1.0), nextTheta.evaluate(t / 8.0, 0.0)) < kExact);
      }
    }
}
