// Homework 3's fit: the judgements of the collage path (glass/course/ifs3d_collage_path.h), on
// random systems of the course generator with seeds of no battery list. With two maps wrong at
// once, the wrong ones are those whose image falls out of the cloud, and a set of maps with one
// swollen or one shrunk to a point is not ranked by the collage distance.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "glass/course/ifs3d_collage_path.h"
#include "glass/course/ifs3d_random.h"
#include "glass/geometry/kd_tree.h"

namespace g = glass::geometry;
namespace c = glass::course;

namespace {

constexpr std::uint64_t kSeeds[] = {120001, 120002, 120003, 120004, 120005, 120006};

std::vector<g::Affine3> trueMaps(std::uint64_t seed) {
  std::vector<g::Affine3> maps;
  for (const auto& map : c::randomIfs3(seed).maps) maps.push_back(map.transform);
  return maps;
}

// The map turned by a quarter turn about its image of the cloud's centre: same size and place,
// wrong orientation, the way a fit's wrong maps are.
g::Affine3 turned(const g::Affine3& map, const glm::dvec3& axis) {
  const glm::dvec3 pivot = map.apply(glm::dvec3(0.5));
  return g::Affine3::translation(pivot) * g::Affine3::rotationDegrees(90.0, axis) * g::Affine3::translation(-pivot) * map;
}

}  // namespace

TEST_CASE("course homework 3: with two maps wrong, the collage path replaces those whose image leaves the cloud") {
  for (const std::uint64_t seed : kSeeds) {
    CAPTURE(seed);
    const std::vector<g::Affine3> truth = trueMaps(seed);
    const std::vector<glm::dvec3> cloud = c::ifs3Cloud(c::randomIfs3(seed), 10000, 0.0, seed + 5);
    const std::vector<glm::dvec3> source(cloud.begin(), cloud.begin() + 1000);
    const g::KdTree3 cloudTree(cloud);
    // The right maps: any order, but each within the cloud.
    REQUIRE(c::mapsByInclusion(truth, source, cloudTree, 0.02).size() == 4);
    for (std::size_t first = 0; first < 4; ++first) {
      const std::size_t second = (first + 2) % 4;
      std::vector<g::Affine3> maps = truth;
      maps[first] = turned(truth[first], {1.0, 0.0, 0.0});
      maps[second] = turned(truth[second], {0.0, 1.0, 1.0});
      const std::vector<std::size_t> order = c::mapsByInclusion(maps, source, cloudTree, 0.02);
      REQUIRE(order.size() == 4);
      CAPTURE(first);
      CHECK(std::min(order[0], order[1]) == std::min(first, second));
      CHECK(std::max(order[0], order[1]) == std::max(first, second));
    }
  }
}

TEST_CASE("course homework 3: the collage path ranks no set with a swollen or a collapsed map") {
  for (const std::uint64_t seed : kSeeds) {
    CAPTURE(seed);
    const std::vector<g::Affine3> truth = trueMaps(seed);
    CHECK(c::stretchesWithinCollagePath(truth));
    for (std::size_t i = 0; i < 4; ++i) {
      std::vector<g::Affine3> swollen = truth, collapsed = truth;
      // About the map's image of the centre, so that it stays in place.
      const glm::dvec3 pivot = truth[i].apply(glm::dvec3(0.5));
      swollen[i] = g::Affine3::translation(pivot) * g::Affine3::scaling(glm::dvec3(4.0)) * g::Affine3::translation(-pivot) * truth[i];
      collapsed[i] = g::Affine3::translation(pivot) * g::Affine3::scaling(glm::dvec3(0.1)) * g::Affine3::translation(-pivot) * truth[i];
      CHECK_FALSE(c::stretchesWithinCollagePath(swollen));
      CHECK_FALSE(c::stretchesWithinCollagePath(collapsed));
    }
  }
}
