#include "glass/course/ifs3d_distance_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>

#include "glass/geometry/rotation.h"

namespace glass::course {

namespace g = glass::geometry;

DistanceGrid::DistanceGrid(std::span<const glm::dvec3> cloud, const g::KdTree3& tree, int resolution) {
  lo_ = glm::dvec3(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : cloud) {
    lo_ = glm::min(lo_, p);
    hi = glm::max(hi, p);
  }
  cell_ = std::max({hi.x - lo_.x, hi.y - lo_.y, hi.z - lo_.z, 1e-9}) / resolution;
  for (int a = 0; a < 3; ++a) size_[a] = std::max(1, static_cast<int>(std::ceil((hi[a] - lo_[a]) / cell_)));
  values_.resize(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2]);
  for (int z = 0; z < size_[2]; ++z)
    for (int y = 0; y < size_[1]; ++y)
      for (int x = 0; x < size_[0]; ++x) {
        const glm::dvec3 centre = lo_ + (glm::dvec3(x, y, z) + 0.5) * cell_;
        values_[index(x, y, z)] = std::sqrt(tree.nearest(centre).distanceSquared);
      }
}

glm::dmat3 climbOnGrid(const GridScore& score, glm::dmat3 linear, glm::dvec3& centre, double shift) {
  double best = score(linear, centre);
  double angle = 8.0, stretch = 0.08;
  for (int iteration = 0; iteration < 40 && angle > 1.0; ++iteration) {
    glm::dmat3 bestLinear = linear;
    glm::dvec3 bestCentre = centre;
    double bestScore = best;
    for (int axis = 0; axis < 3; ++axis) {
      for (const double sign : {-1.0, 1.0}) {
        glm::dvec3 unit(0.0);
        unit[axis] = 1.0;
        const glm::dmat3 turned = linear * g::rotationMatrixDegrees(unit, sign * angle);
        glm::dmat3 stretched = linear;
        stretched[axis] *= 1.0 + sign * stretch;
        const glm::dvec3 moved = centre + sign * shift * unit;
        for (const auto& [l, c] : {std::pair{turned, centre}, std::pair{stretched, centre}, std::pair{linear, moved}}) {
          const double s = score(l, c);
          if (s < bestScore) {
            bestScore = s;
            bestLinear = l;
            bestCentre = c;
          }
        }
      }
    }
    if (bestScore < best) {
      best = bestScore;
      linear = bestLinear;
      centre = bestCentre;
    } else {
      angle /= 2.0;
      stretch /= 2.0;
      shift /= 2.0;
    }
  }
  return linear;
}

std::vector<glm::dvec3> spreadPoints(std::span<const glm::dvec3> points, std::size_t m) {
  std::vector<glm::dvec3> chosen{points.front()};
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
  while (chosen.size() < std::min(m, points.size())) {
    std::size_t farthest = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      nearest[i] = std::min(nearest[i], glm::dot(points[i] - chosen.back(), points[i] - chosen.back()));
      if (nearest[i] > nearest[farthest]) farthest = i;
    }
    chosen.push_back(points[farthest]);
  }
  return chosen;
}

}  // namespace glass::course
