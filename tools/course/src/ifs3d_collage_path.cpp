#include "glass/course/ifs3d_collage_path.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "glass/geometry/polar_decomposition.h"

namespace glass::course {

namespace g = glass::geometry;

bool stretchesWithinCollagePath(std::span<const g::Affine3> maps) {
  for (const g::Affine3& map : maps) {
    const glm::dmat3 l = map.linearPart();
    // The squared singular values of L are the eigenvalues of L^T L.
    const glm::dvec3 squared = g::symmetricEigen(glm::transpose(l) * l).values;
    const double largest = std::sqrt(std::max({squared.x, squared.y, squared.z}));
    if (!(largest >= kCollagePathStretches[0] && largest <= kCollagePathStretches[1])) return false;
  }
  return true;
}

std::vector<std::size_t> mapsByInclusion(std::span<const g::Affine3> maps, std::span<const glm::dvec3> source, const g::KdTree3& cloudTree,
                                         double trim) {
  std::vector<double> inclusion;
  for (const g::Affine3& map : maps) {
    std::vector<double> distances;
    for (const glm::dvec3& p : source) distances.push_back(std::sqrt(cloudTree.nearest(map.apply(p)).distanceSquared));
    // The mean of the smallest (1 - trim) share, as the fit's trimmed means.
    const std::size_t keep = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(distances.size() * (1.0 - trim))));
    std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(keep - 1), distances.end());
    double sum = 0.0;
    for (std::size_t i = 0; i < keep && i < distances.size(); ++i) sum += distances[i];
    inclusion.push_back(distances.empty() ? 0.0 : sum / static_cast<double>(keep));
  }
  std::vector<std::size_t> order(maps.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return inclusion[a] > inclusion[b]; });
  return order;
}

}  // namespace glass::course
