// SmoothLineCoverage::coverage and SmoothPointCoverage::coverage (smooth_coverage.h) on the eight
// pixel centres of a block row, one pixel per lane: the block kernels' way of weighing the
// fragments of an antialiased line or point (fragment/block_kernels.cpp). Each lane does the
// scalar function's operations in its order (separate multiplies and adds, exact division, the
// clamps and the point's choices as compares and selects, so a NaN or a -0 comes out as the
// scalar code gives it), and so every target gives the scalar function's bits.
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each).
#if defined(GLASS_PRIMITIVE_SMOOTH_COVERAGE_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_PRIMITIVE_SMOOTH_COVERAGE_ROWS_INL_H_
#undef GLASS_PRIMITIVE_SMOOTH_COVERAGE_ROWS_INL_H_
#else
#define GLASS_PRIMITIVE_SMOOTH_COVERAGE_ROWS_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "primitive/smooth_coverage.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace smooth_coverage_rows {

namespace hn = hwy::HWY_NAMESPACE;

// The pixel centres' x of the row's columns: float(bx + i) + 0.5, as the reference path's
// CoverageFilter computes them.
template <int kColumns>
struct ColumnCentres {
  alignas(64) float x[kColumns];
  explicit ColumnCentres(int bx) {
    for (int i = 0; i < kColumns; ++i) x[i] = static_cast<float>(bx + i) + 0.5f;
  }
};

// std::clamp(v, 0, 1): v < 0 ? 0 : (1 < v ? 1 : v).
template <class DF, class VF>
VF saturate(DF f, VF v) {
  const auto zero = hn::Zero(f), one = hn::Set(f, 1.0f);
  return hn::IfThenElse(hn::Lt(v, zero), zero, hn::IfThenElse(hn::Lt(one, v), one, v));
}

// The coverage of a smooth line's fragments at the centres (x[i], y), i < kColumns.
template <int kColumns>
class LineRows {
 public:
  explicit LineRows(const SmoothLineCoverage& shape)
      : s_(shape), shortening_(std::min(shape.length / shape.halfLength, 1.0f)) {}

  void row(const float* x, float y, float coverage[kColumns]) const {
    const hn::CappedTag<float, kColumns> f;
    const auto dirX = hn::Set(f, s_.dirX), dirY = hn::Set(f, s_.dirY);
    const auto ry = hn::Set(f, y - s_.midY);
    for (int i = 0; i < kColumns; i += static_cast<int>(hn::Lanes(f))) {
      const auto rx = hn::Sub(hn::Load(f, x + i), hn::Set(f, s_.midX));
      const auto along = hn::Add(hn::Mul(rx, dirX), hn::Mul(ry, dirY));
      const auto across = hn::Sub(hn::Mul(ry, dirX), hn::Mul(rx, dirY));
      const auto acrossCoverage = saturate(f, hn::Sub(hn::Set(f, s_.halfWidth), hn::Abs(across)));
      const auto alongCoverage = hn::Mul(saturate(f, hn::Sub(hn::Set(f, s_.halfLength), hn::Abs(along))),
                                         hn::Set(f, shortening_));
      hn::Store(hn::Mul(acrossCoverage, alongCoverage), f, coverage + i);
    }
  }

 private:
  SmoothLineCoverage s_;
  float shortening_;  // min(L / l, 1)
};

// The coverage of a smooth point's fragments at the centres (x[i], y), i < kColumns: negative
// outside the disc (the fragment is dropped).
template <int kColumns>
class PointRows {
 public:
  explicit PointRows(const SmoothPointCoverage& shape) : s_(shape) {
    const float inverse = 1.0f / shape.radius;
    k_ = 1.0f - 2.0f * inverse + inverse * inverse;
    innerScale_ = 1.0f / (1.0f - k_);
  }

  void row(const float* x, float y, float coverage[kColumns]) const {
    const hn::CappedTag<float, kColumns> f;
    const auto radius = hn::Set(f, s_.radius), one = hn::Set(f, 1.0f), k = hn::Set(f, k_);
    const auto t = hn::Div(hn::Set(f, y - s_.y), radius);
    for (int i = 0; i < kColumns; i += static_cast<int>(hn::Lanes(f))) {
      const auto s = hn::Div(hn::Sub(hn::Load(f, x + i), hn::Set(f, s_.x)), radius);
      const auto d = hn::Add(hn::Mul(s, s), hn::Mul(t, t));
      const auto inside = hn::IfThenElse(hn::Ge(k, d), hn::Mul(hn::Set(f, innerScale_), hn::Sub(one, d)), one);
      hn::Store(hn::IfThenElse(hn::Gt(d, one), hn::Set(f, -1.0f), inside), f, coverage + i);
    }
  }

 private:
  SmoothPointCoverage s_;
  float k_, innerScale_;  // Mesa's inner radius squared, and 1 / (1 - k)
};

}  // namespace smooth_coverage_rows
}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#endif  // GLASS_PRIMITIVE_SMOOTH_COVERAGE_ROWS_INL_H_
