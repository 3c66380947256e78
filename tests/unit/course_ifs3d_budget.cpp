// Homework 3's fit under its work budget (Ifs3FitOptions::workBudget): a cloud that no system of
// four affine maps makes (points on a sphere: an affine contraction of a sphere is a smaller
// ellipsoid, which does not lie on the sphere) is never fitted, and the search must stop after
// about the work it was given and say so, always at the same place; a cloud that is fitted on the
// first stages must not need the budget at all.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "glass/course/ifs3d_fit.h"
#include "glass/course/ifs3d_random.h"
#include "glass/geometry/deterministic_random.h"

namespace g = glass::geometry;
namespace c = glass::course;

namespace {

// Points spread uniformly on the sphere of radius 0.4 about the centre of the unit cube.
std::vector<glm::dvec3> sphereCloud(std::size_t count, std::uint64_t seed) {
  g::SplitMix64 random(seed);
  std::vector<glm::dvec3> points;
  while (points.size() < count) {
    const glm::dvec3 d(2.0 * random.uniform() - 1.0, 2.0 * random.uniform() - 1.0, 2.0 * random.uniform() - 1.0);
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (length < 0.1 || length > 1.0) continue;
    points.push_back(glm::dvec3(0.5) + 0.4 * d / length);
  }
  return points;
}

// The most the search may overrun its budget: the budget is looked at between its steps, so the
// step that spends it (at most one start or re-seeding, about a million queries at these sizes)
// and the finishing of the best maps (a refinement and the measures) run on.
constexpr std::uint64_t kOverrun = 4'000'000;

}  // namespace

TEST_CASE("course homework 3: a cloud no system makes stops at the work budget and says so") {
  const std::vector<glm::dvec3> cloud = sphereCloud(2000, 7);
  c::Ifs3FitOptions options;
  options.workBudget = 3'000'000;
  const c::Ifs3Fit fit = c::fitIfs3(cloud, options);
  INFO("work " << fit.work << " queries in " << fit.attempts << " attempts");
  CHECK_FALSE(fit.converged());
  CHECK(fit.stoppedByBudget);
  CHECK(fit.work >= options.workBudget);
  CHECK(fit.work < options.workBudget + kOverrun);
  CHECK(fit.attempts < options.attempts);
  CHECK(fit.maps.size() == 4);

  // Counted, not timed: the same cloud stops at the same place with the same maps.
  const c::Ifs3Fit again = c::fitIfs3(cloud, options);
  CHECK(again.work == fit.work);
  CHECK(again.attempts == fit.attempts);
  REQUIRE(again.maps.size() == fit.maps.size());
  for (std::size_t i = 0; i < fit.maps.size(); ++i) CHECK(g::Affine3::maxDifference(again.maps[i], fit.maps[i]) == 0.0);

  // A larger budget lets it search longer.
  options.workBudget = 2 * fit.work;
  const c::Ifs3Fit longer = c::fitIfs3(cloud, options);
  CHECK(longer.work > fit.work);
  CHECK(longer.work < options.workBudget + kOverrun);
}

TEST_CASE("course homework 3: a cloud fitted on the first stages is finished early") {
  // Tuning seed 2 of the fit battery: found in the first attempt. The search stops as soon as a
  // stage's maps have converged, before the first attempt's later stages, so a budget of 12
  // million queries (with which an unfittable cloud gives up in about a third of the time) leaves
  // it as it is.
  const g::IteratedFunctionSystem3 ifs = c::randomIfs3(2);
  const std::vector<glm::dvec3> cloud = c::ifs3Cloud(ifs, 6000, 0.0, 7);
  const c::Ifs3Fit fit = c::fitIfs3(cloud);
  std::vector<g::Affine3> truth;
  for (const auto& map : ifs.maps) truth.push_back(map.transform);
  INFO("work " << fit.work << " queries, largest matrix entry error " << c::ifs3MapError(truth, fit.maps));
  CHECK(c::ifs3MapError(truth, fit.maps) < 0.03);
  CHECK(fit.converged());
  CHECK_FALSE(fit.stoppedByBudget);
  CHECK(fit.attempts == 1);
  CHECK(fit.work < 8'000'000);
  c::Ifs3FitOptions budgeted;
  budgeted.workBudget = 12'000'000;
  const c::Ifs3Fit withBudget = c::fitIfs3(cloud, budgeted);
  CHECK(withBudget.work == fit.work);
  REQUIRE(withBudget.maps.size() == fit.maps.size());
  for (std::size_t i = 0; i < fit.maps.size(); ++i) CHECK(g::Affine3::maxDifference(withBudget.maps[i], fit.maps[i]) == 0.0);
}
