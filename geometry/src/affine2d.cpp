#include "glass/geometry/affine2d.h"

#include <cmath>

#include "glass/geometry/rotation.h"
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

Affine2 Affine2::rotation(double radians) {
  const double c = portable::cos(radians), s = portable::sin(radians);
  return fromRows(c, -s, 0, s, c, 0);
}

Affine2 Affine2::rotationDegrees(double degrees) {
  const CosSin cs = cosSinDegrees(degrees);
  return fromRows(cs.cos, -cs.sin, 0, cs.sin, cs.cos, 0);
}

glm::dmat4 Affine2::toMatrix4() const {
  glm::dmat4 out(1.0);  // out[column][row]
  out[0][0] = m[0][0];
  out[1][0] = m[0][1];
  out[3][0] = m[0][2];
  out[0][1] = m[1][0];
  out[1][1] = m[1][1];
  out[3][1] = m[1][2];
  return out;
}

Affine2 operator*(const Affine2& a, const Affine2& b) {
  Affine2 out;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      out.m[r][c] = a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c];
    }
    out.m[r][2] += a.m[r][2];  // the implied third row (0 0 1) of b carries a's translation
  }
  return out;
}

}  // namespace glass::geometry
