#include "texture/texture_combine.h"

#include <algorithm>

#include "texture/texture_units.h"

namespace glass::gl {
namespace {

constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};

// The colour a source names. A GL_TEXTUREi source whose unit is not textured has undefined
// results (spec 3.8.13); glass reads zero there.
const float* sourceColor(GLenum source, const TextureEnvironment& env, const CombineSources& s) {
  switch (source) {
    case GL_TEXTURE: return s.texel;
    case GL_CONSTANT: return env.color;
    case GL_PRIMARY_COLOR: return s.primary;
    case GL_PREVIOUS: return s.previous;
    default: {
      if (!isTextureUnit(source) || s.unitTexels == nullptr) return kZero;
      const float* texel = s.unitTexels[source - GL_TEXTURE0];
      return texel != nullptr ? texel : kZero;
    }
  }
}

// Table 3.24: an RGB operand is the source's colour, one minus it, its alpha or one minus it.
void rgbArgument(GLenum operand, const float* c, float out[3]) {
  for (int k = 0; k < 3; ++k) {
    switch (operand) {
      case GL_SRC_COLOR: out[k] = c[k]; break;
      case GL_ONE_MINUS_SRC_COLOR: out[k] = 1.0f - c[k]; break;
      case GL_SRC_ALPHA: out[k] = c[3]; break;
      default: out[k] = 1.0f - c[3]; break;  // GL_ONE_MINUS_SRC_ALPHA
    }
  }
}

float alphaArgument(GLenum operand, const float* c) {
  return operand == GL_SRC_ALPHA ? c[3] : 1.0f - c[3];
}

float combine(GLenum function, float a0, float a1, float a2) {
  switch (function) {
    case GL_REPLACE: return a0;
    case GL_MODULATE: return a0 * a1;
    case GL_ADD: return a0 + a1;
    case GL_ADD_SIGNED: return a0 + a1 - 0.5f;
    case GL_INTERPOLATE: return a0 * a2 + a1 * (1.0f - a2);
    case GL_SUBTRACT: return a0 - a1;
    default: return a0;
  }
}

float dot3(const float a0[3], const float a1[3]) {
  return 4.0f * ((a0[0] - 0.5f) * (a1[0] - 0.5f) + (a0[1] - 0.5f) * (a1[1] - 0.5f) +
                 (a0[2] - 0.5f) * (a1[2] - 0.5f));
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

}  // namespace

void applyCombine(const TextureEnvironment& env, const CombineSources& sources, float color[4]) {
  float rgb[3][3];
  float alpha[3];
  for (int n = 0; n < 3; ++n) {
    rgbArgument(env.operandRGB[n], sourceColor(env.sourceRGB[n], env, sources), rgb[n]);
    alpha[n] = alphaArgument(env.operandAlpha[n], sourceColor(env.sourceAlpha[n], env, sources));
  }
  float result[4];
  if (env.combineRGB == GL_DOT3_RGB || env.combineRGB == GL_DOT3_RGBA) {
    const float d = dot3(rgb[0], rgb[1]);
    for (int k = 0; k < 3; ++k) result[k] = d;
  } else {
    for (int k = 0; k < 3; ++k)
      result[k] = combine(env.combineRGB, rgb[0][k], rgb[1][k], rgb[2][k]);
  }
  // DOT3_RGBA puts the dot product in alpha too, and the alpha function is not used.
  result[3] = env.combineRGB == GL_DOT3_RGBA
                  ? result[0]
                  : combine(env.combineAlpha, alpha[0], alpha[1], alpha[2]);
  for (int k = 0; k < 3; ++k) color[k] = clamp01(result[k] * env.rgbScale);
  // The alpha of DOT3_RGBA too is scaled by GL_ALPHA_SCALE, as Mesa does.
  color[3] = clamp01(result[3] * env.alphaScale);
}

bool isCombineAlphaFunction(GLenum f) {
  return f == GL_REPLACE || f == GL_MODULATE || f == GL_ADD || f == GL_ADD_SIGNED ||
         f == GL_INTERPOLATE || f == GL_SUBTRACT;
}

bool isCombineRGBFunction(GLenum f) {
  return isCombineAlphaFunction(f) || f == GL_DOT3_RGB || f == GL_DOT3_RGBA;
}

bool isCombineSource(GLenum s) {
  return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS ||
         isTextureUnit(s);
}

bool isCombineRGBOperand(GLenum o) {
  return o == GL_SRC_COLOR || o == GL_ONE_MINUS_SRC_COLOR || o == GL_SRC_ALPHA ||
         o == GL_ONE_MINUS_SRC_ALPHA;
}

bool isCombineAlphaOperand(GLenum o) { return o == GL_SRC_ALPHA || o == GL_ONE_MINUS_SRC_ALPHA; }

}  // namespace glass::gl
