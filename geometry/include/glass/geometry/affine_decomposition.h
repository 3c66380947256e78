// Writing a plane affine map as a product of simple ones (test question 2 of the study guide):
//   A = T(u) R(theta) S(s1, s2)            when the columns of A's linear part are orthogonal,
//   A = T(u) R(theta) H(h) S(s1, s2)       for every invertible A,
// with T a translation, R a counter-clockwise rotation, H(h) = [1 h; 0 1] a shear and S a
// scaling (negative factors allowed: a scaling by -1 is a reflection). Applied right to left:
// first scale, then shear, then rotate, then translate.
//
// How: A = T(u) L (the guide's equation 3), u = (a13, a23). L = Q U is the QR factorisation of L
// by Gram-Schmidt on its columns: Q = R(theta) a rotation and U = [s1 s2 h; 0 s2] = H(h) S(s1, s2)
// upper triangular. The first column of L is s1 (cos theta, sin theta), so
// theta = atan2(a21, a11) up to a half turn; s2 and s2 h are the second column's components
// along (-sin theta, cos theta) and (cos theta, sin theta). h = 0 exactly when the columns are
// orthogonal, and then the shear is left out.
//
// Every decomposition has a twin with theta + pi and -s1, -s2 (R(pi) = S(-1, -1)). The one with
// theta in (-90, 90] degrees is returned: the smaller rotation, as in the guide's answer
// [-2 -1 2; -2 1 -1] = T(2, -1) R(45) S(-2 sqrt2, sqrt2).
#pragma once

#include <optional>

#include "glass/geometry/affine2d.h"

namespace glass::geometry {

struct AffineDecomposition {
  double translateX = 0.0, translateY = 0.0;
  double rotationRadians = 0.0;
  double shear = 0.0;  // h of H(h); 0 when no shear is needed
  double scaleX = 1.0, scaleY = 1.0;
  bool needsShear = false;  // false: A = T R S; true: A = T R H S

  // The product of the factors, to check the decomposition against the original.
  Affine2 product() const;
};

// Relative tolerance for "the columns are orthogonal": |c1 . c2| <= 1e-12 |c1| |c2|.
inline constexpr double kOrthogonalColumnsTolerance = 1e-12;

// Empty when A is not invertible (its linear part has determinant 0): then no such product
// exists with non-zero scale factors.
std::optional<AffineDecomposition> decomposeAffine(const Affine2& a);

}  // namespace glass::geometry
