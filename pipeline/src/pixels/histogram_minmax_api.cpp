// The histogram and minmax commands of the imaging subset (OpenGL 1.4 specification, sections
// 3.6.3 "Histogram Table Specification", "Minmax Table Specification", 6.1.9 "Histogram Query"
// and 6.1.10 "Minmax Query"; GL_ARB_imaging).
//
// Display lists (spec 5.4): glHistogram, glMinmax and the resets are compiled; glHistogram with
// GL_PROXY_HISTOGRAM executes at once, as do the queries.
#include <GL/gl.h>

#include <algorithm>
#include <vector>

#include "core/context.h"
#include "lists/command_recording.h"
#include "pixels/imaging_client_data.h"
#include "pixels/imaging_formats.h"
#include "pixels/imaging_parameters.h"
#include "texture/client_pixels.h"

using glass::gl::Context;
using glass::gl::Histogram;
using glass::gl::Minmax;
using glass::gl::recordError;

namespace {

void specifyHistogram(Context& ctx, bool proxy, GLsizei width, GLenum internalFormat, bool sink) {
  Histogram& h = proxy ? ctx.imaging.proxyHistogram : ctx.imaging.histogram;
  if (width > glass::gl::kMaxHistogramWidth) {
    // Too large: a proxy says so with a zero width and format; a real histogram is an error.
    if (!proxy) return recordError(ctx, GL_TABLE_TOO_LARGE);
    h = Histogram{};
    h.internalFormat = 0;
    return;
  }
  Histogram specified;
  specified.width = width;
  specified.internalFormat = internalFormat;
  glass::gl::imagingBaseFormat(internalFormat, &specified.base);
  specified.sink = sink;
  if (!proxy) specified.counts.assign(static_cast<size_t>(width) * 4, 0u);
  h = std::move(specified);
}

bool histogramParameterValues(const Context& ctx, GLenum target, GLenum pname, std::vector<double>& out) {
  if (target != GL_HISTOGRAM && target != GL_PROXY_HISTOGRAM) return false;
  const Histogram& h = target == GL_HISTOGRAM ? ctx.imaging.histogram : ctx.imaging.proxyHistogram;
  switch (pname) {
    case GL_HISTOGRAM_WIDTH: out = {double(h.width)}; return true;
    case GL_HISTOGRAM_FORMAT: out = {double(h.internalFormat)}; return true;
    case GL_HISTOGRAM_SINK: out = {h.sink ? 1.0 : 0.0}; return true;
    case GL_HISTOGRAM_RED_SIZE:
    case GL_HISTOGRAM_GREEN_SIZE:
    case GL_HISTOGRAM_BLUE_SIZE:
    case GL_HISTOGRAM_ALPHA_SIZE:
    case GL_HISTOGRAM_LUMINANCE_SIZE:
      // Counters are 32-bit unsigned integers.
      out = {h.width > 0 && glass::gl::imagingComponentBits(h.base, static_cast<int>(pname - GL_HISTOGRAM_RED_SIZE)) > 0
                 ? 32.0 : 0.0};
      return true;
    default: return false;
  }
}

bool minmaxParameterValues(const Context& ctx, GLenum target, GLenum pname, std::vector<double>& out) {
  if (target != GL_MINMAX) return false;
  const Minmax& m = ctx.imaging.minmax;
  switch (pname) {
    case GL_MINMAX_FORMAT: out = {double(m.internalFormat)}; return true;
    case GL_MINMAX_SINK: out = {m.sink ? 1.0 : 0.0}; return true;
    default: return false;
  }
}

}  // namespace

extern "C" {

void glHistogram(GLenum target, GLsizei width, GLenum internalformat, GLboolean sink) {
  glass::gl::executeNow([=](Context& ctx) {
    const bool proxy = target == GL_PROXY_HISTOGRAM;
    auto command = [=](Context& c) {
      if (glass::gl::rejectInsideBeginEnd(c)) return;
      if (target != GL_HISTOGRAM && !proxy) return recordError(c, GL_INVALID_ENUM);
      // Spec 3.6.3: a width that is neither zero nor a power of two is GL_INVALID_VALUE.
      if (width < 0 || (width & (width - 1)) != 0) return recordError(c, GL_INVALID_VALUE);
      if (!glass::gl::isHistogramFormat(internalformat)) return recordError(c, GL_INVALID_ENUM);
      specifyHistogram(c, proxy, width, internalformat, sink != GL_FALSE);
    };
    if (proxy) {
      command(ctx);
    } else {
      glass::gl::compileOrExecuteOn(ctx, command);
    }
  });
}

void glResetHistogram(GLenum target) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (target != GL_HISTOGRAM) return recordError(ctx, GL_INVALID_ENUM);
    std::fill(ctx.imaging.histogram.counts.begin(), ctx.imaging.histogram.counts.end(), 0u);
  });
}

void glGetHistogram(GLenum target, GLboolean reset, GLenum format, GLenum type, GLvoid* values) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (const GLenum error = glass::gl::checkImagingQuery(target == GL_HISTOGRAM, format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    Histogram& h = ctx.imaging.histogram;
    if (values && h.width > 0) {
      glass::gl::packCountSpan(h.counts.data(), h.width, format, type, ctx.pixelStore.pack, values);
    }
    if (reset) std::fill(h.counts.begin(), h.counts.end(), 0u);
  });
}

void glGetHistogramParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::answerParameterQuery(target, pname, params, histogramParameterValues);
}
void glGetHistogramParameteriv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::answerParameterQuery(target, pname, params, histogramParameterValues);
}

void glMinmax(GLenum target, GLenum internalformat, GLboolean sink) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (target != GL_MINMAX || !glass::gl::isHistogramFormat(internalformat)) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    Minmax& m = ctx.imaging.minmax;
    m.internalFormat = internalformat;
    glass::gl::imagingBaseFormat(internalformat, &m.base);
    m.sink = sink != GL_FALSE;
    m.reset();
  });
}

void glResetMinmax(GLenum target) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (target != GL_MINMAX) return recordError(ctx, GL_INVALID_ENUM);
    ctx.imaging.minmax.reset();
  });
}

void glGetMinmax(GLenum target, GLboolean reset, GLenum format, GLenum type, GLvoid* values) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (const GLenum error = glass::gl::checkImagingQuery(target == GL_MINMAX, format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    Minmax& m = ctx.imaging.minmax;
    if (values) {
      // A one-dimensional image of two groups, the minimum then the maximum, with the components
      // the format does not name as table 6.1 returns them.
      float groups[8];
      std::copy(m.minimum, m.minimum + 4, groups);
      std::copy(m.maximum, m.maximum + 4, groups + 4);
      glass::gl::keepBaseComponents(m.base, groups);
      glass::gl::keepBaseComponents(m.base, groups + 4);
      glass::gl::packRgbaBlock(groups, 2, 1, format, type, ctx.pixelStore.pack, values);
    }
    if (reset) m.reset();
  });
}

void glGetMinmaxParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::answerParameterQuery(target, pname, params, minmaxParameterValues);
}
void glGetMinmaxParameteriv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::answerParameterQuery(target, pname, params, minmaxParameterValues);
}

}  // extern "C"
