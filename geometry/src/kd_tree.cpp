#include "glass/geometry/kd_tree.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include <glm/common.hpp>

namespace glass::geometry {

namespace {
constexpr std::uint32_t kLeafSize = 8;
}

KdTree3::KdTree3(std::span<const glm::dvec3> points) {
  order_.resize(points.size());
  for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  points_.assign(points.begin(), points.end());
  if (!points_.empty()) build(0, static_cast<std::uint32_t>(points_.size()));
  // Store the points in tree order so that a leaf's points are adjacent in memory.
  std::vector<glm::dvec3> ordered(points_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) ordered[i] = points[order_[i]];
  points_ = std::move(ordered);
}

std::int32_t KdTree3::build(std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::int32_t>(nodes_.size());
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::uint32_t i = begin; i < end; ++i) {
    lo = glm::min(lo, points_[order_[i]]);
    hi = glm::max(hi, points_[order_[i]]);
  }
  nodes_.push_back({lo, hi, begin, end, -1, -1});
  if (end - begin <= kLeafSize) return index;
  const glm::dvec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (!(extent[axis] > 0.0)) return index;  // all points equal: one leaf
  const std::uint32_t middle = begin + (end - begin) / 2;
  // Ties broken by index, so the tree does not depend on the library's nth_element.
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double pa = points_[a][axis], pb = points_[b][axis];
                     return pa < pb || (pa == pb && a < b);
                   });
  const std::int32_t left = build(begin, middle);
  const std::int32_t right = build(middle, end);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

// The squared distance from p to the node's box (0 inside): no point of the node is nearer.
double KdTree3::boxDistanceSquared(const Node& node, const glm::dvec3& p) {
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double below = node.lo[axis] - p[axis], above = p[axis] - node.hi[axis];
    const double d = below > 0.0 ? below : (above > 0.0 ? above : 0.0);
    sum += d * d;
  }
  return sum;
}

KdTree3::Nearest KdTree3::nearest(const glm::dvec3& p) const {
  Nearest best{0, std::numeric_limits<double>::infinity()};
  search(0, p, best);
  return best;
}

// Depth first, the nearer child's box first; a child is entered only when its box is not farther
// than the best point so far. Points at the same distance are decided by their index, and a box
// at exactly the best distance is still entered (<=), so the result is the nearest point of least
// index, as a search of all points gives, whatever the tree's shape.
void KdTree3::search(std::int32_t nodeIndex, const glm::dvec3& p, Nearest& best) const {
  const Node& node = nodes_[static_cast<std::size_t>(nodeIndex)];
  if (node.left < 0) {
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const glm::dvec3 d = points_[i] - p;
      const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
      if (d2 < best.distanceSquared || (d2 == best.distanceSquared && order_[i] < best.index)) {
        best = {order_[i], d2};
      }
    }
    return;
  }
  const double leftDistance = boxDistanceSquared(nodes_[static_cast<std::size_t>(node.left)], p);
  const double rightDistance = boxDistanceSquared(nodes_[static_cast<std::size_t>(node.right)], p);
  const bool leftFirst = leftDistance <= rightDistance;
  const std::int32_t first = leftFirst ? node.left : node.right, second = leftFirst ? node.right : node.left;
  const double firstDistance = leftFirst ? leftDistance : rightDistance, secondDistance = leftFirst ? rightDistance : leftDistance;
  if (firstDistance <= best.distanceSquared) search(first, p, best);
  if (secondDistance <= best.distanceSquared) search(second, p, best);
}

}  // namespace glass::geometry
