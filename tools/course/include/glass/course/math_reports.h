// The worked solutions `glass math` prints: each computation of the study guide's test and exam
// written out step by step, as the guide's section 3.2 does, ending with the answer. Pure text,
// no GL, so the unit tests read the same words a student does.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine2d.h"
#include "glass/geometry/sphere_view.h"

namespace glass::course {

struct RotationStep {
  double degrees = 0.0;
  glm::dvec3 axis{0.0, 0.0, 1.0};
};

// The composite of rotations applied in the given order (first rotations[0]), by matrices
// (equation 9, multiplied right to left, axis and angle read back from the trace and the
// skew-symmetric part, or from M = 2 u u^T - I at 180 degrees) and by quaternions (equation 7).
// Test question 4: {-90, (0, 1, 0)}, {180, (1, 0, 0)}.
std::string rotateComposeReport(const std::vector<RotationStep>& rotations);

// A = T R S or T R H S (test question 2).
std::string decomposeReport(const geometry::Affine2& a);

// The exam's viewing problem: the gluLookAt and gluPerspective calls, with the working.
std::string viewReport(const geometry::SphereViewProblem& problem);

// The normal of the triangle A0 A1 A2 and its orientation (the exam's lighting question).
std::string normalReport(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& a2);

// A circular arc as rational quadratic Bezier curves (one arc below 180 degrees, several above),
// control points and weights, checked by sampling (the exam's arc: 0 to 120 degrees).
std::string arcReport(double startDegrees, double endDegrees, double radius);

// The exam's 1/16 torus patch x >= 0, y <= 0, z >= 0 (outer or inner half of that eighth):
// control points in terms of R and r, weights, and the numbers for the given radii.
std::string torusPatchReport(double majorRadius, double minorRadius, bool inner);

}  // namespace glass::course
