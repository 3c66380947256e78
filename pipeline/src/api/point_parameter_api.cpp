// glPointParameterf/fv/i/iv (OpenGL 1.4, spec 3.3; primitive/point_parameters.h). Sizes and the
// fade threshold must not be negative (GL_INVALID_VALUE); GL_POINT_DISTANCE_ATTENUATION takes
// three values and so only the vector forms (GL_INVALID_ENUM for the scalar ones).
#include <GL/gl.h>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::Context;
using glass::gl::recordError;

namespace {

void setPointParameter(GLenum pname, const float* v, bool vectorForm) {
  const float values[3] = {v[0], vectorForm ? v[1] : 0.0f, vectorForm ? v[2] : 0.0f};
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    glass::gl::RasterState& r = ctx.raster;
    switch (pname) {
      case GL_POINT_SIZE_MIN:
      case GL_POINT_SIZE_MAX:
      case GL_POINT_FADE_THRESHOLD_SIZE: {
        if (values[0] < 0.0f) return recordError(ctx, GL_INVALID_VALUE);
        float& target = pname == GL_POINT_SIZE_MIN   ? r.pointSizeMin
                        : pname == GL_POINT_SIZE_MAX ? r.pointSizeMax
                                                     : r.pointFadeThreshold;
        target = values[0];
        return;
      }
      case GL_POINT_DISTANCE_ATTENUATION:
        if (!vectorForm) break;
        for (int i = 0; i < 3; ++i) r.pointDistanceAttenuation[i] = values[i];
        return;
      default: break;
    }
    recordError(ctx, GL_INVALID_ENUM);
  });
}

}  // namespace

extern "C" {

void glPointParameterf(GLenum pname, GLfloat param) { setPointParameter(pname, &param, false); }

void glPointParameteri(GLenum pname, GLint param) {
  const float value = static_cast<float>(param);
  setPointParameter(pname, &value, false);
}

void glPointParameterfv(GLenum pname, const GLfloat* params) {
  if (params) setPointParameter(pname, params, pname == GL_POINT_DISTANCE_ATTENUATION);
}

void glPointParameteriv(GLenum pname, const GLint* params) {
  if (!params) return;
  const int n = pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1;
  float values[3] = {0.0f, 0.0f, 0.0f};
  for (int i = 0; i < n; ++i) values[i] = static_cast<float>(params[i]);
  setPointParameter(pname, values, n == 3);
}

}  // extern "C"
