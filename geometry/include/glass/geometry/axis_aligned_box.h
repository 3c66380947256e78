// An axis-aligned box in 3D, the bounding volume of Bezier curves and patches.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <limits>

namespace glass::geometry {

struct AxisAlignedBox {
  // The empty box: min above max, so that the first include() sets both.
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }

  void include(const glm::dvec3& p) {
    min = glm::dvec3(std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z));
    max = glm::dvec3(std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z));
  }

  bool contains(const glm::dvec3& p, double slack = 0.0) const {
    return p.x >= min.x - slack && p.y >= min.y - slack && p.z >= min.z - slack &&
           p.x <= max.x + slack && p.y <= max.y + slack && p.z <= max.z + slack;
  }

  glm::dvec3 size() const { return empty() ? glm::dvec3(0.0) : max - min; }
};

}  // namespace glass::geometry
