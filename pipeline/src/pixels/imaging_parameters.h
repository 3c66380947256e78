// The imaging subset's parameter queries (glGetColorTableParameter, glGetConvolutionParameter,
// glGetHistogramParameter, glGetMinmaxParameter; OpenGL 1.4 specification, sections 6.1.7-6.1.10):
// executed at once, never compiled (spec 5.4), their values converted to the caller's type
// (section 6.1.2): floats as they are, integers rounded to the nearest and saturated.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/context.h"
#include "lists/command_recording.h"

namespace glass::gl {

inline void convertParameters(const std::vector<double>& values, GLfloat* out) {
  for (size_t i = 0; i < values.size(); ++i) out[i] = static_cast<GLfloat>(values[i]);
}

inline void convertParameters(const std::vector<double>& values, GLint* out) {
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = std::isnan(values[i]) ? 0.0 : std::nearbyint(values[i]);
    out[i] = static_cast<GLint>(std::clamp(v, -2147483648.0, 2147483647.0));
  }
}

// Answers a parameter query: `values(ctx, target, pname, out)` fills out, or returns false for a
// target or pname the query does not take (GL_INVALID_ENUM).
template <class T, class Values>
void answerParameterQuery(GLenum target, GLenum pname, T* params, Values values) {
  executeNow([=](Context& ctx) {
    if (rejectInsideBeginEnd(ctx)) return;
    std::vector<double> v;
    if (!values(ctx, target, pname, v)) return recordError(ctx, GL_INVALID_ENUM);
    if (params) convertParameters(v, params);
  });
}

}  // namespace glass::gl
