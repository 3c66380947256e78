#include "glass/course/ifs3d_random.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include <glm/geometric.hpp>

#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/rotation.h"
#include "glass/geometry/portable_math.h"

namespace glass::course {

namespace g = glass::geometry;

g::IteratedFunctionSystem3 randomIfs3(std::uint64_t seed) {
  // The seed is mixed once first: SplitMix64 steps its state by a constant, so states seed and
  // seed + 1 (times that constant) would give the same numbers one step apart.
  g::SplitMix64 random(g::SplitMix64(seed).next());
  g::IteratedFunctionSystem3 ifs;
  ifs.name = "random system " + std::to_string(seed);
  constexpr int kMaps = 4;
  const std::uint64_t reflecting = random.below(kMaps);
  for (int i = 0; i < kMaps; ++i) {
    const double ratio = 0.3 + 0.3 * random.uniform();
    glm::dvec3 scales(ratio);
    if (random.uniform() < 0.5) {
      for (int a = 0; a < 3; ++a) scales[a] = ratio * (0.75 + 0.5 * random.uniform());
    }
    if (static_cast<std::uint64_t>(i) == reflecting) scales.z = -scales.z;
    // An axis uniform on the sphere (z uniform in [-1, 1], longitude uniform) and any angle.
    const double z = 2.0 * random.uniform() - 1.0, longitude = 2.0 * std::numbers::pi * random.uniform();
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 axis{rho * portable::cos(longitude), rho * portable::sin(longitude), z};
    const double angle = 360.0 * random.uniform() - 180.0;
    const g::Affine3 linear = g::Affine3::rotationDegrees(angle, axis) * g::Affine3::scaling(scales);
    // The image of the unit cube's corners: its box, placed at random inside the unit cube.
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p = linear.apply({double(corner & 1), double((corner >> 1) & 1), double((corner >> 2) & 1)});
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    glm::dvec3 t;
    for (int a = 0; a < 3; ++a) t[a] = -lo[a] + random.uniform() * std::max(0.0, 1.0 - (hi[a] - lo[a]));
    ifs.maps.push_back({g::Affine3::translation(t) * linear, std::nullopt, std::nullopt});
  }
  return ifs;
}

std::vector<glm::dvec3> ifs3Cloud(const g::IteratedFunctionSystem3& ifs, std::size_t count, double noise, std::uint64_t seed) {
  std::vector<glm::dvec3> points;
  const auto probabilities = g::chaosGameProbabilities3(ifs);
  if (!probabilities) return points;
  for (const g::IfsPoint3& p : g::chaosGamePoints3(ifs, *probabilities, count, seed)) points.push_back(p.position);
  g::SplitMix64 random(seed + 99);
  for (glm::dvec3& p : points) {
    if (random.uniform() < noise) p = {random.uniform(), random.uniform(), random.uniform()};
  }
  return points;
}

double ifs3MapError(const std::vector<g::Affine3>& truth, const std::vector<g::Affine3>& found) {
  if (truth.size() != found.size() || truth.size() > 8) return std::numeric_limits<double>::infinity();
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  double best = std::numeric_limits<double>::infinity();
  do {
    double worst = 0.0;
    for (std::size_t i = 0; i < order.size(); ++i) worst = std::max(worst, g::Affine3::maxDifference(truth[i], found[order[i]]));
    best = std::min(best, worst);
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

}  // namespace glass::course
