// The level of detail of several pixel quads at once: lambda[i] is what
// levelOfDetailFromSquaredScale (texture/texture_lod.h) gives for rhoSquared[i], bit for bit.
//
// That function takes log2 of rho^2 rounded to float, through portable::log2(float), a series
// of a dozen dependent double operations with a division, and it runs once per 2x2 quad of every
// mipmapped pixel; here the quads of a row are lanes of one vector, worked with the same IEEE
// operations in the same order (portable_math.h describes them): the float rho^2 widened to
// double, split into exponent and mantissa by its bits, the mantissa moved into [sqrt(1/2),
// sqrt(2)), the series, the sum rounded to float, halved, the bias added and the result clamped.
// Widened floats are never subnormal doubles, so log2's scaling of subnormals is not needed.
// Lanes outside the range of normal floats (rho^2 zero, tiny, huge, infinite or NaN) take the
// scalar function.
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each). The unit test level_of_detail_lanes_match compares it with the scalar function on every
// target.
#if defined(GLASS_TEXTURE_LEVEL_OF_DETAIL_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_TEXTURE_LEVEL_OF_DETAIL_INL_H_
#undef GLASS_TEXTURE_LEVEL_OF_DETAIL_INL_H_
#else
#define GLASS_TEXTURE_LEVEL_OF_DETAIL_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>
#include <limits>

#include "glass/geometry/portable_math.h"
#include "texture/texture_lod.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace level_of_detail {

namespace hn = hwy::HWY_NAMESPACE;

constexpr int kQuads = 4;  // the quads of a block's quad row

// portable::log2(float) before its rounding to float, for lanes holding positive, finite,
// normal doubles.
template <class D, class V>
V log2Lanes(D d, V x) {
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const auto bits = hn::BitCast(du, x);
  auto exponent = hn::Sub(hn::BitCast(di, hn::And(hn::ShiftRight<52>(bits), hn::Set(du, 0x7FF))),
                          hn::Set(di, 1023));
  auto m = hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(du, 0x000FFFFFFFFFFFFFull)),
                                 hn::Set(du, 0x3FF0000000000000ull)));  // [1, 2)
  const auto halve = hn::Ge(m, hn::Set(d, portable::kLog2Sqrt2));
  m = hn::IfThenElse(halve, hn::Mul(m, hn::Set(d, 0.5)), m);
  exponent = hn::IfThenElse(hn::RebindMask(di, halve), hn::Add(exponent, hn::Set(di, 1)), exponent);
  const auto one = hn::Set(d, 1.0);
  const auto s = hn::Div(hn::Sub(m, one), hn::Add(m, one));
  const auto z = hn::Mul(s, s);
  auto sum = hn::Zero(d);
  for (int n = portable::kLog2FloatSeriesLastOdd; n >= 3; n -= 2) sum = hn::Mul(z, hn::Add(sum, hn::Set(d, 1.0 / n)));
  const auto ln = hn::Mul(hn::Set(d, 2.0), hn::Add(s, hn::Mul(s, sum)));
  return hn::Add(hn::ConvertTo(d, exponent), hn::Mul(ln, hn::Set(d, portable::kLog2E)));
}

// lambda[i] = levelOfDetailFromSquaredScale(rhoSquared[i], minLod, maxLod, bias) for i < kQuads.
inline void levelsOfDetail(const double* rhoSquared, float minLod, float maxLod, float bias, float* lambda) {
  const hn::CappedTag<double, kQuads> d;
  const hn::Rebind<float, decltype(d)> f;
  const int lanes = static_cast<int>(hn::Lanes(d));
  for (int k = 0; k < kQuads; k += lanes) {
    // Lanes whose rho^2 lies in the range of normal floats (NaN does not) round to a normal
    // float; the others are redone below. (Highway's DemoteTo saturates on some targets where the
    // cast gives infinity, so the range is decided before the rounding.)
    const auto r = hn::Load(d, rhoSquared + k);
    const auto inSeries = hn::And(hn::Ge(r, hn::Set(d, std::numeric_limits<float>::min())),
                                  hn::Le(r, hn::Set(d, std::numeric_limits<float>::max())));
    const auto safe = hn::IfThenElse(inSeries, r, hn::Set(d, 1.0));
    const auto x = hn::PromoteTo(d, hn::DemoteTo(f, safe));  // static_cast<float>
    const auto log2 = hn::DemoteTo(f, log2Lanes(d, x));  // portable::log2(float) rounds to float
    const auto value = hn::Add(hn::Mul(hn::Set(f, 0.5f), log2), hn::Set(f, bias));
    // !(lambda > minLod) gives minLod, else lambda > maxLod gives maxLod (also when minLod >
    // maxLod, as the scalar function's two returns decide).
    const auto belowMin = hn::Not(hn::Gt(value, hn::Set(f, minLod)));
    const auto clamped = hn::IfThenElse(hn::Gt(value, hn::Set(f, maxLod)), hn::Set(f, maxLod), value);
    hn::StoreU(hn::IfThenElse(belowMin, hn::Set(f, minLod), clamped), f, lambda + k);
    if (hn::AllTrue(d, inSeries)) continue;
    uint8_t inSeriesBits[8] = {};
    hn::StoreMaskBits(d, inSeries, inSeriesBits);
    for (int i = 0; i < lanes; ++i)
      if (!(inSeriesBits[0] >> i & 1u))
        lambda[k + i] = levelOfDetailFromSquaredScale(rhoSquared[k + i], minLod, maxLod, bias);
  }
}

}  // namespace level_of_detail
}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
