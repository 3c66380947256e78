// depthValue (glass/raster/depth_value.h) on the lanes of a vector of doubles: the clamps to
// [0, 1] as comparisons and selections (NaN compares false and becomes 0), one multiplication,
// one addition and the truncation to a 32-bit integer, each lane doing exactly the scalar
// function's operations, so every target gives its values. For the triangle walk's block rows
// (block_rows.cpp) and the line walk's runs (line_run_interpolation.cpp).
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each).
#if defined(GLASS_RASTER_DEPTH_VALUE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_RASTER_DEPTH_VALUE_INL_H_
#undef GLASS_RASTER_DEPTH_VALUE_INL_H_
#else
#define GLASS_RASTER_DEPTH_VALUE_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

#include "glass/raster/depth_value.h"

HWY_BEFORE_NAMESPACE();
namespace glass::raster {
namespace HWY_NAMESPACE {

// depthValue of each lane of z, stored as 32-bit integers at out (the values are below 2^24, so
// their bits are the uint32_t ones).
template <class D, class V>
void storeDepthValues(D d, V z, int32_t* out) {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::Rebind<int32_t, D> d32;
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0);
  z = hn::IfThenElse(hn::Gt(z, zero), z, zero);
  z = hn::IfThenElse(hn::Lt(z, one), z, one);
  hn::StoreU(hn::DemoteTo(d32, hn::Add(hn::Mul(z, hn::Set(d, double(kDepthMax))), hn::Set(d, 0.5))), d32, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::raster
HWY_AFTER_NAMESPACE();

#endif  // GLASS_RASTER_DEPTH_VALUE_INL_H_
