// Rotations of space described by an axis and an angle (section 2.3.3 of the study guide): the
// quaternion cos(theta/2) + sin(theta/2) u (equation 7), the matrix
//   R = cos(theta) I + (1 - cos(theta)) u u^T + sin(theta) [u]x   (equation 9),
// and the way back from a matrix or a quaternion to an axis and an angle, the angle-pi case
// included. Angles are counter-clockwise looking from the tip of the axis towards the origin, as
// glRotate's.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "glass/geometry/quaternion.h"

namespace glass::geometry {

struct AxisAngle {
  glm::dvec3 axis{1.0, 0.0, 0.0};  // unit length
  double angle = 0.0;              // radians
};

struct CosSin {
  double cos = 1.0;
  double sin = 0.0;
};

// cos and sin of an angle in degrees, exact (0, 1 or -1) at multiples of 90 degrees, where
// cos(pi / 2) computed in radians would give 6e-17 instead of 0. This keeps the course's matrices
// (glRotate by 90 or 180 degrees) exact integers.
CosSin cosSinDegrees(double degrees);

// Equation 7: the unit quaternion cos(theta/2) + sin(theta/2) u for the axis u (normalised first)
// and the angle theta. q and -q describe the same rotation.
Quaternion rotationQuaternion(const glm::dvec3& axis, double radians);
Quaternion rotationQuaternionDegrees(const glm::dvec3& axis, double degrees);

// Equation 9, for the axis normalised first.
glm::dmat3 rotationMatrix(const glm::dvec3& axis, double radians);
glm::dmat3 rotationMatrixDegrees(const glm::dvec3& axis, double degrees);

// The canonical axis and angle of a rotation: the angle in [0, pi] and a unit axis. The angle 0
// has no axis; (1, 0, 0) is returned. At the angle pi the rotations about u and -u are the same
// (the guide's "the sign is not unique because of the exceptional case theta = pi"); the axis
// whose first non-zero component is positive is returned. "At pi" means within 1e-12 radians,
// far below what a printed answer shows, so rounding in the inputs does not flip the sign.
AxisAngle axisAngleFromQuaternion(const Quaternion& q);
// From a rotation matrix. The guide reads the angle from the trace, cos(theta) = (tr M - 1) / 2,
// and the axis from the skew-symmetric part, or at theta = pi from M = 2 u u^T - I. The same
// answer is computed here through quaternionFromRotationMatrix, which stays accurate near 0 and pi.
AxisAngle axisAngleFromMatrix(const glm::dmat3& m);

// The composite rotation "first a, then b" as a quaternion and as a matrix: b a and B A (the
// product reads right to left, as the guide notes).
Quaternion composeRotations(const Quaternion& first, const Quaternion& second);
glm::dmat3 composeRotations(const glm::dmat3& first, const glm::dmat3& second);

}  // namespace glass::geometry
