// A k-d tree of points of space for nearest-neighbour queries (Bentley, 1975; Friedman, Bentley
// and Finkel, 1977): the points are split at the median of their widest coordinate, recursively,
// down to small leaves; a query descends to the leaf of its point and backtracks only into
// subtrees whose points' bounding box is not farther than the best distance found. Building is
// O(n log n), a query about O(log n).
// Deterministic: ties go to the lower index.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace glass::geometry {

class KdTree3 {
 public:
  KdTree3() = default;
  explicit KdTree3(std::span<const glm::dvec3> points);

  struct Nearest {
    std::uint32_t index = 0;  // into the points given
    double distanceSquared = 0.0;
  };
  // The nearest of the points to p. The tree must not be empty.
  Nearest nearest(const glm::dvec3& p) const;

  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }

 private:
  struct Node {
    // The bounding box of the node's points (not the cell the splits cut out of space): empty
    // space is left out, so a query far from the points, or in a hollow of the cloud, skips
    // whole subtrees that a cell would still reach.
    glm::dvec3 lo{0.0}, hi{0.0};
    std::uint32_t begin = 0, end = 0;  // the node's points: order_[begin, end)
    std::int32_t left = -1, right = -1;  // children; -1 for a leaf
  };
  std::int32_t build(std::uint32_t begin, std::uint32_t end);
  void search(std::int32_t node, const glm::dvec3& p, Nearest& best) const;
  static double boxDistanceSquared(const Node& node, const glm::dvec3& p);

  std::vector<glm::dvec3> points_;     // in tree order, for locality
  std::vector<std::uint32_t> order_;   // original index of points_[i]
  std::vector<Node> nodes_;
};

}  // namespace glass::geometry
