// The texture environment (OpenGL 1.5 specification, section 3.8.13): glTexEnv and glGetTexEnv
// of the active texture unit, GL_COMBINE's functions, sources, operands and scales, the unit's
// level-of-detail bias (target GL_TEXTURE_FILTER_CONTROL, OpenGL 1.4), and the parameters of the
// bump-mapping extension, which use the same commands with the target GL_BUMP_MAP_GLASS.
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/context.h"
#include "core/errors.h"
#include "core/float_to_int.h"
#include "lists/command_recording.h"
#include "texture/integer_colors.h"
#include "texture/texture_combine.h"

namespace glass::gl {
namespace {

bool isEnvMode(GLenum mode) {
  return mode == GL_MODULATE || mode == GL_DECAL || mode == GL_BLEND || mode == GL_REPLACE ||
         mode == GL_ADD || mode == GL_COMBINE;
}

// GL_SOURCE0_RGB .. GL_SOURCE2_RGB, GL_SOURCE0_ALPHA .. and the operands: the argument's index
// 0..2, or -1 when pname is not one of the group starting at first.
int argumentIndex(GLenum pname, GLenum first) {
  return pname >= first && pname < first + 3 ? static_cast<int>(pname - first) : -1;
}

// The number of values of a (target, pname) pair; 0 when the pair is not an environment parameter.
int envParameterSize(GLenum target, GLenum pname) {
  if (target == GL_TEXTURE_ENV) {
    if (pname == GL_TEXTURE_ENV_COLOR) return 4;
    const bool single = pname == GL_TEXTURE_ENV_MODE || pname == GL_COMBINE_RGB ||
                        pname == GL_COMBINE_ALPHA || pname == GL_RGB_SCALE ||
                        pname == GL_ALPHA_SCALE || argumentIndex(pname, GL_SOURCE0_RGB) >= 0 ||
                        argumentIndex(pname, GL_SOURCE0_ALPHA) >= 0 ||
                        argumentIndex(pname, GL_OPERAND0_RGB) >= 0 ||
                        argumentIndex(pname, GL_OPERAND0_ALPHA) >= 0;
    return single ? 1 : 0;
  }
  if (target == GL_TEXTURE_FILTER_CONTROL) return pname == GL_TEXTURE_LOD_BIAS ? 1 : 0;
  if (target == GL_BUMP_MAP_GLASS)
    return pname == GL_BUMP_MAP_TEXTURE_GLASS || pname == GL_BUMP_SCALE_GLASS ? 1 : 0;
  return 0;
}

void texEnv(Context& ctx, GLenum target, GLenum pname, const std::array<double, 4>& v, bool vector) {
  if (rejectInsideBeginEnd(ctx)) return;
  const int size = envParameterSize(target, pname);
  if (size == 0 || (size > 1 && !vector)) return recordError(ctx, GL_INVALID_ENUM);
  TextureState& t = ctx.texture;
  TextureEnvironment& env = t.unit().env;
  const GLenum value = static_cast<GLenum>(enumFromFloat(v[0]));
  if (const int n = argumentIndex(pname, GL_SOURCE0_RGB); n >= 0) {
    if (!isCombineSource(value)) return recordError(ctx, GL_INVALID_ENUM);
    env.sourceRGB[n] = value;
    return;
  }
  if (const int n = argumentIndex(pname, GL_SOURCE0_ALPHA); n >= 0) {
    if (!isCombineSource(value)) return recordError(ctx, GL_INVALID_ENUM);
    env.sourceAlpha[n] = value;
    return;
  }
  if (const int n = argumentIndex(pname, GL_OPERAND0_RGB); n >= 0) {
    if (!isCombineRGBOperand(value)) return recordError(ctx, GL_INVALID_ENUM);
    env.operandRGB[n] = value;
    return;
  }
  if (const int n = argumentIndex(pname, GL_OPERAND0_ALPHA); n >= 0) {
    if (!isCombineAlphaOperand(value)) return recordError(ctx, GL_INVALID_ENUM);
    env.operandAlpha[n] = value;
    return;
  }
  switch (pname) {
    case GL_TEXTURE_ENV_MODE:
      if (!isEnvMode(value)) return recordError(ctx, GL_INVALID_ENUM);
      env.mode = value;
      break;
    case GL_TEXTURE_ENV_COLOR:
      for (int k = 0; k < 4; ++k) env.color[k] = static_cast<float>(std::clamp(v[k], 0.0, 1.0));
      break;
    case GL_COMBINE_RGB:
      if (!isCombineRGBFunction(value)) return recordError(ctx, GL_INVALID_ENUM);
      env.combineRGB = value;
      break;
    case GL_COMBINE_ALPHA:
      if (!isCombineAlphaFunction(value)) return recordError(ctx, GL_INVALID_ENUM);
      env.combineAlpha = value;
      break;
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE: {
      // Spec 3.8.13: the scales are 1.0, 2.0 or 4.0; anything else is INVALID_VALUE.
      if (v[0] != 1.0 && v[0] != 2.0 && v[0] != 4.0) return recordError(ctx, GL_INVALID_VALUE);
      (pname == GL_RGB_SCALE ? env.rgbScale : env.alphaScale) = static_cast<float>(v[0]);
      break;
    }
    case GL_TEXTURE_LOD_BIAS: env.lodBias = static_cast<float>(v[0]); break;
    case GL_BUMP_MAP_TEXTURE_GLASS:
      if (v[0] < 0.0) return recordError(ctx, GL_INVALID_VALUE);
      t.bumpMap.texture = static_cast<GLuint>(v[0]);
      break;
    case GL_BUMP_SCALE_GLASS:
      t.bumpMap.scale = static_cast<float>(v[0]);
      break;
    default: break;
  }
}

bool getTexEnv(Context& ctx, GLenum target, GLenum pname, double out[4], int* count) {
  if (rejectInsideBeginEnd(ctx)) return false;
  *count = envParameterSize(target, pname);
  if (*count == 0) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  const TextureState& t = ctx.texture;
  const TextureEnvironment& env = t.unit().env;
  if (const int n = argumentIndex(pname, GL_SOURCE0_RGB); n >= 0) out[0] = env.sourceRGB[n];
  if (const int n = argumentIndex(pname, GL_SOURCE0_ALPHA); n >= 0) out[0] = env.sourceAlpha[n];
  if (const int n = argumentIndex(pname, GL_OPERAND0_RGB); n >= 0) out[0] = env.operandRGB[n];
  if (const int n = argumentIndex(pname, GL_OPERAND0_ALPHA); n >= 0) out[0] = env.operandAlpha[n];
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: out[0] = env.mode; break;
    case GL_TEXTURE_ENV_COLOR: for (int k = 0; k < 4; ++k) out[k] = env.color[k]; break;
    case GL_COMBINE_RGB: out[0] = env.combineRGB; break;
    case GL_COMBINE_ALPHA: out[0] = env.combineAlpha; break;
    case GL_RGB_SCALE: out[0] = env.rgbScale; break;
    case GL_ALPHA_SCALE: out[0] = env.alphaScale; break;
    case GL_TEXTURE_LOD_BIAS: out[0] = env.lodBias; break;
    case GL_BUMP_MAP_TEXTURE_GLASS: out[0] = t.bumpMap.texture; break;
    case GL_BUMP_SCALE_GLASS: out[0] = t.bumpMap.scale; break;
    default: break;
  }
  return true;
}

template <class T>
std::array<double, 4> copyEnvValues(GLenum target, GLenum pname, const T* params, bool colorFromInteger) {
  std::array<double, 4> v{0.0, 0.0, 0.0, 0.0};
  const int n = envParameterSize(target, pname);
  for (int k = 0; k < n; ++k) {
    v[static_cast<size_t>(k)] = colorFromInteger && pname == GL_TEXTURE_ENV_COLOR
                                    ? integerToColor(static_cast<GLint>(params[k]))
                                    : static_cast<double>(params[k]);
  }
  return v;
}

}  // namespace
}  // namespace glass::gl

using glass::gl::Context;

void GLAPIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat param) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texEnv(ctx, target, pname, {param, 0.0, 0.0, 0.0}, false); });
}

void GLAPIENTRY glTexEnvi(GLenum target, GLenum pname, GLint param) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::texEnv(ctx, target, pname, {static_cast<double>(param), 0.0, 0.0, 0.0}, false);
  });
}

void GLAPIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat* params) {
  const auto v = glass::gl::copyEnvValues(target, pname, params, false);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texEnv(ctx, target, pname, v, true); });
}

void GLAPIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint* params) {
  const auto v = glass::gl::copyEnvValues(target, pname, params, true);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texEnv(ctx, target, pname, v, true); });
}

void GLAPIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double v[4];
    int count;
    if (!glass::gl::getTexEnv(ctx, target, pname, v, &count)) return;
    for (int k = 0; k < count; ++k) params[k] = static_cast<GLfloat>(v[k]);
  });
}

void GLAPIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double v[4];
    int count;
    if (!glass::gl::getTexEnv(ctx, target, pname, v, &count)) return;
    for (int k = 0; k < count; ++k)
      params[k] = pname == GL_TEXTURE_ENV_COLOR ? glass::gl::colorToInteger(v[k])
                                                : static_cast<GLint>(std::lround(v[k]));
  });
}
