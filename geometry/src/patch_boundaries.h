// The boundary curves of a set of patches, each in one canonical orientation, and which patches
// share which boundary curve. Used by the tessellators to make neighbouring patches meet exactly.
// Private to the library.
#pragma once

#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/bezier_surface.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glass::geometry::detail {

// Where on a patch side a vertex sits: position `step` of `steps` equal steps along the side,
// counted in the side's own direction (increasing u or v).
struct SidePosition {
  std::int64_t step = 0;
  std::int64_t steps = 1;
};

constexpr std::array<PatchSide, 4> kAllSides = {PatchSide::UMin, PatchSide::UMax, PatchSide::VMin, PatchSide::VMax};

inline std::size_t sideIndex(PatchSide side) { return static_cast<std::size_t>(side); }

struct PatchSideRef {
  std::size_t patch = 0;
  PatchSide side = PatchSide::UMin;
};

class PatchBoundaries {
 public:
  explicit PatchBoundaries(std::span<const BezierSurface> patches);

  // The point of a side, evaluated on the canonical curve: the same bits for every patch that
  // shares this boundary, whichever way round it runs there. A collapsed side gives its point.
  glm::dvec3 point(std::size_t patch, PatchSide side, SidePosition position) const;

  // For each side of each patch, the sides of other patches with the same boundary curve, and
  // whether they run the other way round. Collapsed sides (all control points equal) share
  // nothing.
  struct Neighbour {
    PatchSideRef ref;
    bool opposite = false;
  };
  const std::vector<Neighbour>& neighbours(std::size_t patch, PatchSide side) const;
  bool collapsed(std::size_t patch, PatchSide side) const { return sides_[patch][sideIndex(side)].collapsed; }

 private:
  struct Side {
    BezierCurve canonical;  // the boundary, in the canonical orientation
    bool reversed = false;  // the patch runs along it from t = 1 to t = 0
    // All control points project to one point (a pole, up to rounding of w p / w); every point of
    // the side is then collapsedPoint, bit for bit.
    bool collapsed = false;
    glm::dvec3 collapsedPoint{0.0};
    std::vector<Neighbour> neighbours;
  };
  std::vector<std::array<Side, 4>> sides_;
};

}  // namespace glass::geometry::detail
