// floatToColorByte and packColorBytes (fragment/color_conversion.h) on the lanes of a vector:
// the colours whose components are in the arrays red .. alpha, one colour per lane, each lane
// doing exactly the scalar functions' operations (a multiply, then an add: no fused
// multiply-add; the ends chosen by compares and selects), so every target gives their bytes.
// For the kernels of a block row (fragment/block_kernels.cpp) and of a batch of line runs
// (fragment/line_kernels.cpp).
//
// A Highway per-target header: included, inside no namespace, by files that
// hwy/foreach_target.h compiles once per target (the toggle below lets it be included again for
// each).
#if defined(GLASS_FRAGMENT_COLOR_PACKING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLASS_FRAGMENT_COLOR_PACKING_INL_H_
#undef GLASS_FRAGMENT_COLOR_PACKING_INL_H_
#else
#define GLASS_FRAGMENT_COLOR_PACKING_INL_H_
#endif

#include <hwy/highway.h>

#include <bit>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace color_packing {

namespace hn = hwy::HWY_NAMESPACE;

// floatToColorByte of each lane of c, as 32-bit unsigned lanes.
template <class DF, class VF>
auto colorBytes(DF f, VF c) {
  const hn::RebindToUnsigned<DF> u;
  // Multiply, then add: two roundings, as in floatToColorByte.
  const auto sum = hn::Add(hn::Mul(c, hn::Set(f, 255.0f / 256.0f)), hn::Set(f, 32768.0f));
  const auto inRange = hn::And(hn::BitCast(u, sum), hn::Set(u, 0xFFu));
  const auto belowOne = hn::IfThenElse(hn::RebindMask(u, hn::Ge(c, hn::Set(f, 1.0f))), hn::Set(u, 255u), inRange);
  return hn::IfThenElseZero(hn::RebindMask(u, hn::Gt(c, hn::Zero(f))), belowOne);  // 0 for NaN
}

// words[i] = packColorBytes(floatToColorByte(red[i]), ..., floatToColorByte(alpha[i])) for the
// Lanes(f) colours from index 0 (unaligned).
template <class DF>
void packColorVector(DF f, const float* red, const float* green, const float* blue, const float* alpha,
                     uint32_t* words) {
  const hn::RebindToUnsigned<DF> u;
  const auto r = colorBytes(f, hn::LoadU(f, red)), g = colorBytes(f, hn::LoadU(f, green));
  const auto b = colorBytes(f, hn::LoadU(f, blue)), a = colorBytes(f, hn::LoadU(f, alpha));
  // The colour buffer's order, r, g, b, a in memory, as packColorBytes's word holds it.
  if constexpr (std::endian::native == std::endian::little) {
    hn::StoreU(hn::Or(hn::Or(r, hn::ShiftLeft<8>(g)), hn::Or(hn::ShiftLeft<16>(b), hn::ShiftLeft<24>(a))), u, words);
  } else {
    hn::StoreU(hn::Or(hn::Or(hn::ShiftLeft<24>(r), hn::ShiftLeft<16>(g)), hn::Or(hn::ShiftLeft<8>(b), a)), u, words);
  }
}

}  // namespace color_packing
}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
