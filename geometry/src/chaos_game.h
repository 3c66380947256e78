// The chaos game's steps, shared by the IFS of the plane (ifs.h) and of space (ifs3d.h): the
// probabilities of the maps and the seeded random walk.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glass/geometry/deterministic_random.h"

namespace glass::geometry::chaos {

// Given probabilities normalised; when none is given, weights proportional to |det L_i| (the share
// of area or volume map i keeps: Barnsley's rule), each at least 1/100 of the largest so that a
// flattening map still gets points. Empty when some are given and some not, one is negative, or
// all are 0.
std::optional<std::vector<double>> probabilities(std::span<const std::optional<double>> given,
                                                 std::span<const double> absDeterminants);

// The walk x_{k+1} = f_i(x_k): 100 unrecorded steps from `start` (forgetting it), then `count`
// reported ones, each with the map that made it. step(i, x) applies map i.
template <class Point, class Step, class Visit>
void walk(const std::vector<double>& probabilities, Point start, std::uint64_t count, std::uint64_t seed,
          const Step& step, const Visit& visit) {
  const std::size_t n = probabilities.size();
  if (n == 0) return;
  // Cumulative probabilities; the last is forced to 1 so that rounding never lets u fall past it.
  std::vector<double> cumulative(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) cumulative[i] = (sum += probabilities[i]);
  cumulative[n - 1] = 1.0;
  SplitMix64 random(seed);
  constexpr int kWarmUp = 100;
  Point point = start;
  for (std::uint64_t k = 0; k < count + kWarmUp; ++k) {
    const double u = random.uniform();
    const std::size_t i = static_cast<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    const std::size_t chosen = std::min(i, n - 1);
    point = step(chosen, point);
    if (k >= kWarmUp) visit(point, static_cast<int>(chosen));
  }
}

}  // namespace glass::geometry::chaos
