#include "glass/geometry/ifs_dimension.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "box_counting.h"
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

std::optional<double> similarityRatio(const Affine2& map) {
  const double c1x = map.m[0][0], c1y = map.m[1][0];
  const double c2x = map.m[0][1], c2y = map.m[1][1];
  const double n1 = c1x * c1x + c1y * c1y;
  const double n2 = c2x * c2x + c2y * c2y;
  const double scale = std::max(n1, n2);
  if (scale == 0.0) return 0.0;  // everything to one point: a similarity with ratio 0
  constexpr double kTolerance = 1e-9;
  if (std::abs(n1 - n2) > kTolerance * scale) return std::nullopt;
  if (std::abs(c1x * c2x + c1y * c2y) > kTolerance * scale) return std::nullopt;
  return std::sqrt((n1 + n2) / 2.0);
}

std::optional<double> solveMoranEquation(std::span<const double> ratios) {
  bool anyPositive = false;
  for (double r : ratios) {
    if (!(r >= 0.0 && r < 1.0)) return std::nullopt;
    anyPositive = anyPositive || r > 0.0;
  }
  if (!anyPositive) return std::nullopt;
  // g(d) = sum r_i^d - 1 is strictly decreasing for 0 < r_i < 1 and tends to -1; 0^d = 0 for d > 0.
  auto g = [&](double d) {
    double sum = 0.0;
    for (double r : ratios) {
      if (r > 0.0) sum += portable::pow(r, d);
    }
    return sum - 1.0;
  };
  if (g(0.0) <= 0.0) return 0.0;  // a single positive ratio: the attractor is a point
  double lo = 0.0, hi = 1.0;
  while (g(hi) > 0.0) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::nullopt;
  }
  // Bisection to the last bit: deterministic and immune to Newton's overshoot.
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = lo + (hi - lo) / 2.0;
    if (mid <= lo || mid >= hi) break;
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return lo + (hi - lo) / 2.0;
}

std::optional<BoxCountingEstimate> boxCountingDimension(std::span<const glm::dvec2> points) {
  if (points.size() < 1000) return std::nullopt;
  double xMin = points[0].x, xMax = xMin, yMin = points[0].y, yMax = yMin;
  for (const glm::dvec2& p : points) {
    xMin = std::min(xMin, p.x);
    xMax = std::max(xMax, p.x);
    yMin = std::min(yMin, p.y);
    yMax = std::max(yMax, p.y);
  }
  const double side = std::max(xMax - xMin, yMax - yMin);
  if (!(side > 0.0) || !std::isfinite(side)) return std::nullopt;
  return box_counting::estimate(points.size(), side, 24, [&](int level, std::size_t i) {
    const double cells = std::ldexp(1.0, level);
    const std::uint64_t maxCell = (std::uint64_t{1} << level) - 1;
    // The top and right edges of the square belong to the last box.
    const auto cx = std::min(static_cast<std::uint64_t>((points[i].x - xMin) / side * cells), maxCell);
    const auto cy = std::min(static_cast<std::uint64_t>((points[i].y - yMin) / side * cells), maxCell);
    return (cx << 32) | cy;
  });
}

IfsDimensionReport ifsDimension(const IteratedFunctionSystem& ifs, std::uint64_t points, std::uint64_t seed) {
  return box_counting::dimensionReport(
      ifs.maps.size(), [&](std::size_t i) { return similarityRatio(ifs.maps[i].transform); },
      [&](IfsDimensionReport& report) {
        const auto probabilities = chaosGameProbabilities(ifs);
        if (!probabilities) {
          report.problem = "the maps' probabilities are invalid";
          return;
        }
        std::vector<glm::dvec2> cloud;
        cloud.reserve(points);
        chaosGame(ifs, *probabilities, points, seed, [&cloud](const glm::dvec2& p, int) { cloud.push_back(p); });
        report.boxCounting = boxCountingDimension(cloud);
        if (!report.boxCounting) report.problem = "the attractor is too small or too thin for box counting";
      });
}

}  // namespace glass::geometry
