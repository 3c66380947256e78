// The study guide's exam computations (section 4.1): the viewing problem and a triangle's normal.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "glass/geometry/sphere_view.h"
#include "glass/geometry/triangle_normal.h"

namespace g = glass::geometry;

TEST_CASE("course exam 1: the sphere fills 2/3 of the height and 1/2 of the width, one half visible") {
  const g::SphereViewProblem problem;  // the exam's numbers are the defaults
  CHECK(problem.eye == glm::dvec3{0, 2, -1});
  CHECK(problem.center == glm::dvec3{1, 4, 1});
  const g::SphereViewResult result = g::solveSphereView(problem);
  REQUIRE(result.solution.has_value());
  const g::SphereViewSolution& s = *result.solution;
  CHECK(s.distance == 3.0);
  CHECK(s.zNear == 3.0);  // the near plane through the centre cuts the sphere in half
  CHECK(s.backDistance == 4.0);  // the back of the sphere
  CHECK(s.zFar == 5.0);          // beyond it, so rounding cannot clip the farthest point
  CHECK(s.aspect == doctest::Approx(4.0 / 3.0));
  CHECK(s.fovyDegrees == doctest::Approx(2 * std::atan(0.5) * 180 / std::numbers::pi));
  CHECK(s.fovyDegrees == doctest::Approx(53.1301023542));

  // Check by projecting: the same matrices gluLookAt and gluPerspective build (glm's lookAt and
  // perspective follow the GLU definitions). The rim of the cut, the great circle perpendicular to
  // the line of sight, must reach +-2/3 in normalized y and +-1/2 in normalized x, at depth -1
  // (the near plane); the back of the sphere must lie inside the far plane.
  const glm::dmat4 view = glm::lookAt(s.eye, s.center, s.up);
  const glm::dmat4 projection =
      glm::perspective(s.fovyDegrees * std::numbers::pi / 180, s.aspect, s.zNear, s.zFar);
  const glm::dvec3 axis = glm::normalize(s.center - s.eye);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, s.up));
  const glm::dvec3 v = glm::cross(u, axis);
  double maxX = 0, maxY = 0;
  for (int k = 0; k < 360; ++k) {
    const double a = k * std::numbers::pi / 180;
    const glm::dvec3 p = s.center + std::cos(a) * u + std::sin(a) * v;
    const glm::dvec4 clip = projection * view * glm::dvec4(p, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    maxX = std::max(maxX, std::abs(ndc.x));
    maxY = std::max(maxY, std::abs(ndc.y));
    CHECK(ndc.z == doctest::Approx(-1.0));
  }
  CHECK(maxX == doctest::Approx(0.5));
  CHECK(maxY == doctest::Approx(2.0 / 3.0));
  const glm::dvec4 back = projection * view * glm::dvec4(s.center + axis, 1.0);
  // z_ndc = (f + n)/(f - n) - 2 f n / ((f - n) z) = 4 - 3.75 at z = 4: inside the far plane.
  CHECK(back.z / back.w == doctest::Approx(0.25));
}

TEST_CASE("course exam 1: other visible parts move the near plane beyond the centre") {
  g::SphereViewProblem problem;
  problem.visibleFraction = 0.25;  // the cap beyond t = r/2: a quarter of the area
  const auto result = g::solveSphereView(problem);
  REQUIRE(result.solution.has_value());
  CHECK(result.solution->planeOffset == 0.5);
  CHECK(result.solution->zNear == 3.5);
  CHECK(result.solution->rimRadius == doctest::Approx(std::sqrt(0.75)));
  problem.visibleFraction = 0.75;
  CHECK_FALSE(g::solveSphereView(problem).solution.has_value());
  problem.visibleFraction = 0.5;
  problem.eye = problem.center + glm::dvec3{0.5, 0, 0};  // inside
  CHECK_FALSE(g::solveSphereView(problem).solution.has_value());
}

TEST_CASE("course exam 2: the normal of A0 = (3,1,2), A1 = (3,-1,3), A2 = (4,-1,4)") {
  const glm::dvec3 a0{3, 1, 2}, a1{3, -1, 3}, a2{4, -1, 4};
  const auto n = g::triangleNormal(a0, a1, a2);
  REQUIRE(n.has_value());
  // (A1 - A0) x (A2 - A0) = (0, -2, 1) x (1, -2, 2) = (-2, 1, 2), length 3.
  CHECK(n->normal == glm::dvec3{-2, 1, 2});
  CHECK(n->unitNormal.x == doctest::Approx(-2.0 / 3));
  CHECK(n->unitNormal.y == doctest::Approx(1.0 / 3));
  CHECK(n->unitNormal.z == doctest::Approx(2.0 / 3));
  CHECK(n->area == 1.5);
  CHECK(n->planeOffset == -1.0);  // the plane -2x + y + 2z = -1
  for (const glm::dvec3& p : {a0, a1, a2}) CHECK(glm::dot(n->normal, p) == -1.0);
  // The other order turns the normal round: the orientation flips.
  CHECK(g::triangleNormal(a0, a2, a1)->normal == glm::dvec3{2, -1, -2});
  CHECK_FALSE(g::triangleNormal(a0, a1, a1 + (a1 - a0)).has_value());
}
