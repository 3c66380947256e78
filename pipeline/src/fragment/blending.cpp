#include "fragment/blending.h"

#include <algorithm>

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

// The factor for component i (0-2: colour, 3: alpha) of table 4.1.
float blendFactor(GLenum factor, int i, const float s[4], const float d[4], const float c[4]) {
  switch (factor) {
    case GL_ZERO: return 0.0f;
    case GL_ONE: return 1.0f;
    case GL_SRC_COLOR: return s[i];
    case GL_ONE_MINUS_SRC_COLOR: return 1.0f - s[i];
    case GL_DST_COLOR: return d[i];
    case GL_ONE_MINUS_DST_COLOR: return 1.0f - d[i];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 1.0f - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 1.0f - d[3];
    case GL_CONSTANT_COLOR: return c[i];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 1.0f - c[i];
    case GL_CONSTANT_ALPHA: return c[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 1.0f - c[3];
    case GL_SRC_ALPHA_SATURATE: return i == 3 ? 1.0f : std::min(s[3], 1.0f - d[3]);
    default: return 0.0f;
  }
}

}  // namespace

void blend(const BlendSettings& b, const float s[4], const float d[4], float result[4]) {
  for (int i = 0; i < 4; ++i) {
    const GLenum srcFactor = i < 3 ? b.srcRGB : b.srcAlpha;
    const GLenum dstFactor = i < 3 ? b.dstRGB : b.dstAlpha;
    float value;
    switch (b.equation) {
      case GL_MIN: value = std::min(s[i], d[i]); break;
      case GL_MAX: value = std::max(s[i], d[i]); break;
      default: {
        const float sTerm = s[i] * blendFactor(srcFactor, i, s, d, b.constant);
        const float dTerm = d[i] * blendFactor(dstFactor, i, s, d, b.constant);
        value = b.equation == GL_FUNC_SUBTRACT           ? sTerm - dTerm
                : b.equation == GL_FUNC_REVERSE_SUBTRACT ? dTerm - sTerm
                                                          : sTerm + dTerm;
      }
    }
    result[i] = std::clamp(value, 0.0f, 1.0f);
  }
}

}  // namespace glass::gl
