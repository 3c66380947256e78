// Box counting, shared by the plane (ifs_dimension.h) and space (ifs3d_dimension.h): count the
// occupied boxes level by level and fit the slope of log2 N against the level.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "glass/geometry/ifs_dimension.h"
#include "glass/geometry/portable_math.h"

namespace glass::geometry::box_counting {

// boxKey(level, i): the key of the box of side `side` / 2^level holding point i. Levels run from 0
// until the count passes a twentieth of the points (beyond, N levels off at the number of
// points) or maxLevel; levels 2 to the last well-sampled one are fitted.
template <class BoxKey>
std::optional<BoxCountingEstimate> estimate(std::size_t pointCount, double side, int maxLevel, const BoxKey& boxKey) {
  BoxCountingEstimate estimate;
  std::vector<std::uint64_t> keys(pointCount);
  const std::size_t wellSampled = pointCount / 20;
  for (int level = 0; level <= maxLevel; ++level) {
    for (std::size_t i = 0; i < pointCount; ++i) keys[i] = boxKey(level, i);
    std::sort(keys.begin(), keys.end());
    const auto boxes = static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
    estimate.counts.push_back({level, side / std::ldexp(1.0, level), boxes});
    if (boxes > wellSampled) break;
  }
  estimate.firstFittedLevel = 2;
  estimate.lastFittedLevel = 2;
  for (const BoxCount& count : estimate.counts) {
    if (count.level >= 2 && count.boxes <= wellSampled) estimate.lastFittedLevel = count.level;
  }
  if (estimate.lastFittedLevel - estimate.firstFittedLevel < 2) return std::nullopt;
  double sumX = 0.0, sumY = 0.0, sumXX = 0.0, sumXY = 0.0;
  int n = 0;
  for (const BoxCount& count : estimate.counts) {
    if (count.level < estimate.firstFittedLevel || count.level > estimate.lastFittedLevel) continue;
    const double x = count.level, y = portable::log2(static_cast<double>(count.boxes));
    sumX += x;
    sumY += y;
    sumXX += x * x;
    sumXY += x * y;
    ++n;
  }
  estimate.dimension = (n * sumXY - sumX * sumY) / (n * sumXX - sumX * sumX);
  return estimate;
}

// The dimension report of r maps: Moran's equation when ratioOf(i) gives every map's similarity
// ratio, else boxCount(report), which fills report.boxCounting or report.problem.
template <class RatioOf, class BoxCount>
IfsDimensionReport dimensionReport(std::size_t maps, const RatioOf& ratioOf, const BoxCount& boxCount) {
  IfsDimensionReport report;
  report.allSimilarities = maps != 0;
  std::vector<double> ratios;
  for (std::size_t i = 0; i < maps; ++i) {
    report.ratios.push_back(ratioOf(i));
    if (report.ratios.back()) {
      ratios.push_back(*report.ratios.back());
    } else {
      report.allSimilarities = false;
    }
  }
  if (report.allSimilarities) {
    report.moranDimension = solveMoranEquation(ratios);
    if (report.moranDimension) return report;
  }
  boxCount(report);
  return report;
}

}  // namespace glass::geometry::box_counting
