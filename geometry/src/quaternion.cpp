#include "glass/geometry/quaternion.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  // (r + v)(r' + v') = (r r' - v.v') + (r v' + r' v + v x v'), written out per component.
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + b.w * a.x + a.y * b.z - a.z * b.y,
          a.w * b.y + b.w * a.y + a.z * b.x - a.x * b.z,
          a.w * b.z + b.w * a.z + a.x * b.y - a.y * b.x};
}

double norm(const Quaternion& q) { return std::sqrt(normSquared(q)); }

Quaternion inverse(const Quaternion& q) {
  const double n2 = normSquared(q);
  if (n2 == 0.0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  return (1.0 / n2) * conjugate(q);
}

Quaternion normalized(const Quaternion& q) {
  const double n = norm(q);
  return n == 0.0 ? q : (1.0 / n) * q;
}

glm::dvec3 rotate(const Quaternion& q, const glm::dvec3& v) {
  return (q * Quaternion::pure(v) * inverse(q)).imaginary();
}

glm::dvec3 reflect(const glm::dvec3& n, const glm::dvec3& v) {
  const Quaternion unit = Quaternion::pure(n / glm::length(n));
  return (unit * Quaternion::pure(v) * unit).imaginary();
}

glm::dmat3 rotationMatrix(const Quaternion& q) {
  const Quaternion u = normalized(q);
  const double w = u.w, x = u.x, y = u.y, z = u.z;
  glm::dmat3 m;  // m[column][row]
  m[0][0] = w * w + x * x - y * y - z * z;
  m[1][0] = 2.0 * (x * y - w * z);
  m[2][0] = 2.0 * (x * z + w * y);
  m[0][1] = 2.0 * (x * y + w * z);
  m[1][1] = w * w - x * x + y * y - z * z;
  m[2][1] = 2.0 * (y * z - w * x);
  m[0][2] = 2.0 * (x * z - w * y);
  m[1][2] = 2.0 * (y * z + w * x);
  m[2][2] = w * w - x * x - y * y + z * z;
  return m;
}

Quaternion quaternionFromRotationMatrix(const glm::dmat3& m) {
  // Entries by (row, column), as equation 8 is written.
  auto e = [&m](int row, int column) { return m[column][row]; };
  const double trace = e(0, 0) + e(1, 1) + e(2, 2);
  // From equation 8 for a unit quaternion: 4w^2 = 1 + trace, 4x^2 = 1 + m00 - m11 - m22, ...
  // and the off-diagonal sums and differences are 4wx, 4xy, ...; divide by the largest.
  Quaternion q;
  if (trace >= e(0, 0) && trace >= e(1, 1) && trace >= e(2, 2)) {
    const double w4 = 2.0 * std::sqrt(1.0 + trace);
    q = {w4 / 4.0, (e(2, 1) - e(1, 2)) / w4, (e(0, 2) - e(2, 0)) / w4, (e(1, 0) - e(0, 1)) / w4};
  } else if (e(0, 0) >= e(1, 1) && e(0, 0) >= e(2, 2)) {
    const double x4 = 2.0 * std::sqrt(1.0 + e(0, 0) - e(1, 1) - e(2, 2));
    q = {(e(2, 1) - e(1, 2)) / x4, x4 / 4.0, (e(0, 1) + e(1, 0)) / x4, (e(0, 2) + e(2, 0)) / x4};
  } else if (e(1, 1) >= e(2, 2)) {
    const double y4 = 2.0 * std::sqrt(1.0 - e(0, 0) + e(1, 1) - e(2, 2));
    q = {(e(0, 2) - e(2, 0)) / y4, (e(0, 1) + e(1, 0)) / y4, y4 / 4.0, (e(1, 2) + e(2, 1)) / y4};
  } else {
    const double z4 = 2.0 * std::sqrt(1.0 - e(0, 0) - e(1, 1) + e(2, 2));
    q = {(e(1, 0) - e(0, 1)) / z4, (e(0, 2) + e(2, 0)) / z4, (e(1, 2) + e(2, 1)) / z4, z4 / 4.0};
  }
  if (q.w < 0.0) q = -q;
  return normalized(q);
}

Quaternion slerp(const Quaternion& a, const Quaternion& b, double t) {
  const Quaternion from = normalized(a);
  Quaternion to = normalized(b);
  double cosPhi = dot(from, to);
  if (cosPhi < 0.0) {
    to = -to;
    cosPhi = -cosPhi;
  }
  // Below this angle sin(phi) loses most of its digits; the chord and the arc agree to ~1e-10.
  constexpr double kNearlyParallel = 1.0 - 1e-10;
  if (cosPhi > kNearlyParallel) return normalized((1.0 - t) * from + t * to);
  const double phi = portable::acos(cosPhi);
  const double sinPhi = portable::sin(phi);
  return (portable::sin((1.0 - t) * phi) / sinPhi) * from + (portable::sin(t * phi) / sinPhi) * to;
}

}  // namespace glass::geometry
