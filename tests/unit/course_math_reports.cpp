// The worked solutions `glass math` prints contain the study guide's answers, in the guide's
// notation.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "glass/course/exact_number.h"
#include "glass/course/math_reports.h"

namespace c = glass::course;
namespace g = glass::geometry;

namespace {
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("course math: numbers in the guide's exact forms") {
  CHECK(c::exactForm(2.0) == "2");
  CHECK(c::exactForm(-0.5) == "-1/2");
  CHECK(c::exactForm(1 / std::sqrt(2.0)) == "1/√2");
  CHECK(c::exactForm(-2 * std::sqrt(2.0)) == "-2√2");
  CHECK(c::exactForm(std::sqrt(3.0) / 2) == "√3/2");
  CHECK(c::exactForm(4.0 / 3) == "4/3");
  CHECK(c::exactForm(1 / (2 * std::sqrt(3.0))) == "1/(2√3)");
  CHECK(c::exactForm(std::numbers::pi) == "");
  CHECK(c::describe(0.25) == "0.25");
  CHECK(c::describe(1.0 / 3) == "0.333333 (1/3)");
  CHECK(c::describe(std::cos(std::numbers::pi / 2)) == "0");
}

TEST_CASE("course math: rotate-compose reproduces test question 4, both ways") {
  const std::string report = c::rotateComposeReport({{-90, {0, 1, 0}}, {180, {1, 0, 0}}});
  CAPTURE(report);
  CHECK(contains(report, "M = R2 R1"));
  CHECK(contains(report, "cos(theta) = (m11 + m22 + m33 - 1) / 2 = -1"));
  CHECK(contains(report, "u1^2 = (m11 + 1)/2 = 1/2"));
  CHECK(contains(report, "u = ±(1/√2, 0, -1/√2)"));
  CHECK(contains(report, "q1 = cos(-45) + sin(-45) (0, 1, 0) = 1/√2 - 1/√2 j"));
  CHECK(contains(report, "q2 = cos(90) + sin(90) (1, 0, 0) = i"));
  CHECK(contains(report, "q = q2 q1 = 1/√2 i - 1/√2 k"));
  CHECK(contains(report, "Answer: 180 degrees about (1/√2, 0, -1/√2)"));
  CHECK(contains(report, "(a) and (b) agree"));
  // A general angle: 90 about z then 90 about x sends x to z, y to -x, z to -y: 120 degrees
  // about (1, -1, 1)/√3.
  const std::string general = c::rotateComposeReport({{90, {0, 0, 1}}, {90, {1, 0, 0}}});
  CAPTURE(general);
  CHECK(contains(general, "Answer: 120 degrees about (1/√3, -1/√3, 1/√3)"));
}

TEST_CASE("course math: decompose reproduces test question 2") {
  const std::string report = c::decomposeReport(g::Affine2::fromRows(-2, -1, 2, -2, 1, -1));
  CAPTURE(report);
  CHECK(contains(report, "A = T(2, -1) R(45 degrees) S(-2√2, √2)"));
  CHECK(contains(report, "no shear is needed"));
  const std::string sheared = c::decomposeReport(g::Affine2::fromRows(1, 1, 0, 0, 1, 0));
  CAPTURE(sheared);
  CHECK(contains(sheared, "A = T(0, 0) R(0 degrees) H(1) S(1, 1)"));
  CHECK(contains(c::decomposeReport(g::Affine2::fromRows(1, 2, 0, 2, 4, 0)), "not invertible"));
}

TEST_CASE("course math: view gives the exam's gluLookAt and gluPerspective") {
  const std::string report = c::viewReport(g::SphereViewProblem{});
  CAPTURE(report);
  CHECK(contains(report, "d = |C - E| = 3"));
  CHECK(contains(report, "zNear = d + t = 3"));
  CHECK(contains(report, "tan(fovy/2) = rho / (h zNear) = 0.5"));
  CHECK(contains(report, "aspect = h / w = 1.33333 (4/3)"));
  CHECK(contains(report, "gluLookAt(0, 2, -1,  1, 4, 1,  0, 1, 0);"));
  CHECK(contains(report, "gluPerspective(53.1301, 1.33333, 3, 5);"));
  CHECK(contains(report, "glMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\ngluLookAt"));
}

TEST_CASE("course math: normal of the exam's triangle") {
  const std::string report = c::normalReport({3, 1, 2}, {3, -1, 3}, {4, -1, 4});
  CAPTURE(report);
  CHECK(contains(report, "n = (A1 - A0) x (A2 - A0) = (-2, 1, 2), |n| = 3"));
  CHECK(contains(report, "unit normal n / |n| = (-2/3, 1/3, 2/3)"));
  CHECK(contains(report, "-2x + y + 2z = -1"));
  CHECK(contains(report, "counter-clockwise"));
}

TEST_CASE("course math: the exam's arc and 1/16 torus patch") {
  const std::string arc = c::arcReport(0, 120, 1);
  CAPTURE(arc);
  CHECK(contains(arc, "0  (1, 0)                1         (1, 0, 0, 1)"));
  CHECK(contains(arc, "1  (1, √3)               1/2       (1/2, √3/2, 0, 1/2)"));
  CHECK(contains(arc, "2  (-1/2, √3/2)          1         (-1/2, √3/2, 0, 1)"));
  CHECK(contains(arc, "lie on the circle to 0"));
  const std::string whole = c::arcReport(0, 360, 2);
  CHECK(contains(whole, "in 3 pieces of 120 degrees"));

  const std::string torus = c::torusPatchReport(2, 1, false);
  CAPTURE(torus);
  CHECK(contains(torus, "(0, -r, R)"));
  CHECK(contains(torus, "(R+r, -r, R+r)"));
  CHECK(contains(torus, "1/2"));
  CHECK(contains(torus, "all satisfy x >= 0, y <= 0, z >= 0"));
}
