// The fractal dimension of an IFS attractor (section 2.2.2 of the study guide).
//  - When every map is a similarity with ratio 0 < r_i < 1, the Moran equation (the guide's
//    equation 4) r_1^d + ... + r_r^d = 1 has one root d, the similarity dimension; it is the
//    Hausdorff and box dimension when the parts do not overlap (the open set condition), as in
//    the guide's examples.
//  - Otherwise the box-counting dimension is estimated from points of the attractor: the slope of
//    log N(eps) against log(1/eps), N(eps) the number of eps-boxes holding a point.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "glass/geometry/affine2d.h"
#include "glass/geometry/ifs.h"

namespace glass::geometry {

// The ratio r of a similarity (a map that changes every distance by the factor r: its linear part
// is r times a rotation or a reflection, L^T L = r^2 I), or nothing when the map is not one.
// Relative tolerance 1e-9 on |c1| = |c2| and c1 . c2 = 0 for the columns c1, c2 of L.
std::optional<double> similarityRatio(const Affine2& map);

// The root d >= 0 of sum r_i^d = 1 for ratios in [0, 1): ratio-0 maps (a whole plane sent to a
// point) add nothing. Empty when a ratio is outside [0, 1) or no ratio is positive.
std::optional<double> solveMoranEquation(std::span<const double> ratios);

struct BoxCount {
  int level = 0;           // boxes of side (bounding square side) / 2^level
  double boxSide = 0.0;
  std::size_t boxes = 0;   // occupied boxes N
};

struct BoxCountingEstimate {
  double dimension = 0.0;            // least-squares slope of log2 N against level
  std::vector<BoxCount> counts;      // every level counted
  int firstFittedLevel = 0, lastFittedLevel = 0;
};

// Box counting on the bounding square of the points. Levels are fitted from 2 up to the last one
// whose box count stays below a twentieth of the number of points, beyond which the boxes are no
// longer well sampled and N levels off at the number of points. Needs at least 1000 points.
std::optional<BoxCountingEstimate> boxCountingDimension(std::span<const glm::dvec2> points);

struct IfsDimensionReport {
  std::vector<std::optional<double>> ratios;  // per map: its similarity ratio, or none
  bool allSimilarities = false;
  std::optional<double> moranDimension;       // when all maps are similarities with r < 1
  std::optional<BoxCountingEstimate> boxCounting;  // otherwise, from the chaos game
  std::string problem;                         // why no dimension could be given, if none
};

// Moran when possible; else box counting over `points` chaos-game points from `seed`.
IfsDimensionReport ifsDimension(const IteratedFunctionSystem& ifs, std::uint64_t points = 2'000'000,
                                std::uint64_t seed = 1);

}  // namespace glass::geometry
