// Texture parameters (OpenGL 1.5 specification, section 3.8.4, table 3.19): glTexParameter and
// glGetTexParameter.
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/context.h"
#include "core/errors.h"
#include "core/float_to_int.h"
#include "lists/command_recording.h"
#include "texture/integer_colors.h"
#include "texture/texture_commands.h"

namespace glass::gl {
namespace {

bool isWrapMode(GLenum mode) {
  return mode == GL_REPEAT || mode == GL_CLAMP || mode == GL_CLAMP_TO_EDGE ||
         mode == GL_CLAMP_TO_BORDER || mode == GL_MIRRORED_REPEAT;
}

bool isMinFilter(GLenum f) {
  return f == GL_NEAREST || f == GL_LINEAR || isMipmapFilter(f);
}

// The number of values a parameter takes; 0 for a pname that is not a texture parameter.
int parameterSize(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
    case GL_TEXTURE_MAG_FILTER:
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R:
    case GL_TEXTURE_PRIORITY:
    case GL_TEXTURE_MIN_LOD:
    case GL_TEXTURE_MAX_LOD:
    case GL_TEXTURE_LOD_BIAS:
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL:
    case GL_GENERATE_MIPMAP:
    case GL_TEXTURE_COMPARE_MODE:
    case GL_TEXTURE_COMPARE_FUNC:
    case GL_DEPTH_TEXTURE_MODE: return 1;
    case GL_TEXTURE_BORDER_COLOR: return 4;
    default: return 0;
  }
}

// Values arrive as floats (glTexParameterf/fv, or glTexParameteri/iv converted exactly, except
// the border colour of glTexParameteriv, which the caller converts as a colour). vector says
// whether a v form was called: the border colour has no scalar form.
void texParameter(Context& ctx, GLenum target, GLenum pname, const std::array<double, 4>& v, bool vector) {
  if (rejectInsideBeginEnd(ctx)) return;
  TextureObject* texture = boundTexture(ctx, target);
  if (texture == nullptr) return recordError(ctx, GL_INVALID_ENUM);
  const int size = parameterSize(pname);
  if (size == 0 || (size > 1 && !vector)) return recordError(ctx, GL_INVALID_ENUM);
  SamplerParameters& p = texture->params;
  const GLenum e = static_cast<GLenum>(enumFromFloat(v[0]));
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (!isMinFilter(e)) return recordError(ctx, GL_INVALID_ENUM);
      p.minFilter = e;
      break;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return recordError(ctx, GL_INVALID_ENUM);
      p.magFilter = e;
      break;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R:
      if (!isWrapMode(e)) return recordError(ctx, GL_INVALID_ENUM);
      (pname == GL_TEXTURE_WRAP_S ? p.wrapS : pname == GL_TEXTURE_WRAP_T ? p.wrapT : p.wrapR) = e;
      break;
    case GL_TEXTURE_BORDER_COLOR:
      for (int k = 0; k < 4; ++k) p.borderColor[k] = static_cast<float>(std::clamp(v[k], 0.0, 1.0));
      break;
    case GL_TEXTURE_PRIORITY:
      p.priority = static_cast<float>(std::clamp(v[0], 0.0, 1.0));
      break;
    case GL_TEXTURE_MIN_LOD: p.minLod = static_cast<float>(v[0]); break;
    case GL_TEXTURE_MAX_LOD: p.maxLod = static_cast<float>(v[0]); break;
    case GL_TEXTURE_LOD_BIAS: p.lodBias = static_cast<float>(v[0]); break;
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL: {
      // Spec 3.8.4: negative levels are an INVALID_VALUE error. Integral values are expected;
      // a fractional float is rounded like any integer state set from a float.
      const double level = std::nearbyint(v[0]);
      if (level < 0.0) return recordError(ctx, GL_INVALID_VALUE);
      const int clamped = static_cast<int>(std::min(level, 1.0e6));
      (pname == GL_TEXTURE_BASE_LEVEL ? p.baseLevel : p.maxLevel) = clamped;
      break;
    }
    case GL_GENERATE_MIPMAP:
      p.generateMipmap = v[0] != 0.0;
      break;
    // OpenGL 1.4, 3.8.4 (table 3.19); the functions beyond LEQUAL and GEQUAL are
    // GL_EXT_shadow_funcs' (OpenGL 1.5).
    case GL_TEXTURE_COMPARE_MODE:
      if (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE) return recordError(ctx, GL_INVALID_ENUM);
      p.compareMode = e;
      break;
    case GL_TEXTURE_COMPARE_FUNC:
      if (e < GL_NEVER || e > GL_ALWAYS) return recordError(ctx, GL_INVALID_ENUM);
      p.compareFunc = e;
      break;
    case GL_DEPTH_TEXTURE_MODE:
      if (e != GL_LUMINANCE && e != GL_INTENSITY && e != GL_ALPHA)
        return recordError(ctx, GL_INVALID_ENUM);
      p.depthTextureMode = e;
      break;
    default: break;
  }
  texture->updateCompleteness();
}

// glGetTexParameter: the value(s) of pname as doubles; false (after the error) when invalid.
// isColor marks the border colour, which integer queries map as colours (spec 6.1.2).
bool getTexParameter(Context& ctx, GLenum target, GLenum pname, double out[4], int* count, bool* isColor) {
  if (rejectInsideBeginEnd(ctx)) return false;
  const TextureObject* texture = boundTexture(ctx, target);
  if (texture == nullptr) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  const SamplerParameters& p = texture->params;
  *count = 1;
  *isColor = false;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = p.minFilter; return true;
    case GL_TEXTURE_MAG_FILTER: out[0] = p.magFilter; return true;
    case GL_TEXTURE_WRAP_S: out[0] = p.wrapS; return true;
    case GL_TEXTURE_WRAP_T: out[0] = p.wrapT; return true;
    case GL_TEXTURE_WRAP_R: out[0] = p.wrapR; return true;
    case GL_TEXTURE_BORDER_COLOR:
      for (int k = 0; k < 4; ++k) out[k] = p.borderColor[k];
      *count = 4;
      *isColor = true;
      return true;
    case GL_TEXTURE_PRIORITY: out[0] = p.priority; return true;
    case GL_TEXTURE_RESIDENT: out[0] = GL_TRUE; return true;
    case GL_TEXTURE_MIN_LOD: out[0] = p.minLod; return true;
    case GL_TEXTURE_MAX_LOD: out[0] = p.maxLod; return true;
    case GL_TEXTURE_LOD_BIAS: out[0] = p.lodBias; return true;
    case GL_TEXTURE_BASE_LEVEL: out[0] = p.baseLevel; return true;
    case GL_TEXTURE_MAX_LEVEL: out[0] = p.maxLevel; return true;
    case GL_GENERATE_MIPMAP: out[0] = p.generateMipmap ? GL_TRUE : GL_FALSE; return true;
    case GL_TEXTURE_COMPARE_MODE: out[0] = p.compareMode; return true;
    case GL_TEXTURE_COMPARE_FUNC: out[0] = p.compareFunc; return true;
    case GL_DEPTH_TEXTURE_MODE: out[0] = p.depthTextureMode; return true;
    default:
      recordError(ctx, GL_INVALID_ENUM);
      return false;
  }
}

// Copies the values a pointer argument holds for pname (none for an unknown pname: the command
// then reports the error when it runs).
template <class T>
std::array<double, 4> copyParameterValues(GLenum pname, const T* params, bool colorFromInteger) {
  std::array<double, 4> v{0.0, 0.0, 0.0, 0.0};
  const int n = parameterSize(pname);
  for (int k = 0; k < n; ++k) {
    v[static_cast<size_t>(k)] = colorFromInteger && pname == GL_TEXTURE_BORDER_COLOR
                                    ? integerToColor(static_cast<GLint>(params[k]))
                                    : static_cast<double>(params[k]);
  }
  return v;
}

}  // namespace
}  // namespace glass::gl

using glass::gl::Context;

void GLAPIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat param) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::texParameter(ctx, target, pname, {param, 0.0, 0.0, 0.0}, false);
  });
}

void GLAPIENTRY glTexParameteri(GLenum target, GLenum pname, GLint param) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::texParameter(ctx, target, pname, {static_cast<double>(param), 0.0, 0.0, 0.0}, false);
  });
}

void GLAPIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  const auto v = glass::gl::copyParameterValues(pname, params, false);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texParameter(ctx, target, pname, v, true); });
}

void GLAPIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint* params) {
  const auto v = glass::gl::copyParameterValues(pname, params, true);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texParameter(ctx, target, pname, v, true); });
}

void GLAPIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double v[4];
    int count;
    bool isColor;
    if (!glass::gl::getTexParameter(ctx, target, pname, v, &count, &isColor)) return;
    for (int k = 0; k < count; ++k) params[k] = static_cast<GLfloat>(v[k]);
  });
}

void GLAPIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double v[4];
    int count;
    bool isColor;
    if (!glass::gl::getTexParameter(ctx, target, pname, v, &count, &isColor)) return;
    for (int k = 0; k < count; ++k)
      params[k] = isColor ? glass::gl::colorToInteger(v[k]) : static_cast<GLint>(std::lround(v[k]));
  });
}
