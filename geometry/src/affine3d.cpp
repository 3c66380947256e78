#include "glass/geometry/affine3d.h"

#include <algorithm>
#include <cmath>

#include "glass/geometry/rotation.h"

namespace glass::geometry {

Affine3 Affine3::fromRows(const std::array<double, 12>& v) {
  Affine3 a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] = v[static_cast<std::size_t>(4 * r + c)];
  return a;
}

Affine3 Affine3::fromParts(const glm::dmat3& linear, const glm::dvec3& translation) {
  Affine3 a;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a.m[r][c] = linear[c][r];
    a.m[r][3] = translation[r];
  }
  return a;
}

Affine3 Affine3::translation(const glm::dvec3& t) { return fromParts(glm::dmat3(1.0), t); }

Affine3 Affine3::scaling(const glm::dvec3& s) {
  glm::dmat3 l(1.0);
  l[0][0] = s.x;
  l[1][1] = s.y;
  l[2][2] = s.z;
  return fromParts(l, glm::dvec3(0.0));
}

Affine3 Affine3::rotationDegrees(double degrees, const glm::dvec3& axis) {
  return fromParts(rotationMatrixDegrees(axis, degrees), glm::dvec3(0.0));
}

glm::dmat3 Affine3::linearPart() const {
  glm::dmat3 l;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) l[c][r] = m[r][c];
  return l;
}

double Affine3::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

glm::dmat4 Affine3::toMatrix4() const {
  glm::dmat4 out(1.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out[c][r] = m[r][c];
  return out;
}

double Affine3::maxDifference(const Affine3& a, const Affine3& b) {
  double worst = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(a.m[r][c] - b.m[r][c]));
  return worst;
}

Affine3 operator*(const Affine3& a, const Affine3& b) {
  Affine3 out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      out.m[r][c] = a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c] + a.m[r][2] * b.m[2][c];
    }
    out.m[r][3] += a.m[r][3];  // b's implied last row (0 0 0 1) carries a's translation
  }
  return out;
}

}  // namespace glass::geometry
