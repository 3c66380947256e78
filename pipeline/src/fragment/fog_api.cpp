// glFogf, glFogi, glFogfv, glFogiv (OpenGL 1.5 specification, section 3.10). Values are checked
// and stored as given; the fog colour is clamped to [0, 1] when it is specified.
#include <GL/gl.h>

#include <vector>

#include "core/context.h"
#include "core/errors.h"
#include "lists/command_recording.h"
#include "texture/integer_colors.h"
#include "core/float_to_int.h"

namespace glass::gl {
namespace {

float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

// v holds 4 values for GL_FOG_COLOR, 1 otherwise; vectorForm: called as glFog*v.
void setFog(Context& ctx, GLenum pname, const float* v, bool vectorForm) {
  if (rejectInsideBeginEnd(ctx)) return;
  FogState& fog = ctx.fog;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum mode = static_cast<GLenum>(enumFromFloat(v[0]));
      if (static_cast<float>(mode) != v[0] ||
          (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2)) {
        break;
      }
      fog.mode = mode;
      return;
    }
    case GL_FOG_DENSITY:
      if (v[0] < 0.0f) {
        recordError(ctx, GL_INVALID_VALUE);
        return;
      }
      fog.density = v[0];
      return;
    case GL_FOG_START: fog.start = v[0]; return;
    case GL_FOG_END: fog.end = v[0]; return;
    case GL_FOG_INDEX: fog.index = v[0]; return;
    case GL_FOG_COLOR:
      if (!vectorForm) break;
      for (int i = 0; i < 4; ++i) fog.color[i] = clamp01(v[i]);
      return;
    case GL_FOG_COORDINATE_SOURCE: {
      const GLenum source = static_cast<GLenum>(enumFromFloat(v[0]));
      if (static_cast<float>(source) != v[0] ||
          (source != GL_FRAGMENT_DEPTH && source != GL_FOG_COORDINATE)) {
        break;
      }
      fog.coordinateSource = source;
      return;
    }
    default: break;
  }
  recordError(ctx, GL_INVALID_ENUM);
}

// Copies a glFog*v argument for a display list: 4 values for the colour, 1 otherwise.
template <class T>
std::vector<float> fogValues(GLenum pname, const T* params, bool integerColor) {
  std::vector<float> out(4, 0.0f);
  if (!params) return out;
  const int n = pname == GL_FOG_COLOR ? 4 : 1;
  for (int i = 0; i < n; ++i) {
    out[i] = integerColor && pname == GL_FOG_COLOR
                 ? static_cast<float>(integerToColor(static_cast<GLint>(params[i])))
                 : static_cast<float>(params[i]);
  }
  return out;
}

}  // namespace
}  // namespace glass::gl

using glass::gl::compileOrExecute;
using glass::gl::Context;

extern "C" {

void glFogf(GLenum pname, GLfloat param) {
  compileOrExecute([=](Context& ctx) {
    const float v[4] = {param, 0.0f, 0.0f, 0.0f};
    glass::gl::setFog(ctx, pname, v, false);
  });
}

void glFogi(GLenum pname, GLint param) {
  compileOrExecute([=](Context& ctx) {
    const float v[4] = {static_cast<float>(param), 0.0f, 0.0f, 0.0f};
    glass::gl::setFog(ctx, pname, v, false);
  });
}

void glFogfv(GLenum pname, const GLfloat* params) {
  const std::vector<float> values = glass::gl::fogValues(pname, params, false);
  compileOrExecute([=](Context& ctx) { glass::gl::setFog(ctx, pname, values.data(), true); });
}

void glFogiv(GLenum pname, const GLint* params) {
  const std::vector<float> values = glass::gl::fogValues(pname, params, true);
  compileOrExecute([=](Context& ctx) { glass::gl::setFog(ctx, pname, values.data(), true); });
}

}  // extern "C"
