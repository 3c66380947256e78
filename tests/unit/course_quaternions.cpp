// Section 2.3 of the study guide: the algebra of quaternions, reflections n v n, rotations
// q v q^-1, equations 7, 8 and 9 and their inverses, and slerp.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

#include <glm/geometric.hpp>

#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/quaternion.h"
#include "glass/geometry/rotation.h"

using glass::geometry::Quaternion;
namespace g = glass::geometry;

namespace {

constexpr double kEps = 1e-12;

bool near(const Quaternion& a, const Quaternion& b, double eps = kEps) {
  return std::abs(a.w - b.w) <= eps && std::abs(a.x - b.x) <= eps && std::abs(a.y - b.y) <= eps &&
         std::abs(a.z - b.z) <= eps;
}
bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = kEps) {
  return glm::length(a - b) <= eps;
}
bool near(const glm::dmat3& a, const glm::dmat3& b, double eps = kEps) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(a[c][r] - b[c][r]) > eps) return false;
  return true;
}

glm::dvec3 randomUnitVector(g::SplitMix64& random) {
  while (true) {
    const glm::dvec3 v{2 * random.uniform() - 1, 2 * random.uniform() - 1, 2 * random.uniform() - 1};
    const double n = glm::length(v);
    if (n > 0.1 && n <= 1.0) return v / n;
  }
}

}  // namespace

TEST_CASE("course 2.3.1: the units multiply as i^2 = j^2 = k^2 = -1, ij = k, jk = i, ki = j") {
  const Quaternion one{1, 0, 0, 0}, i{0, 1, 0, 0}, j{0, 0, 1, 0}, k{0, 0, 0, 1};
  CHECK(i * i == -one);
  CHECK(j * j == -one);
  CHECK(k * k == -one);
  CHECK(i * j == k);
  CHECK(j * k == i);
  CHECK(k * i == j);
  CHECK(j * i == -k);
  CHECK(k * j == -i);
  CHECK(i * k == -j);
}

TEST_CASE("course 2.3.1: sum, product in scalar-vector form, conjugate, norm, inverse") {
  const Quaternion a{1, 2, 3, 4}, b{-2, 0.5, 1, -3};
  CHECK(a + b == Quaternion{-1, 2.5, 4, 1});
  // q q' = (r r' - v.v') + (r v' + r' v + v x v')
  const glm::dvec3 v = a.imaginary(), w = b.imaginary();
  const Quaternion expected{a.w * b.w - glm::dot(v, w), a.w * w + b.w * v + glm::cross(v, w)};
  CHECK(near(a * b, expected));
  CHECK_FALSE(near(a * b, b * a));  // not commutative
  CHECK(g::conjugate(a) == Quaternion{1, -2, -3, -4});
  CHECK(near(a * g::conjugate(a), Quaternion{30, 0, 0, 0}));  // q conj(q) = |q|^2
  CHECK(g::norm(a) == doctest::Approx(std::sqrt(30.0)));
  CHECK(g::norm(a * b) == doctest::Approx(g::norm(a) * g::norm(b)));
  CHECK(near(g::inverse(a) * a, Quaternion{1, 0, 0, 0}));
  CHECK(near(a * g::inverse(a), Quaternion{1, 0, 0, 0}));
  CHECK(std::isnan(g::inverse(Quaternion{0, 0, 0, 0}).w));
  // Equation 5: for vectors, v v' = -v.v' + v x v'.
  const Quaternion pv = Quaternion::pure(v), pw = Quaternion::pure(w);
  CHECK(near(pv * pw, Quaternion{-glm::dot(v, w), glm::cross(v, w)}));
}

TEST_CASE("course 2.3.2: n v n reflects v in the plane perpendicular to n") {
  const glm::dvec3 n{0, 0, 1};
  CHECK(near(g::reflect(n, {1, 2, 3}), {1, 2, -3}));
  g::SplitMix64 random(7);
  for (int trial = 0; trial < 100; ++trial) {
    const glm::dvec3 unit = randomUnitVector(random);
    const glm::dvec3 v = 3.0 * randomUnitVector(random);
    const glm::dvec3 expected = v - 2.0 * glm::dot(unit, v) * unit;
    CHECK(near(g::reflect(unit, v), expected));
    CHECK(near(g::reflect(5.0 * unit, v), expected));  // n is normalised first
  }
}

TEST_CASE("course 2.3.3: two reflections make the rotation q v q^-1 with q = n2 n1") {
  // Planes at 30 degrees to each other about the z axis: a rotation by 60 degrees about z.
  const glm::dvec3 n1{0, 1, 0};
  const glm::dvec3 n2{-std::sin(std::numbers::pi / 6), std::cos(std::numbers::pi / 6), 0};
  const Quaternion q = Quaternion::pure(n2) * Quaternion::pure(n1);
  const glm::dvec3 v{1, 0.5, 2};
  CHECK(near(g::reflect(n2, g::reflect(n1, v)), g::rotate(q, v)));
  const g::AxisAngle aa = g::axisAngleFromQuaternion(q);
  CHECK(aa.angle == doctest::Approx(std::numbers::pi / 3));
  CHECK(near(aa.axis, {0, 0, 1}));
}

TEST_CASE("course 2.3.3: equations 7, 8 and 9 describe the same rotation") {
  g::SplitMix64 random(11);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 axis = randomUnitVector(random);
    const double angle = (2 * random.uniform() - 1) * std::numbers::pi;
    const Quaternion q = g::rotationQuaternion(axis, angle);  // equation 7
    CHECK(g::norm(q) == doctest::Approx(1.0));
    const glm::dmat3 byQuaternion = g::rotationMatrix(q);     // equation 8
    const glm::dmat3 byAxisAngle = g::rotationMatrix(axis, angle);  // equation 9
    CHECK(near(byQuaternion, byAxisAngle));
    const glm::dvec3 v = randomUnitVector(random);
    CHECK(near(g::rotate(q, v), byAxisAngle * v));
    CHECK(near(g::rotate(-q, v), g::rotate(q, v)));       // q and -q: the same rotation
    CHECK(near(g::rotate(2.5 * q, v), g::rotate(q, v)));  // any non-zero multiple
    // Back again.
    const Quaternion back = g::quaternionFromRotationMatrix(byAxisAngle);
    CHECK((near(back, q, 1e-10) || near(back, -q, 1e-10)));
    const g::AxisAngle aa = g::axisAngleFromMatrix(byAxisAngle);
    CHECK(near(g::rotationMatrix(aa.axis, aa.angle), byAxisAngle, 1e-10));
    CHECK(aa.angle >= 0.0);
    CHECK(aa.angle <= std::numbers::pi);
  }
}

TEST_CASE("course 2.3.3: a rotation by 90 degrees about z sends x to y, as glRotate") {
  const glm::dmat3 m = g::rotationMatrixDegrees({0, 0, 1}, 90);
  CHECK(m * glm::dvec3{1, 0, 0} == glm::dvec3{0, 1, 0});  // exact at multiples of 90 degrees
  CHECK(near(g::rotate(g::rotationQuaternionDegrees({0, 0, 1}, 90), {1, 0, 0}), {0, 1, 0}));
}

TEST_CASE("course 2.3.3: axis and angle near 0 and at pi") {
  // Angle 0: no axis; the canonical one is returned.
  const g::AxisAngle identity = g::axisAngleFromMatrix(glm::dmat3(1.0));
  CHECK(identity.angle == 0.0);
  // A tiny angle keeps its axis.
  const g::AxisAngle tiny = g::axisAngleFromMatrix(g::rotationMatrix({0, 1, 0}, 1e-7));
  CHECK(tiny.angle == doctest::Approx(1e-7).epsilon(1e-6));
  CHECK(near(tiny.axis, {0, 1, 0}, 1e-6));
  // At pi the axis sign is not unique; the canonical one has its first non-zero component > 0.
  for (const glm::dvec3& axis : {glm::dvec3{1, 2, 3}, glm::dvec3{-1, 2, 3}, glm::dvec3{0, -1, 1},
                                 glm::dvec3{0, 0, -1}}) {
    const glm::dvec3 unit = glm::normalize(axis);
    for (const double sign : {1.0, -1.0}) {
      const g::AxisAngle aa = g::axisAngleFromMatrix(g::rotationMatrix(sign * unit, std::numbers::pi));
      CHECK(aa.angle == doctest::Approx(std::numbers::pi));
      const glm::dvec3 canonical = (unit.x > 0 || (unit.x == 0 && (unit.y > 0 || (unit.y == 0 && unit.z > 0)))) ? unit : -unit;
      CHECK(near(aa.axis, canonical, 1e-10));
    }
  }
  // Just short of pi the axis is determined, and kept.
  const g::AxisAngle almost = g::axisAngleFromMatrix(g::rotationMatrix({0, 0, -1}, std::numbers::pi - 1e-6));
  CHECK(near(almost.axis, {0, 0, -1}, 1e-8));
}

TEST_CASE("course 2.3: slerp interpolates along the shorter arc at constant speed") {
  const Quaternion a = g::rotationQuaternionDegrees({0, 0, 1}, 0);
  const Quaternion b = g::rotationQuaternionDegrees({0, 0, 1}, 90);
  for (const double t : {0.0, 0.25, 0.5, 1.0}) {
    const g::AxisAngle aa = g::axisAngleFromQuaternion(g::slerp(a, b, t));
    CHECK(aa.angle == doctest::Approx(t * std::numbers::pi / 2));
  }
  // -b is the same rotation as b: slerp still turns by 45 degrees at t = 1/2, not the long way.
  const g::AxisAngle viaNegated = g::axisAngleFromQuaternion(g::slerp(a, -b, 0.5));
  CHECK(viaNegated.angle == doctest::Approx(std::numbers::pi / 4));
  CHECK(near(g::slerp(a, a, 0.3), a));
  // The composite of slerp steps: a (a^-1 b)^t. Equal angles for equal steps.
  const Quaternion c = g::rotationQuaternion(glm::normalize(glm::dvec3{1, 1, 0}), 2.0);
  const Quaternion q1 = g::slerp(a, c, 0.2), q2 = g::slerp(a, c, 0.4);
  const double step1 = g::axisAngleFromQuaternion(g::inverse(a) * q1).angle;
  const double step2 = g::axisAngleFromQuaternion(g::inverse(q1) * q2).angle;
  CHECK(step1 == doctest::Approx(step2));
  CHECK(step1 == doctest::Approx(0.4));
}
