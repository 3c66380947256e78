#include "patch_boundaries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>

namespace glass::geometry::detail {
namespace {

using Homogeneous = std::vector<glm::dvec4>;

bool lessPoint(const glm::dvec4& a, const glm::dvec4& b) {
  for (int k = 0; k < 4; ++k)
    if (a[k] != b[k]) return a[k] < b[k];
  return false;
}

struct LessRow {
  bool operator()(const Homogeneous& a, const Homogeneous& b) const {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), lessPoint);
  }
};

// Compared projected: the weights of a collapsed rational row differ, and w p / w may round p.
bool isCollapsed(const Homogeneous& row) {
  if (row.front().w == 0.0) return false;
  const glm::dvec3 first = glm::dvec3(row.front()) / row.front().w;
  const double slack = 1e-14 * (1.0 + glm::length(first));
  return std::all_of(row.begin(), row.end(), [&](const glm::dvec4& h) {
    return h.w != 0.0 && glm::length(glm::dvec3(h) / h.w - first) <= slack;
  });
}

// The one point of a collapsed row: a control point of weight 1 if there is one (it is exact, and
// it is the corner the neighbouring sides end in), else the first.
glm::dvec3 collapsedPointOf(const Homogeneous& row) {
  for (const glm::dvec4& h : row)
    if (h.w == 1.0) return glm::dvec3(h);
  return glm::dvec3(row.front()) / row.front().w;
}

}  // namespace

PatchBoundaries::PatchBoundaries(std::span<const BezierSurface> patches) : sides_(patches.size()) {
  std::map<Homogeneous, std::vector<PatchSideRef>, LessRow> byCurve;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    for (PatchSide side : kAllSides) {
      const BezierCurve curve = patches[p].boundary(side);
      const std::span<const glm::dvec4> forward = curve.homogeneousControlPoints();
      const Homogeneous backward(forward.rbegin(), forward.rend());
      const bool reversed = LessRow{}(backward, Homogeneous(forward.begin(), forward.end()));
      Side& entry = sides_[p][sideIndex(side)];
      entry.reversed = reversed;
      entry.canonical = reversed ? curve.reversed() : curve;
      const Homogeneous key(entry.canonical.homogeneousControlPoints().begin(),
                            entry.canonical.homogeneousControlPoints().end());
      entry.collapsed = !key.empty() && isCollapsed(key);
      if (entry.collapsed) entry.collapsedPoint = collapsedPointOf(key);
      if (!key.empty() && !entry.collapsed) byCurve[key].push_back({p, side});
    }
  }
  // A pole shared by several patches is one point: a patch cut from a rational net between its
  // weight-1 control points (a sphere corner split through its pole) has none of weight 1 in its
  // collapsed row, and its projected control point may differ from the exact pole in the last
  // bit. It takes the exact point of a neighbour's pole within the same slack.
  std::vector<const Side*> exactPoles;
  std::vector<Side*> inexactPoles;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    for (PatchSide side : kAllSides) {
      Side& entry = sides_[p][sideIndex(side)];
      if (!entry.collapsed) continue;
      const BezierCurve curve = patches[p].boundary(side);
      const auto row = curve.homogeneousControlPoints();
      if (std::any_of(row.begin(), row.end(), [](const glm::dvec4& h) { return h.w == 1.0; }))
        exactPoles.push_back(&entry);
      else
        inexactPoles.push_back(&entry);
    }
  }
  for (Side* pole : inexactPoles) {
    const double slack = 1e-14 * (1.0 + glm::length(pole->collapsedPoint));
    for (const Side* exact : exactPoles) {
      if (glm::length(exact->collapsedPoint - pole->collapsedPoint) <= slack) {
        pole->collapsedPoint = exact->collapsedPoint;
        break;
      }
    }
  }
  for (const auto& [key, refs] : byCurve) {
    for (const PatchSideRef& a : refs) {
      Side& entry = sides_[a.patch][sideIndex(a.side)];
      for (const PatchSideRef& b : refs) {
        if (a.patch == b.patch && a.side == b.side) continue;
        entry.neighbours.push_back({b, entry.reversed != sides_[b.patch][sideIndex(b.side)].reversed});
      }
    }
  }
}

glm::dvec3 PatchBoundaries::point(std::size_t patch, PatchSide side, SidePosition position) const {
  const Side& entry = sides_[patch][sideIndex(side)];
  if (entry.collapsed) return entry.collapsedPoint;
  const std::int64_t step = entry.reversed ? position.steps - position.step : position.step;
  return entry.canonical.evaluate(static_cast<double>(step) / static_cast<double>(position.steps));
}

const std::vector<PatchBoundaries::Neighbour>& PatchBoundaries::neighbours(std::size_t patch, PatchSide side) const {
  return sides_[patch][sideIndex(side)].neighbours;
}

}  // namespace glass::geometry::detail
