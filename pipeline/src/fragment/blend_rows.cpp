// The blend rows of blend_rows.h, compiled for each SIMD target (hwy/foreach_target.h
// re-includes this file per target).
//
// A 32-bit lane holds one pixel's word. Its four bytes are split into two halves, each a pair of
// 16-bit values 0 to 255 (the bytes at bits 0 and 16, and those at bits 8 and 24), and the
// arithmetic runs on the 16-bit values, two components per 32-bit lane: every value it makes
// fits in 16 bits, so no carry crosses from one to the other. Each component's factor (table 4.1,
// as blending.cpp's blendFactor gives it for that component) is made where the component is.
// The rounded product v f / 255 is t = v f + 128, (t + t / 256) / 256 (t at most 65,153, the
// sum at most 65,407), equal to blend()'s (2 v f + 255) / 510 for every pair of bytes; a
// difference saturated at 0 is max(a, b) - b, a sum saturated at 255 min(a + b, 255). Only
// shifts, masks, adds, multiplies, minima and maxima of 16- and 32-bit lanes: every target,
// one-lane vectors too, gives blend()'s bytes.
//
// As blending.cpp does for one pixel, the row has a copy compiled for each of the common
// settings (kCommonBlends), whose equation and factors are then constants and their switches
// fold away, and a copy that reads them at run time for every other setting.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fragment/blend_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <utility>

#include "core/simd_dispatch.h"
#include "fragment/blend_rows.h"

HWY_BEFORE_NAMESPACE();
namespace glass::gl {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

using RowWords = hn::CappedTag<uint32_t, kBlendRowPixels>;
using Word = hn::Vec<RowWords>;

// Where component c of a pixel's word is: byte c in memory.
constexpr int componentShift(int c) { return std::endian::native == std::endian::little ? 8 * c : 8 * (3 - c); }
// The half that holds component c (half h is the word shifted right by 8 h, masked with
// kPairOfFull), and the bit where it begins there.
constexpr int halfOf(int c) { return componentShift(c) / 8 % 2; }
constexpr int shiftInHalf(int c) { return componentShift(c) / 16 * 16; }
constexpr uint32_t kPairOfFull = 0x00FF00FFu;  // 255 in both 16-bit values
constexpr int kAlphaHalf = halfOf(3);
constexpr uint32_t kAlphaBits = 0xFFFFu << shiftInHalf(3);  // the alpha's 16 bits in its half

// A pair's two 16-bit values set to `value` (0 to 255).
constexpr uint32_t bothValues(uint32_t value) { return value | value << 16; }

// Operations on both 16-bit values of each lane's pair: the lanes seen as twice as many 16-bit
// lanes, or, for one-lane vectors (which have no such view), the two values worked apart.
#if HWY_TARGET == HWY_SCALAR
template <class Op>
Word eachValue(RowWords d, Word a, Word b, Op op) {
  const uint32_t x = hn::GetLane(a), y = hn::GetLane(b);
  const uint32_t low = op(x & 0xFFFFu, y & 0xFFFFu) & 0xFFFFu, high = op(x >> 16, y >> 16) & 0xFFFFu;
  return hn::Set(d, low | high << 16);
}
Word pairMul(RowWords d, Word a, Word b) { return eachValue(d, a, b, [](uint32_t x, uint32_t y) { return x * y; }); }
Word pairMin(RowWords d, Word a, Word b) { return eachValue(d, a, b, [](uint32_t x, uint32_t y) { return std::min(x, y); }); }
Word pairMax(RowWords d, Word a, Word b) { return eachValue(d, a, b, [](uint32_t x, uint32_t y) { return std::max(x, y); }); }
Word pairShiftRight8(RowWords d, Word a) { return hn::And(hn::ShiftRight<8>(a), hn::Set(d, kPairOfFull)); }
#else
using RowPairs = hn::Repartition<uint16_t, RowWords>;
Word pairMul(RowWords d, Word a, Word b) {
  const RowPairs p;
  return hn::BitCast(d, hn::Mul(hn::BitCast(p, a), hn::BitCast(p, b)));
}
Word pairMin(RowWords d, Word a, Word b) {
  const RowPairs p;
  return hn::BitCast(d, hn::Min(hn::BitCast(p, a), hn::BitCast(p, b)));
}
Word pairMax(RowWords d, Word a, Word b) {
  const RowPairs p;
  return hn::BitCast(d, hn::Max(hn::BitCast(p, a), hn::BitCast(p, b)));
}
Word pairShiftRight8(RowWords d, Word a) { return hn::BitCast(d, hn::ShiftRight<8>(hn::BitCast(RowPairs(), a))); }
#endif
// Adding and subtracting pairs needs no view: no sum here passes 65,535 and no difference is
// below 0, so no carry or borrow crosses from one value to the other.

// The blend colour's components of half h, where the pixels' components are.
uint32_t constantHalf(const uint8_t constant[4], int h) {
  uint32_t pair = 0;
  for (int c = 0; c < 4; ++c)
    if (halfOf(c) == h) pair |= static_cast<uint32_t>(constant[c]) << shiftInHalf(c);
  return pair;
}

// The lanes' pixels in two halves, and each pixel's alpha in both values of a pair.
struct Halves {
  Word half[2];
  Word alpha;
  Halves(RowWords d, Word words) {
    const Word mask = hn::Set(d, kPairOfFull);
    half[0] = hn::And(words, mask);
    half[1] = hn::And(hn::ShiftRight<8>(words), mask);
    const Word a = hn::And(hn::ShiftRightSame(words, componentShift(3)), hn::Set(d, 0xFFu));
    alpha = hn::Or(a, hn::ShiftLeft<16>(a));
  }
};

// blendFactor(factor, i, s, d, constant) for the components i of half h (alphaComponent: for
// the alpha's value, which only GL_SRC_ALPHA_SATURATE treats apart).
[[gnu::always_inline]] inline Word factor(RowWords d, GLenum factor, bool alphaComponent, int h, const Halves& s,
                                          const Halves& t, const uint8_t constant[4]) {
  const Word full = hn::Set(d, kPairOfFull);
  switch (factor) {
    case GL_ZERO: return hn::Zero(d);
    case GL_ONE: return full;
    case GL_SRC_COLOR: return s.half[h];
    case GL_ONE_MINUS_SRC_COLOR: return hn::Sub(full, s.half[h]);  // no value below 0: no borrow
    case GL_DST_COLOR: return t.half[h];
    case GL_ONE_MINUS_DST_COLOR: return hn::Sub(full, t.half[h]);
    case GL_SRC_ALPHA: return s.alpha;
    case GL_ONE_MINUS_SRC_ALPHA: return hn::Sub(full, s.alpha);
    case GL_DST_ALPHA: return t.alpha;
    case GL_ONE_MINUS_DST_ALPHA: return hn::Sub(full, t.alpha);
    case GL_CONSTANT_COLOR: return hn::Set(d, constantHalf(constant, h));
    case GL_ONE_MINUS_CONSTANT_COLOR: return hn::Set(d, kPairOfFull - constantHalf(constant, h));
    case GL_CONSTANT_ALPHA: return hn::Set(d, bothValues(constant[3]));
    case GL_ONE_MINUS_CONSTANT_ALPHA: return hn::Set(d, bothValues(255u - constant[3]));
    case GL_SRC_ALPHA_SATURATE: return alphaComponent ? full : pairMin(d, s.alpha, hn::Sub(full, t.alpha));
    default: return hn::Zero(d);
  }
}

// The factors of half h's components: the colour factor, and in the alpha's half the alpha
// factor for the alpha's value when it differs.
[[gnu::always_inline]] inline Word halfFactor(RowWords d, GLenum colorFactor, GLenum alphaFactor, int h,
                                              const Halves& s, const Halves& t, const uint8_t constant[4]) {
  const Word color = factor(d, colorFactor, false, h, s, t, constant);
  if (h != kAlphaHalf || (alphaFactor == colorFactor && colorFactor != GL_SRC_ALPHA_SATURATE)) return color;
  const Word alphaBits = hn::Set(d, kAlphaBits);
  return hn::Or(hn::AndNot(alphaBits, color), hn::And(alphaBits, factor(d, alphaFactor, true, h, s, t, constant)));
}

// v f / 255 rounded to the nearest integer, for both values of each pair.
[[gnu::always_inline]] inline Word scaled(RowWords d, Word v, Word f) {
  const Word t = hn::Add(pairMul(d, v, f), hn::Set(d, bothValues(128)));
  return pairShiftRight8(d, hn::Add(t, pairShiftRight8(d, t)));
}

// blend() on the row's pixels, inline so that blendRowWith can fix the settings it switches on.
[[gnu::always_inline]] inline void blendRowPixels(const BlendSettings& b, const uint32_t* source,
                                                  const uint32_t* destination, uint32_t* result) {
  const RowWords d;
  for (int i = 0; i < kBlendRowPixels; i += static_cast<int>(hn::Lanes(d))) {
    const Halves s(d, hn::LoadU(d, source + i)), t(d, hn::LoadU(d, destination + i));
    Word out = hn::Zero(d);
    for (int h = 0; h < 2; ++h) {
      Word value;
      switch (b.equation) {
        case GL_MIN: value = pairMin(d, s.half[h], t.half[h]); break;
        case GL_MAX: value = pairMax(d, s.half[h], t.half[h]); break;
        default: {
          const Word sTerm = scaled(d, s.half[h], halfFactor(d, b.srcRGB, b.srcAlpha, h, s, t, b.constant));
          const Word dTerm = scaled(d, t.half[h], halfFactor(d, b.dstRGB, b.dstAlpha, h, s, t, b.constant));
          value = b.equation == GL_FUNC_SUBTRACT           ? hn::Sub(pairMax(d, sTerm, dTerm), dTerm)
                  : b.equation == GL_FUNC_REVERSE_SUBTRACT ? hn::Sub(pairMax(d, dTerm, sTerm), sTerm)
                                                           : pairMin(d, hn::Add(sTerm, dTerm), hn::Set(d, kPairOfFull));
        }
      }
      out = hn::Or(out, hn::ShiftLeftSame(value, 8 * h));
    }
    hn::StoreU(out, d, result + i);
  }
}

// The row for any settings, read at run time.
void blendRowAnySettings(const BlendSettings& b, const uint32_t source[kBlendRowPixels],
                         const uint32_t destination[kBlendRowPixels], uint32_t result[kBlendRowPixels]) {
  blendRowPixels(b, source, destination, result);
}

// The row for kCommonBlends[kIndex]: its equation and factors fixed (the blend colour still
// comes from b).
template <int kIndex>
void blendRowWith(const BlendSettings& b, const uint32_t source[kBlendRowPixels],
                  const uint32_t destination[kBlendRowPixels], uint32_t result[kBlendRowPixels]) {
  constexpr CommonBlend common = kCommonBlends[kIndex];
  BlendSettings fixed;
  fixed.equation = GL_FUNC_ADD;
  fixed.srcRGB = fixed.srcAlpha = common.source;
  fixed.dstRGB = fixed.dstAlpha = common.destination;
  std::memcpy(fixed.constant, b.constant, sizeof fixed.constant);
  blendRowPixels(fixed, source, destination, result);
}

template <int... kIndices>
constexpr std::array<BlendRow, sizeof...(kIndices)> commonBlendRows(std::integer_sequence<int, kIndices...>) {
  return {&blendRowWith<kIndices>...};
}
constexpr auto kCommonBlendRows = commonBlendRows(std::make_integer_sequence<int, kCommonBlendCount>());

}  // namespace

// This target's blend row for the common blend `common` (an index in kCommonBlends), or for any
// settings when it is -1.
glass::gl::BlendRow BlendRowOfTarget(int common) {
  return common >= 0 ? kCommonBlendRows[common] : &blendRowAnySettings;
}

}  // namespace HWY_NAMESPACE
}  // namespace glass::gl
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glass::gl {
namespace {

constexpr SimdFunctions<BlendRow (*)(int)> kBlendRowOfTarget = GLASS_SIMD_FUNCTIONS(BlendRowOfTarget);

}  // namespace

BlendRow blendRowFor(const BlendSettings& settings) {
  return chosenSimdFunction(kBlendRowOfTarget)(commonBlendIndex(settings));
}

BlendRow blendRowFor(raster::SimdTarget target, const BlendSettings& settings) {
  return kBlendRowOfTarget[static_cast<int>(target)](commonBlendIndex(settings));
}

}  // namespace glass::gl
#endif  // HWY_ONCE
