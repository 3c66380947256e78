#include "glass/geometry/triangle_normal.h"

#include <glm/geometric.hpp>

namespace glass::geometry {

std::optional<TriangleNormal> triangleNormal(const glm::dvec3& a0, const glm::dvec3& a1,
                                             const glm::dvec3& a2) {
  const glm::dvec3 n = glm::cross(a1 - a0, a2 - a0);
  const double length = glm::length(n);
  // Collinear within rounding: |n| tiny against the product of the edge lengths.
  if (!(length > 1e-14 * glm::length(a1 - a0) * glm::length(a2 - a0))) return std::nullopt;
  return TriangleNormal{n, n / length, length / 2.0, glm::dot(n, a0)};
}

}  // namespace glass::geometry
