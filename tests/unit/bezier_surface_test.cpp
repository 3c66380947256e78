// Bezier patches: evaluation, partial derivatives (quotient rule), normals including collapsed
// rows, subdivision, degree elevation, iso-curves and bounds.
#include "glass/geometry/bezier_constructions.h"
#include "glass/geometry/bezier_surface.h"
#include "glass/geometry/de_casteljau.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using glass::geometry::BezierSurface;
using glass::geometry::PatchSide;
using glass::geometry::binomial;

namespace {

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

// A bi-degree (2, 3) rational patch with a wavy net and uneven weights.
BezierSurface wavyPatch() {
  std::vector<glm::dvec3> points;
  std::vector<double> weights;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 3; ++j) {
      points.emplace_back(i, j, std::sin(1.3 * i + 0.7 * j));
      weights.push_back(1.0 + 0.3 * ((i * 5 + j * 3) % 4));
    }
  return BezierSurface(2, 3, points, weights);
}

glm::dvec3 bernsteinPoint(const BezierSurface& s, double u, double v) {
  glm::dvec4 sum(0.0);
  for (int i = 0; i <= s.degreeU(); ++i)
    for (int j = 0; j <= s.degreeV(); ++j) {
      const double b = binomial(s.degreeU(), i) * std::pow(u, i) * std::pow(1 - u, s.degreeU() - i) *
                       binomial(s.degreeV(), j) * std::pow(v, j) * std::pow(1 - v, s.degreeV() - j);
      sum += b * s.homogeneousControlPoint(i, j);
    }
  return glm::dvec3(sum) / sum.w;
}

}  // namespace

TEST_CASE("bezier surface: tensor-product de Casteljau agrees with the Bernstein form") {
  const BezierSurface s = wavyPatch();
  CHECK(s.isRational());
  CHECK(s.degreeU() == 2);
  CHECK(s.degreeV() == 3);
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) CHECK(distance(s.evaluate(a / 10.0, b / 10.0), bernsteinPoint(s, a / 10.0, b / 10.0)) < 1e-12);
  CHECK(s.evaluate(0, 0) == s.controlPoint(0, 0));
  CHECK(distance(s.evaluate(1, 1), s.controlPoint(2, 3)) < 1e-15);
}

TEST_CASE("bezier surface: partial derivatives match finite differences") {
  const BezierSurface s = wavyPatch();
  const double h = 1e-5;
  for (double u : {0.2, 0.5, 0.75})
    for (double v : {0.1, 0.6}) {
      const glm::dvec3 du = (s.evaluate(u + h, v) - s.evaluate(u - h, v)) / (2 * h);
      const glm::dvec3 dv = (s.evaluate(u, v + h) - s.evaluate(u, v - h)) / (2 * h);
      const glm::dvec3 duv = (s.evaluate(u + h, v + h) - s.evaluate(u + h, v - h) - s.evaluate(u - h, v + h) +
                              s.evaluate(u - h, v - h)) / (4 * h * h);
      CHECK(distance(s.derivative(u, v, 1, 0), du) < 1e-6);
      CHECK(distance(s.derivative(u, v, 0, 1), dv) < 1e-6);
      CHECK(distance(s.derivative(u, v, 1, 1), duv) < 1e-3);
      const auto frame = s.frame(u, v);
      CHECK(distance(frame.normal, glm::normalize(glm::cross(du, dv))) < 1e-6);
      CHECK(distance(frame.du, du) < 1e-6);
    }
}

TEST_CASE("bezier surface: normals at collapsed rows are the limit from inside") {
  // Sphere octant: u = longitude, v = latitude 0..pi/2; the row v = 1 collapses to the north pole,
  // with a rational net whose homogeneous points differ there.
  const double pi = std::numbers::pi;
  const BezierSurface octant = glass::geometry::spherePatch(2.0, 0.0, pi / 2, 0.0, pi / 2);
  for (double u : {0.0, 0.3, 1.0}) {
    CHECK(distance(octant.evaluate(u, 1.0), glm::dvec3(0, 0, 2)) < 1e-14);
    CHECK(distance(octant.normal(u, 1.0), glm::dvec3(0, 0, 1)) < 1e-9);
  }
  // Everywhere else the normal of a sphere is p / |p|.
  for (double u : {0.0, 0.5, 1.0})
    for (double v : {0.0, 0.5, 0.99}) {
      const glm::dvec3 p = octant.evaluate(u, v);
      CHECK(distance(octant.normal(u, v), p / 2.0) < 1e-9);
    }
  // The cone's apex: the normal is the limit along each generator, (h cos a, h sin a, r) / |.|.
  const BezierSurface cone = glass::geometry::conePatch(1.0, 2.0, 0.0, pi / 2);
  for (double u : {0.0, 0.4, 1.0}) {
    const glm::dvec3 base = cone.evaluate(u, 0.0);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(2.0 * base.x, 2.0 * base.y, 1.0));
    CHECK(distance(cone.normal(u, 1.0), expected) < 1e-9);
    CHECK(distance(cone.normal(u, 0.5), expected) < 1e-9);
  }
  // An integral patch with a collapsed row u = 0 (all points at the origin).
  std::vector<glm::dvec3> fan;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) fan.emplace_back(i == 0 ? glm::dvec3(0.0) : glm::dvec3(i, j - 1.0, 0.1 * i * i));
  const BezierSurface apex(2, 2, fan);
  const glm::dvec3 limit = apex.normal(0.0, 0.5);
  CHECK(std::abs(glm::length(limit) - 1.0) < 1e-12);
  CHECK(distance(limit, apex.normal(1e-6, 0.5)) < 1e-5);
}

TEST_CASE("bezier surface: subdivision, pieces and degree elevation keep the surface") {
  const BezierSurface s = wavyPatch();
  const auto [low, high] = s.subdivideU(0.4);
  const auto [near, far] = s.subdivideV(0.7);
  const BezierSurface piece = s.piece(0.25, 0.5, 0.1, 0.9);
  const BezierSurface raised = s.elevatedU().elevatedV().elevatedV();
  CHECK(raised.degreeU() == 3);
  CHECK(raised.degreeV() == 5);
  for (int a = 0; a <= 8; ++a)
    for (int b = 0; b <= 8; ++b) {
      const double u = a / 8.0, v = b / 8.0;
      CHECK(distance(low.evaluate(u, v), s.evaluate(0.4 * u, v)) < 1e-12);
      CHECK(distance(high.evaluate(u, v), s.evaluate(0.4 + 0.6 * u, v)) < 1e-12);
      CHECK(distance(near.evaluate(u, v), s.evaluate(u, 0.7 * v)) < 1e-12);
      CHECK(distance(far.evaluate(u, v), s.evaluate(u, 0.7 + 0.3 * v)) < 1e-12);
      CHECK(distance(piece.evaluate(u, v), s.evaluate(0.25 + 0.25 * u, 0.1 + 0.8 * v)) < 1e-12);
      CHECK(distance(raised.evaluate(u, v), s.evaluate(u, v)) < 1e-12);
    }
}

TEST_CASE("bezier surface: iso-curves and boundaries") {
  const BezierSurface s = wavyPatch();
  for (int k = 0; k <= 10; ++k) {
    const double t = k / 10.0;
    CHECK(distance(s.curveAtU(0.3).evaluate(t), s.evaluate(0.3, t)) < 1e-12);
    CHECK(distance(s.curveAtV(0.8).evaluate(t), s.evaluate(t, 0.8)) < 1e-12);
    // Boundary curves agree with the patch bit for bit (what keeps neighbours crack-free).
    CHECK(s.boundary(PatchSide::UMin).evaluate(t) == s.evaluate(0.0, t));
    CHECK(s.boundary(PatchSide::VMin).evaluate(t) == s.evaluate(t, 0.0));
    CHECK(s.boundary(PatchSide::UMax).evaluate(t) == s.evaluate(1.0, t));
    CHECK(s.boundary(PatchSide::VMax).evaluate(t) == s.evaluate(t, 1.0));
  }
}

TEST_CASE("bezier surface: the control net's box holds the patch") {
  const BezierSurface s = wavyPatch();
  const auto box = s.bounds();
  for (int a = 0; a <= 30; ++a)
    for (int b = 0; b <= 30; ++b) CHECK(box.contains(s.evaluate(a / 30.0, b / 30.0), 1e-12));
  CHECK(box.min.x == 0.0);
  CHECK(box.max.y == doctest::Approx(3.0).epsilon(1e-15));
}
