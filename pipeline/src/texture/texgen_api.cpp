// Texture coordinate generation commands (OpenGL 1.5 specification, section 2.11.4): glTexGen
// and glGetTexGen.
#include <GL/gl.h>

#include <array>
#include <cmath>

#include "core/context.h"
#include "core/errors.h"
#include "core/float_to_int.h"
#include "lists/command_recording.h"

namespace glass::gl {
namespace {

// The index of coord (0 = s .. 3 = q), or -1 for a value that is not a coordinate.
int coordinateIndex(GLenum coord) {
  switch (coord) {
    case GL_S: return 0;
    case GL_T: return 1;
    case GL_R: return 2;
    case GL_Q: return 3;
    default: return -1;
  }
}

int texGenParameterSize(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: return 1;
    case GL_OBJECT_PLANE:
    case GL_EYE_PLANE: return 4;
    default: return 0;
  }
}

void texGen(Context& ctx, GLenum coord, GLenum pname, const std::array<double, 4>& v, bool vector) {
  if (rejectInsideBeginEnd(ctx)) return;
  const int index = coordinateIndex(coord);
  const int size = texGenParameterSize(pname);
  if (index < 0 || size == 0 || (size > 1 && !vector)) return recordError(ctx, GL_INVALID_ENUM);
  TexGenCoordinate& g = ctx.texture.unit().texGen[index];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const GLenum mode = static_cast<GLenum>(enumFromFloat(v[0]));
      // SPHERE_MAP defines s and t only, REFLECTION_MAP and NORMAL_MAP s, t and r (spec 2.11.4).
      const bool valid = mode == GL_OBJECT_LINEAR || mode == GL_EYE_LINEAR ||
                         (mode == GL_SPHERE_MAP && index < 2) ||
                         ((mode == GL_REFLECTION_MAP || mode == GL_NORMAL_MAP) && index < 3);
      if (!valid) return recordError(ctx, GL_INVALID_ENUM);
      g.mode = mode;
      break;
    }
    case GL_OBJECT_PLANE:
      for (int k = 0; k < 4; ++k) g.objectPlane[k] = static_cast<float>(v[static_cast<size_t>(k)]);
      break;
    case GL_EYE_PLANE: {
      // The plane is stored in eye coordinates: p M^-1 with M the modelview matrix of this moment.
      const float plane[4] = {static_cast<float>(v[0]), static_cast<float>(v[1]),
                              static_cast<float>(v[2]), static_cast<float>(v[3])};
      transformEyePlane(plane, ctx.transform.modelview.top().m, g.eyePlane);
      break;
    }
    default: break;
  }
}

bool getTexGen(Context& ctx, GLenum coord, GLenum pname, double out[4], int* count) {
  if (rejectInsideBeginEnd(ctx)) return false;
  const int index = coordinateIndex(coord);
  *count = texGenParameterSize(pname);
  if (index < 0 || *count == 0) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  const TexGenCoordinate& g = ctx.texture.unit().texGen[index];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: out[0] = g.mode; break;
    case GL_OBJECT_PLANE: for (int k = 0; k < 4; ++k) out[k] = g.objectPlane[k]; break;
    case GL_EYE_PLANE: for (int k = 0; k < 4; ++k) out[k] = g.eyePlane[k]; break;
    default: break;
  }
  return true;
}

template <class T>
std::array<double, 4> copyTexGenValues(GLenum pname, const T* params) {
  std::array<double, 4> v{0.0, 0.0, 0.0, 0.0};
  const int n = texGenParameterSize(pname);
  for (int k = 0; k < n; ++k) v[static_cast<size_t>(k)] = static_cast<double>(params[k]);
  return v;
}

template <class T>
void getTexGenAs(GLenum coord, GLenum pname, T* params) {
  executeNow([=](Context& ctx) {
    double v[4];
    int count;
    if (!getTexGen(ctx, coord, pname, v, &count)) return;
    for (int k = 0; k < count; ++k) params[k] = static_cast<T>(v[k]);
  });
}

}  // namespace
}  // namespace glass::gl

using glass::gl::Context;

void GLAPIENTRY glTexGeni(GLenum coord, GLenum pname, GLint param) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    glass::gl::texGen(ctx, coord, pname, {static_cast<double>(param), 0.0, 0.0, 0.0}, false);
  });
}

void GLAPIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat param) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texGen(ctx, coord, pname, {param, 0.0, 0.0, 0.0}, false); });
}

void GLAPIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble param) {
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texGen(ctx, coord, pname, {param, 0.0, 0.0, 0.0}, false); });
}

void GLAPIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint* params) {
  const auto v = glass::gl::copyTexGenValues(pname, params);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texGen(ctx, coord, pname, v, true); });
}

void GLAPIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat* params) {
  const auto v = glass::gl::copyTexGenValues(pname, params);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texGen(ctx, coord, pname, v, true); });
}

void GLAPIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble* params) {
  const auto v = glass::gl::copyTexGenValues(pname, params);
  glass::gl::compileOrExecute([=](Context& ctx) { glass::gl::texGen(ctx, coord, pname, v, true); });
}

void GLAPIENTRY glGetTexGeniv(GLenum coord, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    double v[4];
    int count;
    if (!glass::gl::getTexGen(ctx, coord, pname, v, &count)) return;
    for (int k = 0; k < count; ++k) params[k] = static_cast<GLint>(std::lround(v[k]));
  });
}

void GLAPIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* params) {
  glass::gl::getTexGenAs(coord, pname, params);
}

void GLAPIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble* params) {
  glass::gl::getTexGenAs(coord, pname, params);
}
