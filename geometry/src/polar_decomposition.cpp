#include "glass/geometry/polar_decomposition.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace glass::geometry {

SymmetricEigen symmetricEigen(const glm::dmat3& symmetric) {
  // a[r][c] in row-major terms; the matrix is symmetric so glm's column-major order is the same.
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = (symmetric[c][r] + symmetric[r][c]) / 2.0;
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  // Cyclic Jacobi (Golub and Van Loan, section 8.5): each rotation zeroes one off-diagonal pair.
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off == 0.0 || off <= 1e-34 * diagonal) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- A J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // A <- J^T A
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // V <- V J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j] || (a[i][i] == a[j][j] && i < j); });
  SymmetricEigen out;
  for (int k = 0; k < 3; ++k) {
    out.values[k] = a[order[k]][order[k]];
    out.vectors[k] = glm::dvec3(v[0][order[k]], v[1][order[k]], v[2][order[k]]);
  }
  if (glm::determinant(out.vectors) < 0.0) out.vectors[2] = -out.vectors[2];
  return out;
}

namespace {

// A unit vector perpendicular to the unit vector u.
glm::dvec3 perpendicular(const glm::dvec3& u) {
  const glm::dvec3 other = std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(u, other));
}

}  // namespace

glm::dmat3 TrsDecomposition::stretch() const {
  glm::dmat3 d(0.0);
  d[0][0] = scales.x;
  d[1][1] = scales.y;
  d[2][2] = scales.z;
  return stretchAxes * d * glm::transpose(stretchAxes);
}

Affine3 TrsDecomposition::product() const {
  return Affine3::translation(translation) * Affine3::fromParts(rotationMatrix, glm::dvec3(0.0)) *
         Affine3::fromParts(stretch(), glm::dvec3(0.0));
}

Affine3 TrsDecomposition::at(double t) const {
  const double phase = std::clamp(t, 0.0, 1.0) * 3.0;
  const double scaling = std::min(phase, 1.0);
  const double turning = std::clamp(phase - 1.0, 0.0, 1.0);
  const double moving = std::clamp(phase - 2.0, 0.0, 1.0);
  glm::dmat3 d(0.0);
  for (int k = 0; k < 3; ++k) d[k][k] = 1.0 + scaling * (scales[k] - 1.0);
  // At t = 0 exactly the identity (V V^T is only within rounding of it).
  const glm::dmat3 s = scaling <= 0.0 ? glm::dmat3(1.0) : stretchAxes * d * glm::transpose(stretchAxes);
  // At the ends the exact matrices, so the last frame is the map itself.
  const glm::dmat3 r = turning >= 1.0 ? rotationMatrix
                                      : geometry::rotationMatrix(slerp(Quaternion{}, rotation, turning));
  return Affine3::translation(moving * translation) * Affine3::fromParts(r, glm::dvec3(0.0)) *
         Affine3::fromParts(scaling >= 1.0 ? stretch() : s, glm::dvec3(0.0));
}

TrsDecomposition decomposeTrs(const Affine3& map) {
  TrsDecomposition out;
  out.translation = map.translationPart();
  const glm::dmat3 l = map.linearPart();
  // V and the squared singular values from L^T L; then the singular values as |L v_i|, which
  // keeps small ones accurate, and U from L V.
  const SymmetricEigen eigen = symmetricEigen(glm::transpose(l) * l);
  const glm::dmat3 v = eigen.vectors;
  glm::dvec3 lv[3] = {l * v[0], l * v[1], l * v[2]};
  glm::dvec3 u[3];
  glm::dvec3 s;
  s[0] = glm::length(lv[0]);
  u[0] = s[0] > 0.0 ? lv[0] / s[0] : glm::dvec3(1, 0, 0);
  const glm::dvec3 second = lv[1] - glm::dot(u[0], lv[1]) * u[0];  // Gram-Schmidt against rounding
  s[1] = glm::length(second);
  u[1] = s[1] > 0.0 ? second / s[1] : perpendicular(u[0]);
  u[2] = glm::normalize(glm::cross(u[0], u[1]));
  // U is a rotation by construction and so is V: a map reversing orientation shows as s3 < 0.
  s[2] = glm::dot(u[2], lv[2]);
  const glm::dmat3 uMatrix(u[0], u[1], u[2]);
  out.rotationMatrix = uMatrix * glm::transpose(v);
  out.rotation = quaternionFromRotationMatrix(out.rotationMatrix);
  out.stretchAxes = v;
  out.scales = s;
  out.reflection = s[2] < 0.0;
  const double largest = std::abs(s[0]);
  out.similarity = std::abs(std::abs(s[1]) - largest) <= 1e-9 * largest &&
                   std::abs(std::abs(s[2]) - largest) <= 1e-9 * largest;
  return out;
}

}  // namespace glass::geometry
