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
  for (const glm::dvec3& q : points_) {
    lo_ = glm::min(lo_, q);
    hi_ = glm::max(hi_, q);
  }
  // Store the points in tree order so that a leaf's points are adjacent in memory.
  std::vector<glm::dvec3> ordered(points_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) ordered[i] = points[order_[i]];
  points_ = std::move(ordered);
}

std::int32_t KdTree3::build(std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back({0.0, begin, end, -1, -1, 0});
  if (end - begin <= kLeafSize) return index;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::uint32_t i = begin; i < end; ++i) {
    lo = glm::min(lo, points_[order_[i]]);
    hi = glm::max(hi, points_[order_[i]]);
  }
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
  const double split = points_[order_[middle]][axis];
  const std::int32_t left = build(begin, middle);
  const std::int32_t right = build(middle, end);
  nodes_[static_cast<std::size_t>(index)].axis = static_cast<std::uint8_t>(axis);
  nodes_[static_cast<std::size_t>(index)].split = split;
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

KdTree3::Nearest KdTree3::nearest(const glm::dvec3& p) const {
  Nearest best{0, std::numeric_limits<double>::infinity()};
  // The offsets of p from the root's bounding box along each axis (0 inside), and their squared
  // length: a lower bound on the distance to any point of the tree.
  glm::dvec3 offsets(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    if (p[axis] < lo_[axis]) offsets[axis] = p[axis] - lo_[axis];
    if (p[axis] > hi_[axis]) offsets[axis] = p[axis] - hi_[axis];
  }
  search(0, p, best, glm::dot(offsets, offsets), offsets);
  return best;
}

// Arya and Mount's incremental distance: cellDistance is the squared distance from p to the
// node's cell, kept exact along the split axes, so that a cell that cannot hold a nearer point
// is skipped however far p is from the points.
void KdTree3::search(std::int32_t nodeIndex, const glm::dvec3& p, Nearest& best, double cellDistance,
                     glm::dvec3& offsets) const {
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
  const double offset = p[node.axis] - node.split;
  const std::int32_t nearSide = offset < 0.0 ? node.left : node.right;
  const std::int32_t farSide = offset < 0.0 ? node.right : node.left;
  search(nearSide, p, best, cellDistance, offsets);
  // The far cell lies beyond the split plane: its distance has the split offset on this axis.
  // Points equal to the split can lie on either side, hence <=.
  const double previous = offsets[node.axis];
  const double farDistance = cellDistance - previous * previous + offset * offset;
  if (farDistance <= best.distanceSquared) {
    offsets[node.axis] = offset;
    search(farSide, p, best, farDistance, offsets);
    offsets[node.axis] = previous;
  }
}

}  // namespace glass::geometry
