#include "fragment/blending.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

namespace glass::gl {

bool isBlendFactor(GLenum factor, bool source) {
  switch (factor) {
    case GL_ZERO: case GL_ONE:
    case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR:
    case GL_DST_COLOR: case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA:
    case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA:
    case GL_CONSTANT_COLOR: case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;
    case GL_SRC_ALPHA_SATURATE:
      return source;  // a source factor only
    default:
      return false;
  }
}

bool isBlendEquation(GLenum equation) {
  switch (equation) {
    case GL_FUNC_ADD: case GL_FUNC_SUBTRACT: case GL_FUNC_REVERSE_SUBTRACT: case GL_MIN: case GL_MAX:
      return true;
    default:
      return false;
  }
}

namespace {

// The factor for component i (0-2: colour, 3: alpha) of table 4.1, as an 8-bit value.
[[gnu::always_inline]] inline unsigned blendFactor(GLenum factor, int i, const uint8_t s[4],
                                                   const uint8_t d[4], const uint8_t c[4]) {
  switch (factor) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[i];
    case GL_ONE_MINUS_SRC_COLOR: return 255u - s[i];
    case GL_DST_COLOR: return d[i];
    case GL_ONE_MINUS_DST_COLOR: return 255u - d[i];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255u - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255u - d[3];
    case GL_CONSTANT_COLOR: return c[i];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 255u - c[i];
    case GL_CONSTANT_ALPHA: return c[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 255u - c[3];
    case GL_SRC_ALPHA_SATURATE: return i == 3 ? 255u : std::min<unsigned>(s[3], 255u - d[3]);
    default: return 0;
  }
}

// v * f / 255 rounded to the nearest integer (255 is odd, so there are no ties).
int scale(unsigned v, unsigned f) { return static_cast<int>((v * f * 2 + 255) / 510); }

// blend() for one pixel, inline so that blendWith can fix the settings it switches on.
[[gnu::always_inline]] inline void blendPixel(const BlendSettings& b, const uint8_t s[4], const uint8_t d[4],
                                              uint8_t result[4]) {
  for (int i = 0; i < 4; ++i) {
    int value;
    switch (b.equation) {
      case GL_MIN: value = std::min(s[i], d[i]); break;
      case GL_MAX: value = std::max(s[i], d[i]); break;
      default: {
        const GLenum srcFactor = i < 3 ? b.srcRGB : b.srcAlpha;
        const GLenum dstFactor = i < 3 ? b.dstRGB : b.dstAlpha;
        const int sTerm = scale(s[i], blendFactor(srcFactor, i, s, d, b.constant));
        const int dTerm = scale(d[i], blendFactor(dstFactor, i, s, d, b.constant));
        value = b.equation == GL_FUNC_SUBTRACT           ? sTerm - dTerm
                : b.equation == GL_FUNC_REVERSE_SUBTRACT ? dTerm - sTerm
                                                          : sTerm + dTerm;
      }
    }
    result[i] = static_cast<uint8_t>(std::clamp(value, 0, 255));
  }
}

// blend() with the equation and factors fixed (the blend colour still comes from b).
template <GLenum kEquation, GLenum kSrcRGB, GLenum kDstRGB, GLenum kSrcAlpha, GLenum kDstAlpha>
void blendWith(const BlendSettings& b, const uint8_t s[4], const uint8_t d[4], uint8_t result[4]) {
  BlendSettings fixed;
  fixed.equation = kEquation;
  fixed.srcRGB = kSrcRGB;
  fixed.dstRGB = kDstRGB;
  fixed.srcAlpha = kSrcAlpha;
  fixed.dstAlpha = kDstAlpha;
  std::memcpy(fixed.constant, b.constant, sizeof fixed.constant);
  blendPixel(fixed, s, d, result);
}

// blendWith for kCommonBlends[kIndex].
template <int kIndex>
constexpr BlendFunction commonBlendFunction() {
  constexpr CommonBlend common = kCommonBlends[kIndex];
  return &blendWith<GL_FUNC_ADD, common.source, common.destination, common.source, common.destination>;
}
template <int... kIndices>
constexpr std::array<BlendFunction, sizeof...(kIndices)> commonBlendFunctions(std::integer_sequence<int, kIndices...>) {
  return {commonBlendFunction<kIndices>()...};
}
constexpr auto kCommonBlendFunctions = commonBlendFunctions(std::make_integer_sequence<int, kCommonBlendCount>());

}  // namespace

void blend(const BlendSettings& b, const uint8_t s[4], const uint8_t d[4], uint8_t result[4]) {
  blendPixel(b, s, d, result);
}

int commonBlendIndex(const BlendSettings& b) {
  for (int i = 0; i < kCommonBlendCount; ++i) {
    const CommonBlend& common = kCommonBlends[i];
    if (b.equation == GL_FUNC_ADD && b.srcRGB == common.source && b.srcAlpha == common.source &&
        b.dstRGB == common.destination && b.dstAlpha == common.destination)
      return i;
  }
  return -1;
}

BlendFunction blendFunctionFor(const BlendSettings& b) {
  const int common = commonBlendIndex(b);
  return common >= 0 ? kCommonBlendFunctions[common] : &blend;
}

}  // namespace glass::gl
