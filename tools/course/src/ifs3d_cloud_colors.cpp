#include "glass/course/ifs3d_cloud_colors.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "glass/geometry/kd_tree.h"

namespace glass::course {

namespace g = glass::geometry;

std::vector<int> cloudPartsByMaps(std::span<const glm::dvec3> cloud, std::span<const g::Affine3> maps, std::size_t imagePoints) {
  if (cloud.empty() || maps.empty()) return {};
  // Every stride-th point, so that the images of a large cloud stay within imagePoints.
  const std::size_t perMap = std::max<std::size_t>(1, imagePoints / maps.size());
  const std::size_t stride = std::max<std::size_t>(1, (cloud.size() + perMap - 1) / perMap);
  std::vector<glm::dvec3> images;
  std::vector<int> imageMap;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
      images.push_back(maps[m].apply(cloud[i]));
      imageMap.push_back(static_cast<int>(m));
    }
  }
  const g::KdTree3 tree(images);
  std::vector<int> parts(cloud.size());
  std::vector<double> distances(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const g::KdTree3::Nearest nearest = tree.nearest(cloud[i]);
    parts[i] = imageMap[nearest.index];
    distances[i] = nearest.distanceSquared;
  }
  // The cloud's own spacing: the median distance from a point to the nearest point of the other
  // half (even and odd positions, so that no point finds itself). Not the median distance to the
  // images: in a chaos-game cloud, the image of a point is often the next point itself.
  std::vector<glm::dvec3> halves[2];
  for (std::size_t i = 0; i < cloud.size(); ++i) halves[i % 2].push_back(cloud[i]);
  if (halves[1].empty()) return parts;
  const g::KdTree3 halfTrees[2] = {g::KdTree3(halves[0]), g::KdTree3(halves[1])};
  std::vector<double> spacing(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) spacing[i] = halfTrees[1 - i % 2].nearest(cloud[i]).distanceSquared;
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  // Squared distances: the factor squared.
  const double limit = kUnexplainedFactor * kUnexplainedFactor * *middle;
  if (limit > 0.0) {
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (distances[i] > limit) parts[i] = kUnexplainedPoint;
  }
  return parts;
}

glm::vec3 heightRampColor(double t) {
  static constexpr std::array<glm::vec3, 5> kStops = {glm::vec3(0.25f, 0.45f, 1.0f), glm::vec3(0.1f, 0.8f, 0.9f),
                                                      glm::vec3(0.35f, 0.9f, 0.3f), glm::vec3(1.0f, 0.85f, 0.2f),
                                                      glm::vec3(1.0f, 0.35f, 0.2f)};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(kStops.size() - 1);
  if (x >= static_cast<double>(kStops.size() - 1)) return kStops.back();
  const std::size_t i = static_cast<std::size_t>(x);
  const float f = static_cast<float>(x - static_cast<double>(i));
  return kStops[i] + (kStops[i + 1] - kStops[i]) * f;
}

std::vector<glm::vec3> heightColors(std::span<const glm::dvec3> cloud) {
  double lo = INFINITY, hi = -INFINITY;
  for (const glm::dvec3& p : cloud) {
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  std::vector<glm::vec3> colors;
  colors.reserve(cloud.size());
  for (const glm::dvec3& p : cloud) colors.push_back(heightRampColor(hi > lo ? (p.y - lo) / (hi - lo) : 0.5));
  return colors;
}

}  // namespace glass::course
