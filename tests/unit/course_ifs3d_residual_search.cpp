// Homework 3's fit: the search for a map the fit misses, from the points the other maps leave
// uncovered (glass/course/ifs3d_residual_search.h). Each case takes a random system of the course
// generator (seeds of no battery list), replaces one true map by a copy of another (two maps on
// one part, the way a fit fails when a small part hides inside larger ones), and checks that the
// copy is found least needed, that the uncovered points lie in the missing map's image, and that
// the search finds the missing map from them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "glass/course/ifs3d_distance_grid.h"
#include "glass/course/ifs3d_orientations.h"
#include "glass/course/ifs3d_random.h"
#include "glass/course/ifs3d_residual_search.h"
#include "glass/geometry/kd_tree.h"

namespace g = glass::geometry;
namespace c = glass::course;

namespace {

constexpr std::size_t kPoints = 10000;

struct Case {
  std::vector<g::Affine3> truth;
  std::vector<glm::dvec3> cloud;
  double spacing = 0.0;  // mean nearest-neighbour distance within the cloud
};

Case caseOf(std::uint64_t seed) {
  Case out;
  const g::IteratedFunctionSystem3 ifs = c::randomIfs3(seed);
  for (const auto& map : ifs.maps) out.truth.push_back(map.transform);
  out.cloud = c::ifs3Cloud(ifs, kPoints, 0.0, seed + 5);
  REQUIRE(out.cloud.size() == kPoints);
  // Half the cloud against the other half, scaled to the whole cloud's density.
  const std::span<const glm::dvec3> all(out.cloud);
  const g::KdTree3 half(all.subspan(kPoints / 2));
  for (const glm::dvec3& p : all.first(kPoints / 2)) out.spacing += std::sqrt(half.nearest(p).distanceSquared);
  out.spacing = out.spacing / (kPoints / 2) * std::cbrt(0.5);
  return out;
}

// The true maps with map `missing` replaced by a copy of the next one.
std::vector<g::Affine3> withCopy(const std::vector<g::Affine3>& truth, std::size_t missing) {
  std::vector<g::Affine3> maps = truth;
  maps[missing] = truth[(missing + 1) % truth.size()];
  return maps;
}

// What the residual search reads of a system's cloud: its distance grid (`resolution` cells along
// the longest side), its mean and spread points of it.
struct SearchInputs {
  c::DistanceGrid grid;
  glm::dvec3 mean{0.0};
  std::span<const glm::dvec3> probes;
};

SearchInputs searchInputsOf(const Case& system, int resolution) {
  const g::KdTree3 tree(system.cloud);
  SearchInputs inputs{c::DistanceGrid(system.cloud, tree, resolution), glm::dvec3(0.0), {}};
  for (const glm::dvec3& p : system.cloud) inputs.mean += p;
  inputs.mean /= static_cast<double>(system.cloud.size());
  inputs.probes = std::span<const glm::dvec3>(system.cloud).first(2000);
  return inputs;
}

}  // namespace

TEST_CASE("course homework 3: the right maps leave almost nothing uncovered, a missing map its own points") {
  const Case system = caseOf(90001);
  const double limit = 3.0 * system.spacing;
  CHECK(c::uncoveredPoints(system.truth, system.cloud, system.cloud, limit).size() < kPoints / 200);
  for (std::size_t missing = 0; missing < 4; ++missing) {
    const std::vector<glm::dvec3> residual = c::uncoveredPoints(withCopy(system.truth, missing), system.cloud, system.cloud, limit);
    CHECK(residual.size() > kPoints / 20);
    // Every uncovered point lies in the image of the missing map (the others' images are right).
    std::vector<glm::dvec3> image;
    for (const glm::dvec3& p : system.cloud) image.push_back(system.truth[missing].apply(p));
    const g::KdTree3 imageTree(image);
    std::size_t outside = 0;
    for (const glm::dvec3& p : residual) outside += imageTree.nearest(p).distanceSquared > limit * limit;
    CHECK(outside == 0);
  }
}

TEST_CASE("course homework 3: of two maps on one part, one is the least needed") {
  const Case system = caseOf(90001);
  const std::span<const glm::dvec3> points = std::span<const glm::dvec3>(system.cloud).first(3000);
  for (std::size_t missing = 0; missing < 4; ++missing) {
    const std::vector<std::size_t> order = c::mapsByOwnCover(withCopy(system.truth, missing), system.cloud, points, 0.03);
    REQUIRE(order.size() == 4);
    // The copy and its original cover nothing alone; the two come first.
    const std::size_t copy = missing, original = (missing + 1) % 4;
    CHECK(std::min(order[0], order[1]) == std::min(copy, original));
    CHECK(std::max(order[0], order[1]) == std::max(copy, original));
  }
}

TEST_CASE("course homework 3: the missing map is found from the uncovered points") {
  // Systems and missing maps the search finds; on others it may not (the fit then tries its
  // other starts), so these check that it works where it should, within the fit's tolerance.
  const struct {
    std::uint64_t seed;
    std::size_t missing;
  } cases[] = {{90001, 2}, {90002, 3}, {90003, 1}};
  const std::vector<glm::dmat3> orientations = c::startingOrientations();
  for (const auto& [seed, missing] : cases) {
    CAPTURE(seed);
    const Case system = caseOf(seed);
    const SearchInputs inputs = searchInputsOf(system, 40);
    const c::ResidualSearch search{&inputs.grid, inputs.mean, inputs.probes, orientations};
    const std::vector<glm::dvec3> residual =
        c::uncoveredPoints(withCopy(system.truth, missing), system.cloud, system.cloud, 3.0 * system.spacing);
    const std::vector<g::Affine3> found = c::residualCandidates(search, residual, 3);
    REQUIRE(!found.empty());
    double nearest = INFINITY;
    for (const g::Affine3& map : found) nearest = std::min(nearest, g::Affine3::maxDifference(map, system.truth[missing]));
    CHECK(nearest < 0.03);
    // Too few points to search from: nothing.
    CHECK(c::residualCandidates(search, std::span<const glm::dvec3>(residual).first(7), 3).empty());
  }
}

TEST_CASE("course homework 3: the residual search's bounded vote, on any number of threads, chooses what a vote in full chooses") {
  // The vote stops summing a candidate's score once it cannot rank among the best voteDepth so
  // far; the candidates must be the same bytes as with every score in full (depth 0), also when
  // the depth is too shallow for the candidates kept and the rest must be scored after all (1),
  // and on several threads, which share the bound.
  // A coarser grid than the fit's keeps the votes in full quick.
  const std::vector<glm::dmat3> orientations = c::startingOrientations();
  for (const std::uint64_t seed : {90001u, 90004u}) {
    CAPTURE(seed);
    const Case system = caseOf(seed);
    const SearchInputs inputs = searchInputsOf(system, 24);
    for (std::size_t missing = 0; missing < 4; missing += 3) {
      CAPTURE(missing);
      const std::vector<glm::dvec3> residual =
          c::uncoveredPoints(withCopy(system.truth, missing), system.cloud, system.cloud, 3.0 * system.spacing);
      std::vector<std::vector<g::Affine3>> found;
      const struct {
        std::size_t depth;
        int threads;
      } votes[] = {{0, 1}, {1, 1}, {2000, 1}, {2000, 3}, {1, 2}};
      for (const auto& [depth, threads] : votes) {
        c::ResidualSearch search{&inputs.grid, inputs.mean, inputs.probes, orientations};
        search.voteDepth = depth;
        search.threads = threads;
        found.push_back(c::residualCandidates(search, residual, 3));
      }
      REQUIRE(found[0].size() == 3);
      for (std::size_t depth = 1; depth < found.size(); ++depth) {
        REQUIRE(found[depth].size() == found[0].size());
        for (std::size_t i = 0; i < found[0].size(); ++i)
          CHECK(std::memcmp(&found[depth][i].m, &found[0][i].m, sizeof found[0][i].m) == 0);
      }
    }
  }
}

TEST_CASE("course homework 3: uncovered points split into clusters, largest first") {
  // Two blobs of points on lines (spacing 0.01), a pair, and a point alone.
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 30; ++i) points.push_back({0.01 * i, 0.0, 0.0});
  for (int i = 0; i < 50; ++i) points.push_back({0.5, 0.5, 0.01 * i});
  points.push_back({0.9, 0.9, 0.9});
  points.push_back({0.2, 0.8, 0.1});
  points.push_back({0.205, 0.8, 0.1});
  const std::vector<std::vector<glm::dvec3>> clusters = c::residualClusters(points, 0.015);
  REQUIRE(clusters.size() == 4);
  CHECK(clusters[0].size() == 50);
  CHECK(clusters[1].size() == 30);
  CHECK(clusters[2].size() == 2);
  CHECK(clusters[3].size() == 1);
  for (const glm::dvec3& p : clusters[0]) CHECK(p.x == 0.5);
  // A link shorter than the spacing leaves every point alone.
  CHECK(c::residualClusters(points, 0.004).size() == points.size());
}
