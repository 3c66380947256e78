// The distance grid of a cloud and the hill climbing of a map on it: the two tools that let the
// homework 3 fit (ifs3d_fit.h) score millions of candidate maps. The grid stores, for the centre
// of each cell of a grid over the cloud's box, the distance to the nearest cloud point, so a
// candidate's image points are scored by looking up their cells instead of querying a k-d tree.
#pragma once

#include <functional>
#include <limits>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "glass/geometry/kd_tree.h"

namespace glass::course {

class DistanceGrid {
 public:
  // `resolution` cells along the longest side of the cloud's box; cubic cells.
  DistanceGrid(std::span<const glm::dvec3> cloud, const geometry::KdTree3& tree, int resolution);
  // The distance stored for p's cell; infinity outside the grid. Inline: the searches call it
  // hundreds of millions of times.
  double at(const glm::dvec3& p) const {
    const glm::dvec3 u = (p - lo_) / cell_;
    if (!(u.x >= 0.0 && u.y >= 0.0 && u.z >= 0.0 && u.x < size_[0] && u.y < size_[1] && u.z < size_[2]))
      return std::numeric_limits<double>::infinity();
    return values_[index(static_cast<int>(u.x), static_cast<int>(u.y), static_cast<int>(u.z))];
  }
  double cell() const { return cell_; }
  const glm::dvec3& lo() const { return lo_; }
  int size(int axis) const { return size_[axis]; }

 private:
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * size_[1] + static_cast<std::size_t>(y)) * size_[0] + static_cast<std::size_t>(x);
  }
  glm::dvec3 lo_{0.0};
  double cell_ = 1.0;
  int size_[3] = {1, 1, 1};
  std::vector<double> values_;
};

// A candidate map x -> centre + linear (x - mean), scored by `score(linear, centre)` (smaller is
// better), improved by hill climbing: small turns about the three axes, stretches along them and
// moves of the centre by `shift`, in steps that halve when no move helps. Orientations tried on a
// coarse set of starts are up to about 30 degrees apart, too far for the refinement by
// correspondences to close alone. Returns the improved linear part; `centre` is updated.
using GridScore = std::function<double(const glm::dmat3& linear, const glm::dvec3& centre)>;
glm::dmat3 climbOnGrid(const GridScore& score, glm::dmat3 linear, glm::dvec3& centre, double shift);

// m points of `points` spread out: each the farthest from those chosen before (Gonzalez), from
// the first; they probe a candidate map's image all over.
std::vector<glm::dvec3> spreadPoints(std::span<const glm::dvec3> points, std::size_t m);

}  // namespace glass::course
