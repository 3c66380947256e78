#include "glass/geometry/rotation.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

CosSin cosSinDegrees(double degrees) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns) && std::abs(turns) < 1e15) {
    // A whole number of quarter turns: exact values, from the quarter turn count modulo 4.
    const long long quarter = static_cast<long long>(turns) % 4;
    switch ((quarter + 4) % 4) {
      case 0: return {1.0, 0.0};
      case 1: return {0.0, 1.0};
      case 2: return {-1.0, 0.0};
      default: return {0.0, -1.0};
    }
  }
  const double radians = degrees * (std::numbers::pi / 180.0);
  return {portable::cos(radians), portable::sin(radians)};
}

namespace {

Quaternion quaternionFromHalfAngle(const glm::dvec3& axis, CosSin half) {
  return {half.cos, half.sin * glm::normalize(axis)};
}

glm::dmat3 matrixFromCosSin(const glm::dvec3& axis, CosSin angle) {
  const glm::dvec3 u = glm::normalize(axis);
  const double c = angle.cos, s = angle.sin, t = 1.0 - c;
  glm::dmat3 m;  // m[column][row], rows as equation 9 writes them
  m[0][0] = t * u.x * u.x + c;
  m[1][0] = t * u.x * u.y - s * u.z;
  m[2][0] = t * u.x * u.z + s * u.y;
  m[0][1] = t * u.y * u.x + s * u.z;
  m[1][1] = t * u.y * u.y + c;
  m[2][1] = t * u.y * u.z - s * u.x;
  m[0][2] = t * u.z * u.x - s * u.y;
  m[1][2] = t * u.z * u.y + s * u.x;
  m[2][2] = t * u.z * u.z + c;
  return m;
}

}  // namespace

Quaternion rotationQuaternion(const glm::dvec3& axis, double radians) {
  return quaternionFromHalfAngle(axis, {portable::cos(radians / 2.0), portable::sin(radians / 2.0)});
}

Quaternion rotationQuaternionDegrees(const glm::dvec3& axis, double degrees) {
  return quaternionFromHalfAngle(axis, cosSinDegrees(degrees / 2.0));
}

glm::dmat3 rotationMatrix(const glm::dvec3& axis, double radians) {
  return matrixFromCosSin(axis, {portable::cos(radians), portable::sin(radians)});
}

glm::dmat3 rotationMatrixDegrees(const glm::dvec3& axis, double degrees) {
  return matrixFromCosSin(axis, cosSinDegrees(degrees));
}

AxisAngle axisAngleFromQuaternion(const Quaternion& q) {
  Quaternion u = normalized(q);
  if (u.w < 0.0) u = -u;  // -q is the same rotation; this makes the angle 2 acos(w) <= pi
  const glm::dvec3 v = u.imaginary();
  const double sinHalf = glm::length(v);
  if (sinHalf == 0.0) return {};
  // atan2 rather than acos(w): accurate at both ends of [0, pi].
  AxisAngle result{v / sinHalf, 2.0 * portable::atan2(sinHalf, u.w)};
  constexpr double kAtPi = 1e-12;
  if (std::numbers::pi - result.angle <= kAtPi) {
    result.angle = std::numbers::pi;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(result.axis[i]) > kAtPi) {
        if (result.axis[i] < 0.0) result.axis = -result.axis;
        break;
      }
    }
  }
  return result;
}

AxisAngle axisAngleFromMatrix(const glm::dmat3& m) {
  return axisAngleFromQuaternion(quaternionFromRotationMatrix(m));
}

Quaternion composeRotations(const Quaternion& first, const Quaternion& second) {
  return second * first;
}

glm::dmat3 composeRotations(const glm::dmat3& first, const glm::dmat3& second) {
  return second * first;
}

}  // namespace glass::geometry
