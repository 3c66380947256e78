// glLight*, glGetLight* and glLightModel* (OpenGL 1.5 specification, section 2.13.2, and 6.1.3
// for the queries). Positions and spot directions are transformed into eye coordinates when they
// are given, by the modelview matrix current then; the queries return them as stored.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "core/matrix.h"
#include "lists/command_recording.h"
#include "texture/integer_colors.h"
#include "core/float_to_int.h"

namespace glass::gl {
namespace {

LightSource* lightFor(Context& ctx, GLenum light) {
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights) return nullptr;
  return &ctx.lighting.lights[light - GL_LIGHT0];
}

// How many values a glLight parameter takes; 0 for a name glLight does not know.
int lightParameterCount(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT:
    case GL_SPOT_CUTOFF:
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
  }
}

bool isLightColor(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
}

// glLight with its values already converted to float (spec 2.13.2 and its error list).
void setLight(Context& ctx, GLenum light, GLenum pname, const float* v) {
  if (rejectInsideBeginEnd(ctx)) return;
  LightSource* l = lightFor(ctx, light);
  if (!l || lightParameterCount(pname) == 0) {
    recordError(ctx, GL_INVALID_ENUM);
    return;
  }
  const Matrix4& modelview = ctx.transform.modelview.top();
  switch (pname) {
    case GL_AMBIENT:
      for (int i = 0; i < 4; ++i) l->ambient[i] = v[i];
      break;
    case GL_DIFFUSE:
      for (int i = 0; i < 4; ++i) l->diffuse[i] = v[i];
      break;
    case GL_SPECULAR:
      for (int i = 0; i < 4; ++i) l->specular[i] = v[i];
      break;
    case GL_POSITION: {
      // The position is a homogeneous point: transformed by the whole modelview matrix.
      const float object[4] = {v[0], v[1], v[2], v[3]};
      transformVector4(modelview, object, l->position);
      break;
    }
    case GL_SPOT_DIRECTION: {
      // A direction: transformed by the upper-left 3x3 of the modelview matrix.
      const float object[4] = {v[0], v[1], v[2], 0.0f};
      float eye[4];
      transformVector4(modelview, object, eye);
      for (int i = 0; i < 3; ++i) l->spotDirection[i] = eye[i];
      break;
    }
    case GL_SPOT_EXPONENT:
      if (v[0] < 0.0f || v[0] > 128.0f) {
        recordError(ctx, GL_INVALID_VALUE);
        return;
      }
      l->spotExponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if ((v[0] < 0.0f || v[0] > 90.0f) && v[0] != 180.0f) {
        recordError(ctx, GL_INVALID_VALUE);
        return;
      }
      l->spotCutoff = v[0];
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: {
      if (v[0] < 0.0f) {
        recordError(ctx, GL_INVALID_VALUE);
        return;
      }
      float& k = pname == GL_CONSTANT_ATTENUATION ? l->constantAttenuation
                 : pname == GL_LINEAR_ATTENUATION ? l->linearAttenuation
                                                  : l->quadraticAttenuation;
      k = v[0];
      break;
    }
    default: break;
  }
}

// The scalar forms take only the one-valued parameters.
void setLightScalar(Context& ctx, GLenum light, GLenum pname, float value) {
  if (lightParameterCount(pname) != 1) {
    if (!rejectInsideBeginEnd(ctx)) recordError(ctx, GL_INVALID_ENUM);
    return;
  }
  setLight(ctx, light, pname, &value);
}

// Copies a pointer argument for a display list: as many values as pname takes (none for an
// unknown name, whose error the command reports when it runs).
template <class T>
std::vector<T> lightValues(GLenum pname, const T* params) {
  const int n = params ? lightParameterCount(pname) : 0;
  return std::vector<T>(params, params + n);
}

// glLightiv: colours map the integer range onto [-1, 1] (table 2.9); the other values convert
// directly.
std::vector<float> lightIntegersToFloat(GLenum pname, const std::vector<GLint>& in) {
  std::vector<float> out(4, 0.0f);
  for (size_t i = 0; i < in.size(); ++i) {
    out[i] = isLightColor(pname) ? static_cast<float>(integerToColor(in[i]))
                                 : static_cast<float>(in[i]);
  }
  return out;
}

// glGetLight: the stored values (eye coordinates for position and direction).
int getLight(Context& ctx, GLenum light, GLenum pname, float out[4]) {
  if (rejectInsideBeginEnd(ctx)) return 0;
  LightSource* l = lightFor(ctx, light);
  const int n = lightParameterCount(pname);
  if (!l || n == 0) {
    recordError(ctx, GL_INVALID_ENUM);
    return 0;
  }
  const float* source = nullptr;
  switch (pname) {
    case GL_AMBIENT: source = l->ambient; break;
    case GL_DIFFUSE: source = l->diffuse; break;
    case GL_SPECULAR: source = l->specular; break;
    case GL_POSITION: source = l->position; break;
    case GL_SPOT_DIRECTION: source = l->spotDirection; break;
    case GL_SPOT_EXPONENT: source = &l->spotExponent; break;
    case GL_SPOT_CUTOFF: source = &l->spotCutoff; break;
    case GL_CONSTANT_ATTENUATION: source = &l->constantAttenuation; break;
    case GL_LINEAR_ATTENUATION: source = &l->linearAttenuation; break;
    default: source = &l->quadraticAttenuation; break;
  }
  for (int i = 0; i < n; ++i) out[i] = source[i];
  return n;
}

// glLightModel with float values (spec 2.13.2).
void setLightModel(Context& ctx, GLenum pname, const float* v, bool vectorForm) {
  if (rejectInsideBeginEnd(ctx)) return;
  LightModel& m = ctx.lighting.model;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
      if (!vectorForm) break;
      for (int i = 0; i < 4; ++i) m.ambient[i] = v[i];
      return;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: m.localViewer = v[0] != 0.0f; return;
    case GL_LIGHT_MODEL_TWO_SIDE: m.twoSide = v[0] != 0.0f; return;
    case GL_LIGHT_MODEL_COLOR_CONTROL: {
      const GLenum mode = static_cast<GLenum>(enumFromFloat(v[0]));
      if (static_cast<float>(mode) != v[0] ||
          (mode != GL_SINGLE_COLOR && mode != GL_SEPARATE_SPECULAR_COLOR)) {
        break;
      }
      m.separateSpecular = mode == GL_SEPARATE_SPECULAR_COLOR;
      return;
    }
    default: break;
  }
  recordError(ctx, GL_INVALID_ENUM);
}

std::vector<float> lightModelValues(GLenum pname, const float* params) {
  if (!params) return {};
  const int n = pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1;
  std::vector<float> out(params, params + n);
  out.resize(4, 0.0f);
  return out;
}

}  // namespace
}  // namespace glass::gl

using glass::gl::compileOrExecute;
using glass::gl::Context;

extern "C" {

void glLightf(GLenum light, GLenum pname, GLfloat param) {
  compileOrExecute([=](Context& ctx) { glass::gl::setLightScalar(ctx, light, pname, param); });
}

void glLighti(GLenum light, GLenum pname, GLint param) {
  compileOrExecute([=](Context& ctx) {
    glass::gl::setLightScalar(ctx, light, pname, static_cast<float>(param));
  });
}

void glLightfv(GLenum light, GLenum pname, const GLfloat* params) {
  std::vector<float> values = glass::gl::lightValues(pname, params);
  values.resize(4, 0.0f);
  const bool known = params != nullptr && glass::gl::lightParameterCount(pname) != 0;
  compileOrExecute([=](Context& ctx) {
    if (!known) {
      if (!glass::gl::rejectInsideBeginEnd(ctx)) glass::gl::recordError(ctx, GL_INVALID_ENUM);
      return;
    }
    glass::gl::setLight(ctx, light, pname, values.data());
  });
}

void glLightiv(GLenum light, GLenum pname, const GLint* params) {
  const std::vector<float> values =
      glass::gl::lightIntegersToFloat(pname, glass::gl::lightValues(pname, params));
  const bool known = params != nullptr && glass::gl::lightParameterCount(pname) != 0;
  compileOrExecute([=](Context& ctx) {
    if (!known) {
      if (!glass::gl::rejectInsideBeginEnd(ctx)) glass::gl::recordError(ctx, GL_INVALID_ENUM);
      return;
    }
    glass::gl::setLight(ctx, light, pname, values.data());
  });
}

void glGetLightfv(GLenum light, GLenum pname, GLfloat* params) {
  glass::gl::executeNow([=](Context& ctx) {
    float values[4];
    const int n = glass::gl::getLight(ctx, light, pname, values);
    for (int i = 0; i < n && params; ++i) params[i] = values[i];
  });
}

void glGetLightiv(GLenum light, GLenum pname, GLint* params) {
  glass::gl::executeNow([=](Context& ctx) {
    float values[4];
    const int n = glass::gl::getLight(ctx, light, pname, values);
    const bool isColor = glass::gl::isLightColor(pname);
    for (int i = 0; i < n && params; ++i) params[i] = glass::gl::queriedInteger(values[i], isColor);
  });
}

void glLightModelf(GLenum pname, GLfloat param) {
  compileOrExecute([=](Context& ctx) {
    const float v[4] = {param, 0.0f, 0.0f, 0.0f};
    glass::gl::setLightModel(ctx, pname, v, false);
  });
}

void glLightModeli(GLenum pname, GLint param) {
  compileOrExecute([=](Context& ctx) {
    const float v[4] = {static_cast<float>(param), 0.0f, 0.0f, 0.0f};
    glass::gl::setLightModel(ctx, pname, v, false);
  });
}

void glLightModelfv(GLenum pname, const GLfloat* params) {
  const std::vector<float> values = glass::gl::lightModelValues(pname, params);
  compileOrExecute([=](Context& ctx) {
    if (values.empty()) {
      if (!glass::gl::rejectInsideBeginEnd(ctx)) glass::gl::recordError(ctx, GL_INVALID_VALUE);
      return;
    }
    glass::gl::setLightModel(ctx, pname, values.data(), true);
  });
}

void glLightModeliv(GLenum pname, const GLint* params) {
  std::vector<float> values;
  if (params) {
    if (pname == GL_LIGHT_MODEL_AMBIENT) {
      for (int i = 0; i < 4; ++i) {
        values.push_back(static_cast<float>(glass::gl::integerToColor(params[i])));
      }
    } else {
      values = {static_cast<float>(params[0]), 0.0f, 0.0f, 0.0f};
    }
  }
  compileOrExecute([=](Context& ctx) {
    if (values.empty()) {
      if (!glass::gl::rejectInsideBeginEnd(ctx)) glass::gl::recordError(ctx, GL_INVALID_VALUE);
      return;
    }
    glass::gl::setLightModel(ctx, pname, values.data(), true);
  });
}

}  // extern "C"
