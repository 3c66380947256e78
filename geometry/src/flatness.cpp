#include "flatness.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace glass::geometry::detail {
namespace {

// The space the tolerance is measured in: object space, or pixels (z = 0).
struct MeasureSpace {
  std::function<glm::dvec3(const glm::dvec3&)> map;
  double maxDeviation = 0.0;
  double maxExtent = 0.0;  // 0: no limit
};

MeasureSpace measureSpace(const AdaptiveOptions& options) {
  MeasureSpace space;
  if (const auto* object = std::get_if<ObjectSpaceTolerance>(&options.criterion)) {
    space.map = [](const glm::dvec3& p) { return p; };
    space.maxDeviation = object->maxDeviation;
  } else {
    const auto& screen = std::get<ScreenSpaceTolerance>(options.criterion);
    space.map = [project = screen.project](const glm::dvec3& p) {
      if (!project) return p;
      const glm::dvec2 q = project(p);
      return glm::dvec3(q, 0.0);
    };
    space.maxDeviation = screen.maxDeviationPixels;
    space.maxExtent = screen.maxEdgePixels;
  }
  return space;
}

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

double parameterOf(int index, int degree) {
  return degree > 0 ? static_cast<double>(index) / static_cast<double>(degree) : 0.0;
}

bool extentWithin(const std::vector<glm::dvec3>& points, double maxExtent) {
  if (maxExtent <= 0.0) return true;
  AxisAlignedBox box;
  for (const glm::dvec3& p : points) box.include(p);
  const glm::dvec3 size = box.size();
  return size.x <= maxExtent && size.y <= maxExtent && size.z <= maxExtent;
}

}  // namespace

bool isFlatEnough(const BezierSurface& piece, const AdaptiveOptions& options) {
  if (!piece.hasPositiveWeights()) return false;
  const MeasureSpace space = measureSpace(options);
  const int m = piece.degreeU(), n = piece.degreeV();

  std::vector<glm::dvec3> mapped;
  mapped.reserve(static_cast<std::size_t>((m + 1) * (n + 1)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      mapped.push_back(space.map(piece.controlPoint(i, j)));
      if (!finite(mapped.back())) return false;
    }
  const auto at = [&](int i, int j) { return mapped[static_cast<std::size_t>(i * (n + 1) + j)]; };
  const glm::dvec3 c00 = at(0, 0), c10 = at(m, 0), c01 = at(0, n), c11 = at(m, n);
  const auto bilinear = [&](double s, double t) {
    return (1.0 - s) * (1.0 - t) * c00 + s * (1.0 - t) * c10 + (1.0 - s) * t * c01 + s * t * c11;
  };

  double deviation = 0.0;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      deviation = std::max(deviation, glm::length(at(i, j) - bilinear(parameterOf(i, m), parameterOf(j, n))));
  if (piece.isRational()) {
    // The control points of a rational patch do not sit at (i/m, j/n) of its parametrisation:
    // compare true surface points too.
    static constexpr double kSamples[5][2] = {{0.5, 0.5}, {0.5, 0.0}, {0.5, 1.0}, {0.0, 0.5}, {1.0, 0.5}};
    for (const auto& st : kSamples) {
      const glm::dvec3 p = space.map(piece.evaluate(st[0], st[1]));
      if (!finite(p)) return false;
      deviation = std::max(deviation, glm::length(p - bilinear(st[0], st[1])));
    }
  }
  const double twist = glm::length(c00 - c10 - c01 + c11);
  return 2.0 * deviation + 0.25 * twist <= space.maxDeviation && extentWithin(mapped, space.maxExtent);
}

bool isFlatEnough(const BezierCurve& piece, const AdaptiveOptions& options) {
  if (!piece.hasPositiveWeights()) return false;
  const MeasureSpace space = measureSpace(options);
  const int n = piece.degree();
  if (n < 1) return true;

  std::vector<glm::dvec3> mapped;
  for (int i = 0; i <= n; ++i) {
    mapped.push_back(space.map(piece.controlPoint(static_cast<std::size_t>(i))));
    if (!finite(mapped.back())) return false;
  }
  const auto chord = [&](double t) { return (1.0 - t) * mapped.front() + t * mapped.back(); };
  double deviation = 0.0;
  for (int i = 0; i <= n; ++i) deviation = std::max(deviation, glm::length(mapped[i] - chord(parameterOf(i, n))));
  if (piece.isRational()) {
    for (double t : {0.25, 0.5, 0.75}) {
      const glm::dvec3 p = space.map(piece.evaluate(t));
      if (!finite(p)) return false;
      deviation = std::max(deviation, glm::length(p - chord(t)));
    }
  }
  return deviation <= space.maxDeviation && extentWithin(mapped, space.maxExtent);
}

}  // namespace glass::geometry::detail
