#include "glass/geometry/affine_decomposition.h"

#include <cmath>
#include <numbers>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

Affine2 AffineDecomposition::product() const {
  return Affine2::translation(translateX, translateY) * Affine2::rotation(rotationRadians) *
         Affine2::shear(needsShear ? shear : 0.0) * Affine2::scaling(scaleX, scaleY);
}

std::optional<AffineDecomposition> decomposeAffine(const Affine2& a) {
  const double c1x = a.m[0][0], c1y = a.m[1][0];  // first column of L
  const double c2x = a.m[0][1], c2y = a.m[1][1];  // second column of L
  const double length1 = std::hypot(c1x, c1y);
  const double length2 = std::hypot(c2x, c2y);
  const double det = a.determinant();
  // Singular when a column vanishes or the columns are parallel; the determinant alone would
  // need a scale-dependent threshold, the sine of the angle between the columns does not.
  if (length1 == 0.0 || length2 == 0.0 || std::abs(det) <= 1e-14 * length1 * length2) {
    return std::nullopt;
  }

  AffineDecomposition d;
  d.translateX = a.m[0][2];
  d.translateY = a.m[1][2];

  // The direction of the first column, turned by a half turn if needed so that theta lies in
  // (-pi/2, pi/2]; s1 carries the sign.
  double theta = portable::atan2(c1y, c1x);
  double s1 = length1;
  if (theta > std::numbers::pi / 2.0) {
    theta -= std::numbers::pi;
    s1 = -s1;
  } else if (theta <= -std::numbers::pi / 2.0) {
    theta += std::numbers::pi;
    s1 = -s1;
  }
  // The unit vectors of the rotated frame, from the column itself rather than cos(theta) and
  // sin(theta), so that exact inputs keep exact directions.
  const double ex = c1x / s1, ey = c1y / s1;  // (cos theta, sin theta)
  const double along = ex * c2x + ey * c2y;   // s2 h: second column along e
  const double across = -ey * c2x + ex * c2y;  // s2: second column along (-sin, cos)

  d.rotationRadians = theta;
  d.scaleX = s1;
  d.scaleY = across;
  const bool orthogonal = std::abs(c1x * c2x + c1y * c2y) <= kOrthogonalColumnsTolerance * length1 * length2;
  d.needsShear = !orthogonal;
  d.shear = orthogonal ? 0.0 : along / across;
  return d;
}

}  // namespace glass::geometry
