// Affine maps of space, the 3D counterpart of affine2d.h: the matrix
//   [ a11 a12 a13 a14 ]
//   [ a21 a22 a23 a24 ]
//   [ a31 a32 a33 a34 ]
//   [  0   0   0   1  ]
// acting on points (x, y, z, 1), stored as its top three rows, as the course writes 3D IFS maps
// (a linear part L and a translation t: f(x) = L x + t).
#pragma once

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace glass::geometry {

struct Affine3 {
  // Row-major: m[row][column], row 3 (0 0 0 1) implied.
  std::array<std::array<double, 4>, 3> m{{{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}};

  static Affine3 identity() { return {}; }
  static Affine3 fromRows(const std::array<double, 12>& rowMajor);
  // L and t; glm's dmat3 is column-major (entry row r, column c is linear[c][r]).
  static Affine3 fromParts(const glm::dmat3& linear, const glm::dvec3& translation);
  static Affine3 translation(const glm::dvec3& t);
  static Affine3 scaling(const glm::dvec3& s);
  // glRotate's rotation: counter-clockwise about the axis (normalised first), exact at multiples
  // of 90 degrees.
  static Affine3 rotationDegrees(double degrees, const glm::dvec3& axis);

  glm::dvec3 apply(const glm::dvec3& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  glm::dmat3 linearPart() const;
  glm::dvec3 translationPart() const { return {m[0][3], m[1][3], m[2][3]}; }
  double determinant() const;
  // The same map for glMultMatrixd / glLoadMatrixd (column-major, as glm stores dmat4).
  glm::dmat4 toMatrix4() const;
  // The largest |a_ij - b_ij| over the twelve entries.
  static double maxDifference(const Affine3& a, const Affine3& b);

  bool operator==(const Affine3&) const = default;
};

// Composition: (a * b)(p) = a(b(p)).
Affine3 operator*(const Affine3& a, const Affine3& b);

}  // namespace glass::geometry
