// Affine maps of the plane (section 2.2.1 of the study guide): the matrix
//   [ a11 a12 a13 ]
//   [ a21 a22 a23 ]
//   [  0   0   1  ]
// acting on points (x1, x2, 1), stored as its top two rows. The simple maps are the guide's
// S(l1, l2), R(alpha), T(u), plus the shear H(h) = [1 h; 0 1].
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace glass::geometry {

struct Affine2 {
  // Row-major, as the guide writes matrices: m[row][column], row 2 (0 0 1) implied.
  std::array<std::array<double, 3>, 2> m{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}}};

  static Affine2 identity() { return {}; }
  static Affine2 fromRows(double a11, double a12, double a13, double a21, double a22, double a23) {
    return {{{{a11, a12, a13}, {a21, a22, a23}}}};
  }
  static Affine2 translation(double u1, double u2) { return fromRows(1, 0, u1, 0, 1, u2); }
  static Affine2 scaling(double l1, double l2) { return fromRows(l1, 0, 0, 0, l2, 0); }
  // Counter-clockwise by the angle; degrees use exact values at multiples of 90 degrees.
  static Affine2 rotation(double radians);
  static Affine2 rotationDegrees(double degrees);
  // x1' = x1 + h x2: the upper unitriangular matrix [1 h; 0 1].
  static Affine2 shear(double h) { return fromRows(1, h, 0, 0, 1, 0); }

  glm::dvec2 apply(const glm::dvec2& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2], m[1][0] * p.x + m[1][1] * p.y + m[1][2]};
  }
  double determinant() const { return m[0][0] * m[1][1] - m[0][1] * m[1][0]; }

  // The same map as a 4x4 matrix acting on (x, y, z, 1) with z unchanged, column-major, ready
  // for glMultMatrixd / glLoadMatrixd (glm's dmat4 memory layout is GL's).
  glm::dmat4 toMatrix4() const;

  bool operator==(const Affine2&) const = default;
};

// Composition: (a * b)(p) = a(b(p)), the matrix product, applied right to left as in the guide.
Affine2 operator*(const Affine2& a, const Affine2& b);

}  // namespace glass::geometry
