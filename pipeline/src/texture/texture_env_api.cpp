// The texture environment (OpenGL 1.5 specification, section 3.8.13): glTexEnv and glGetTexEnv,
// and the parameters of the bump-mapping extension, which use the same commands with the target
// GL_BUMP_MAP_GLASS.
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/context.h"
#include "core/errors.h"
#include "lists/command_recording.h"
#include "texture/integer_colors.h"
#include "core/float_to_int.h"

namespace glass::gl {
namespace {

bool isEnvMode(GLenum mode) {
  return mode == GL_MODULATE || mode == GL_DECAL || mode == GL_BLEND || mode == GL_REPLACE ||
         mode == GL_ADD;
}

// The number of values of a (target, pname) pair; 0 when the pair is not an environment parameter.
int envParameterSize(GLenum target, GLenum pname) {
  if (target == GL_TEXTURE_ENV) {
    if (pname == GL_TEXTURE_ENV_MODE) return 1;
    if (pname == GL_TEXTURE_ENV_COLOR) return 4;
    return 0;
  }
  if (target == GL_BUMP_MAP_GLASS)
    return pname == GL_BUMP_MAP_TEXTURE_GLASS || pname == GL_BUMP_SCALE_GLASS ? 1 : 0;
  return 0;
}

void texEnv(Context& ctx, GLenum target, GLenum pname, const std::array<double, 4>& v, bool vector) {
  if (rejectInsideBeginEnd(ctx)) return;
  const int size = envParameterSize(target, pname);
  if (size == 0 || (size > 1 && !vector)) return recordError(ctx, GL_INVALID_ENUM);
  TextureState& t = ctx.texture;
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: {
      const GLenum mode = static_cast<GLenum>(enumFromFloat(v[0]));
      if (!isEnvMode(mode)) return recordError(ctx, GL_INVALID_ENUM);
      t.envMode = mode;
      break;
    }
    case GL_TEXTURE_ENV_COLOR:
      for (int k = 0; k < 4; ++k) t.envColor[k] = static_cast<float>(std::clamp(v[k], 0.0, 1.0));
      break;
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
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: out[0] = t.envMode; break;
    case GL_TEXTURE_ENV_COLOR: for (int k = 0; k < 4; ++k) out[k] = t.envColor[k]; break;
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
