// The blend rows of blend_rows.h, compiled for each SIMD target (hwy/foreach_target.h
// re-includes this file per target).
//
// A lane holds one pixel's word; each component is taken out of it as a 32-bit value 0 to 255,
// and its factor (table 4.1, as blending.cpp's blendFactor gives it for that component) is
// worked out in the lanes too. The rounded product v f / 255 is t = v f + 128, (t + t / 256) /
// 256, equal to blend()'s (2 v f + 255) / 510 for every pair of bytes; a difference saturated
// at 0 is max(a, b) - b, a sum saturated at 255 min(a + b, 255). Only shifts, masks, adds,
// multiplies, minima and maxima of 32-bit lanes: every target, one-lane vectors too, gives blend()'s
// bytes.
//
// As blending.cpp does for one pixel, the row has a copy compiled for each of the common
// settings (kCommonBlends), whose equation and factors are then constants and their switches
// fold away, and a copy that reads them at run time for every other setting.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fragment/blend_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

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

// The four components of the lanes' pixels, each 0 to 255.
struct Components {
  Word c[4];
  Components(RowWords d, Word words) {
    for (int i = 0; i < 4; ++i) c[i] = hn::And(hn::ShiftRightSame(words, componentShift(i)), hn::Set(d, 0xFFu));
  }
};

// blendFactor(factor, i, s, d, constant) in each lane.
[[gnu::always_inline]] inline Word factor(RowWords d, GLenum factor, int i, const Components& s,
                                          const Components& t, const uint8_t constant[4]) {
  const Word full = hn::Set(d, 255u);
  switch (factor) {
    case GL_ZERO: return hn::Zero(d);
    case GL_ONE: return full;
    case GL_SRC_COLOR: return s.c[i];
    case GL_ONE_MINUS_SRC_COLOR: return hn::Sub(full, s.c[i]);
    case GL_DST_COLOR: return t.c[i];
    case GL_ONE_MINUS_DST_COLOR: return hn::Sub(full, t.c[i]);
    case GL_SRC_ALPHA: return s.c[3];
    case GL_ONE_MINUS_SRC_ALPHA: return hn::Sub(full, s.c[3]);
    case GL_DST_ALPHA: return t.c[3];
    case GL_ONE_MINUS_DST_ALPHA: return hn::Sub(full, t.c[3]);
    case GL_CONSTANT_COLOR: return hn::Set(d, constant[i]);
    case GL_ONE_MINUS_CONSTANT_COLOR: return hn::Set(d, 255u - constant[i]);
    case GL_CONSTANT_ALPHA: return hn::Set(d, constant[3]);
    case GL_ONE_MINUS_CONSTANT_ALPHA: return hn::Set(d, 255u - constant[3]);
    case GL_SRC_ALPHA_SATURATE: return i == 3 ? full : hn::Min(s.c[3], hn::Sub(full, t.c[3]));
    default: return hn::Zero(d);
  }
}

// v f / 255 rounded to the nearest integer.
[[gnu::always_inline]] inline Word scaled(RowWords d, Word v, Word f) {
  const Word t = hn::Add(hn::Mul(v, f), hn::Set(d, 128u));
  return hn::ShiftRight<8>(hn::Add(t, hn::ShiftRight<8>(t)));
}

// blend() on the row's pixels, inline so that blendRowWith can fix the settings it switches on.
[[gnu::always_inline]] inline void blendRowPixels(const BlendSettings& b, const uint32_t* source,
                                                  const uint32_t* destination, uint32_t* result) {
  const RowWords d;
  for (int p = 0; p < kBlendRowPixels; p += static_cast<int>(hn::Lanes(d))) {
    const Components s(d, hn::LoadU(d, source + p)), t(d, hn::LoadU(d, destination + p));
    Word out = hn::Zero(d);
    for (int i = 0; i < 4; ++i) {
      Word value;
      switch (b.equation) {
        case GL_MIN: value = hn::Min(s.c[i], t.c[i]); break;
        case GL_MAX: value = hn::Max(s.c[i], t.c[i]); break;
        default: {
          const Word sTerm = scaled(d, s.c[i], factor(d, i < 3 ? b.srcRGB : b.srcAlpha, i, s, t, b.constant));
          const Word dTerm = scaled(d, t.c[i], factor(d, i < 3 ? b.dstRGB : b.dstAlpha, i, s, t, b.constant));
          value = b.equation == GL_FUNC_SUBTRACT           ? hn::Sub(hn::Max(sTerm, dTerm), dTerm)
                  : b.equation == GL_FUNC_REVERSE_SUBTRACT ? hn::Sub(hn::Max(dTerm, sTerm), sTerm)
                                                           : hn::Min(hn::Add(sTerm, dTerm), hn::Set(d, 255u));
        }
      }
      out = hn::Or(out, hn::ShiftLeftSame(value, componentShift(i)));
    }
    hn::StoreU(out, d, result + p);
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
