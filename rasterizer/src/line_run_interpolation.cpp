// interpolateLineRuns (line_run_interpolation.h), one template compiled for each SIMD target
// (hwy/foreach_target.h re-includes this file per target).
//
// A lane is a run. Every lane makes the operations of the evaluation the header gives, in its
// order: the integer major coordinate converted to double exactly, the division by the length,
// the clamp to [0, 1] and the denominator's test as comparisons and selections (NaN compares
// false, and so takes the clamped t, as the scalar test !(q > 0) does), the weights' products and
// quotients, depthValue's clamps, multiplication, addition and truncation, and each varying's two
// products and sum in double, rounded once to float (by the C++ conversion where the value lies
// beyond the float range, since Highway's DemoteTo saturates there on some targets and the
// conversion gives infinity). No multiply-add is fused (-ffp-contract=off,
// and Highway's Mul and Add are separate instructions), so every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "line_run_interpolation.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <limits>

#include "depth_value-inl.h"
#include "line_run_interpolation.h"

HWY_BEFORE_NAMESPACE();
namespace glass::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

void InterpolateLineRuns(const LineRunEnds& ends, const int* majors, LineRunBatch& batch) {
  constexpr int kRuns = LineRunBatch::kMaxRuns;
  const hn::CappedTag<double, kLineRunLanes> d;
  const hn::Rebind<int32_t, decltype(d)> d32;
  const hn::Rebind<float, decltype(d)> f32;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const int count = batch.count;
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
  const auto start = hn::Set(d, ends.start), length = hn::Set(d, ends.length);
  const auto qa = hn::Set(d, ends.qa), qb = hn::Set(d, ends.qb);
  const auto za = hn::Set(d, ends.za), zb = hn::Set(d, ends.zb), bias = hn::Set(d, ends.depthBias);
  const auto floatMax = hn::Set(d, double(std::numeric_limits<float>::max()));
  alignas(64) double weightA[kRuns], weightB[kRuns];
  auto* depth = reinterpret_cast<int32_t*>(batch.depth);  // below 2^24: the same bits either way
  for (int r = 0; r < count; r += lanes) {
    const auto major = hn::PromoteTo(d, hn::LoadU(d32, majors + r));
    const auto extrapolated = hn::Div(hn::Sub(hn::Add(major, half), start), length);
    auto clamped = hn::IfThenElse(hn::Lt(extrapolated, zero), zero, extrapolated);
    clamped = hn::IfThenElse(hn::Gt(clamped, one), one, clamped);
    const auto denominator =
        hn::Add(hn::Mul(hn::Sub(one, extrapolated), qa), hn::Mul(extrapolated, qb));
    const auto t = hn::IfThenElse(hn::Gt(denominator, zero), extrapolated, clamped);
    const auto notT = hn::Sub(one, t);
    const auto wa = hn::Mul(notT, qa), wb = hn::Mul(t, qb);
    const auto q = hn::Add(wa, wb);
    hn::Store(hn::Div(wa, q), d, weightA + r);
    hn::Store(hn::Div(wb, q), d, weightB + r);
    storeDepthValues(d, hn::Add(hn::Add(hn::Mul(notT, za), hn::Mul(t, zb)), bias), depth + r);
  }
  for (int k = 0; k < batch.varyingCount; ++k) {
    const auto atA = hn::Set(d, double(ends.varyingsA[k])), atB = hn::Set(d, double(ends.varyingsB[k]));
    float* values = batch.varyings[k];
    for (int r = 0; r < count; r += lanes) {
      const auto value = hn::Add(hn::Mul(hn::Load(d, weightA + r), atA), hn::Mul(hn::Load(d, weightB + r), atB));
      if (HWY_LIKELY(hn::AllTrue(d, hn::Le(hn::Abs(value), floatMax)))) {
        hn::StoreU(hn::DemoteTo(f32, value), f32, values + r);
      } else {
        // Beyond the float range (or NaN), where DemoteTo saturates on some targets and the C++
        // conversion gives infinity: the conversion itself, lane by lane.
        alignas(64) double exact[16];
        hn::Store(value, d, exact);
        for (int i = 0; i < lanes; ++i) values[r + i] = static_cast<float>(exact[i]);
      }
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::raster {
namespace {

constexpr SimdFunctions<decltype(&HWY_STATIC_DISPATCH(InterpolateLineRuns))> kInterpolateLineRuns =
    GLASS_SIMD_FUNCTIONS(InterpolateLineRuns);

}  // namespace

void interpolateLineRuns(const LineRunEnds& ends, const int* majors, LineRunBatch& batch) {
  chosenSimdFunction(kInterpolateLineRuns)(ends, majors, batch);
}

void interpolateLineRunsWith(SimdTarget target, const LineRunEnds& ends, const int* majors,
                             LineRunBatch& batch) {
  kInterpolateLineRuns[static_cast<int>(target)](ends, majors, batch);
}

}  // namespace glass::raster
#endif  // HWY_ONCE
