// The convolution commands of the imaging subset (OpenGL 1.4 specification, sections 3.6.3
// "Convolution Filter Specification" and 6.1.8 "Convolution Query"; GL_ARB_imaging):
// glConvolutionFilter1D/2D, glSeparableFilter2D, glCopyConvolutionFilter1D/2D,
// glConvolutionParameter and their queries.
//
// Display lists (spec 5.4): the specification and parameter commands are compiled, with their
// client data unpacked when compiled; the queries execute at once.
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <memory>
#include <new>
#include <vector>

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "lists/command_recording.h"
#include "pixels/imaging_client_data.h"
#include "pixels/imaging_formats.h"
#include "pixels/imaging_parameters.h"
#include "primitive/queued_drawing.h"

using glass::gl::ConvolutionFilter;
using glass::gl::ConvolutionParameters;
using glass::gl::Context;
using glass::gl::recordError;

namespace {

int convolutionTarget(GLenum target) {
  switch (target) {
    case GL_CONVOLUTION_1D: return glass::gl::kConvolution1D;
    case GL_CONVOLUTION_2D: return glass::gl::kConvolution2D;
    case GL_SEPARABLE_2D: return glass::gl::kSeparable2D;
    default: return -1;
  }
}

using Groups = std::shared_ptr<const std::vector<float>>;

bool isFilterSize(GLsizei size) { return size >= 0 && size <= glass::gl::kMaxConvolutionSize; }

// The checks of the specification commands (spec 3.6.3): the target the command takes, a table
// 3.15 internal format, sizes in [0, GL_MAX_CONVOLUTION_WIDTH/HEIGHT], a colour format.
GLenum filterError(GLenum target, GLenum expected, GLenum internalFormat, GLsizei width, GLsizei height) {
  if (target != expected || !glass::gl::isColorTableFormat(internalFormat)) return GL_INVALID_ENUM;
  return isFilterSize(width) && isFilterSize(height) ? GL_NO_ERROR : GL_INVALID_VALUE;
}

// Spec 3.6.3: the filter's groups are scaled by GL_CONVOLUTION_FILTER_SCALE and biased by
// GL_CONVOLUTION_FILTER_BIAS (not clamped) and kept as the internal format says. `rgba` holds
// width x height groups (width + height for a separable filter), or is empty when no data was
// given (the filter is then 0).
void specifyFilter(Context& ctx, int target, GLenum internalFormat, int width, int height,
                   const std::vector<float>& rgba) {
  const ConvolutionParameters& p = ctx.imaging.mode.convolution[target];
  ConvolutionFilter f;
  f.internalFormat = internalFormat;
  glass::gl::imagingBaseFormat(internalFormat, &f.base);
  f.width = width;
  f.height = height;
  const size_t groups = target == glass::gl::kSeparable2D ? static_cast<size_t>(width) + height
                                                          : static_cast<size_t>(width) * height;
  f.values.assign(groups * 4, 0.0f);
  if (!rgba.empty()) {
    for (size_t i = 0; i < groups; ++i) {
      float* v = &f.values[i * 4];
      for (int k = 0; k < 4; ++k) v[k] = rgba[i * 4 + k] * p.filterScale[k] + p.filterBias[k];
      glass::gl::keepBaseComponents(f.base, v);
    }
  }
  ctx.imaging.filters[target] = std::move(f);
}

// glConvolutionFilter1D/2D and glSeparableFilter2D: unpacks when given, then compiles or runs.
// `images` are the client blocks to unpack, each width x rows.
struct ClientBlock {
  const void* pixels;
  int width, rows;
};

void filterCommand(GLenum target, GLenum expected, GLenum internalFormat, GLsizei width,
                   GLsizei height, GLenum format, GLenum type, std::vector<ClientBlock> blocks) {
  glass::gl::executeNow([&](Context& ctx) {
    GLenum error = filterError(target, expected, internalFormat, width, height);
    if (error == GL_NO_ERROR) error = glass::gl::checkImagingFormatAndType(format, type);
    auto rgba = std::make_shared<std::vector<float>>();
    const bool given = std::all_of(blocks.begin(), blocks.end(), [](const ClientBlock& b) { return b.pixels; });
    if (error == GL_NO_ERROR && given && glass::gl::readsClientDataNow(ctx)) {
      try {
        for (const ClientBlock& b : blocks) {
          const std::vector<float> part =
              glass::gl::unpackRgbaBlock(b.pixels, b.width, b.rows, format, type, ctx.pixelStore.unpack);
          rgba->insert(rgba->end(), part.begin(), part.end());
        }
      } catch (const std::bad_alloc&) {
        error = GL_OUT_OF_MEMORY;
      }
    }
    const Groups groups = std::move(rgba);
    const int index = convolutionTarget(target);
    glass::gl::compileOrExecuteOn(ctx, [=](Context& c) {
      if (glass::gl::rejectInsideBeginEnd(c)) return;
      if (error != GL_NO_ERROR) return recordError(c, error);
      specifyFilter(c, index, internalFormat, width, height, *groups);
    });
  });
}

void copyFilter(GLenum target, GLenum expected, GLenum internalFormat, GLint x, GLint y,
                GLsizei width, GLsizei height) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    GLenum error = filterError(target, expected, internalFormat, width, height);
    if (error == GL_NO_ERROR && !glass::gl::readsColor(ctx.pixelTransfer.readBuffer)) {
      error = GL_INVALID_OPERATION;
    }
    if (error != GL_NO_ERROR) return recordError(ctx, error);
    glass::gl::finishQueuedDrawing(ctx);
    const glass::gl::ReadBufferSelection read(ctx);
    specifyFilter(ctx, convolutionTarget(target), internalFormat, width, height,
                  glass::gl::readColorBlock(ctx, x, y, width, height));
  });
}

bool isBorderMode(float mode) {
  return mode == float(GL_REDUCE) || mode == float(GL_CONSTANT_BORDER) || mode == float(GL_REPLICATE_BORDER);
}

// glConvolutionParameter: count is 1 for the scalar commands, which take only
// GL_CONVOLUTION_BORDER_MODE, and 4 for the vector ones.
void convolutionParameter(GLenum target, GLenum pname, const float* values, int count) {
  std::array<float, 4> v{};
  std::copy(values, values + count, v.begin());
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const int index = convolutionTarget(target);
    if (index < 0) return recordError(ctx, GL_INVALID_ENUM);
    ConvolutionParameters& p = ctx.imaging.mode.convolution[index];
    float* destination = nullptr;
    switch (pname) {
      case GL_CONVOLUTION_BORDER_MODE:
        if (!isBorderMode(v[0])) return recordError(ctx, GL_INVALID_ENUM);
        p.borderMode = static_cast<GLenum>(v[0]);
        return;
      case GL_CONVOLUTION_BORDER_COLOR: destination = p.borderColor; break;
      case GL_CONVOLUTION_FILTER_SCALE: destination = p.filterScale; break;
      case GL_CONVOLUTION_FILTER_BIAS: destination = p.filterBias; break;
      default: return recordError(ctx, GL_INVALID_ENUM);
    }
    if (count < 4) return recordError(ctx, GL_INVALID_ENUM);
    std::copy(v.begin(), v.end(), destination);
  });
}

// glGetConvolutionParameter's values, or false for a bad target or pname.
bool convolutionParameterValues(const Context& ctx, GLenum target, GLenum pname, std::vector<double>& out) {
  const int index = convolutionTarget(target);
  if (index < 0) return false;
  const ConvolutionParameters& p = ctx.imaging.mode.convolution[index];
  const ConvolutionFilter& f = ctx.imaging.filters[index];
  switch (pname) {
    case GL_CONVOLUTION_BORDER_MODE: out = {double(p.borderMode)}; return true;
    case GL_CONVOLUTION_BORDER_COLOR: out.assign(p.borderColor, p.borderColor + 4); return true;
    case GL_CONVOLUTION_FILTER_SCALE: out.assign(p.filterScale, p.filterScale + 4); return true;
    case GL_CONVOLUTION_FILTER_BIAS: out.assign(p.filterBias, p.filterBias + 4); return true;
    case GL_CONVOLUTION_FORMAT: out = {double(f.internalFormat)}; return true;
    case GL_CONVOLUTION_WIDTH: out = {double(f.width)}; return true;
    case GL_CONVOLUTION_HEIGHT: out = {double(f.height)}; return true;
    case GL_MAX_CONVOLUTION_WIDTH: out = {double(glass::gl::kMaxConvolutionSize)}; return true;
    case GL_MAX_CONVOLUTION_HEIGHT:
      out = {index == glass::gl::kConvolution1D ? 1.0 : double(glass::gl::kMaxConvolutionSize)};
      return true;
    default: return false;
  }
}

}  // namespace

extern "C" {

void glConvolutionFilter1D(GLenum target, GLenum internalformat, GLsizei width, GLenum format,
                           GLenum type, const GLvoid* image) {
  filterCommand(target, GL_CONVOLUTION_1D, internalformat, width, 1, format, type, {{image, width, 1}});
}

void glConvolutionFilter2D(GLenum target, GLenum internalformat, GLsizei width, GLsizei height,
                           GLenum format, GLenum type, const GLvoid* image) {
  filterCommand(target, GL_CONVOLUTION_2D, internalformat, width, height, format, type,
                {{image, width, height}});
}

void glSeparableFilter2D(GLenum target, GLenum internalformat, GLsizei width, GLsizei height,
                         GLenum format, GLenum type, const GLvoid* row, const GLvoid* column) {
  filterCommand(target, GL_SEPARABLE_2D, internalformat, width, height, format, type,
                {{row, width, 1}, {column, height, 1}});
}

void glCopyConvolutionFilter1D(GLenum target, GLenum internalformat, GLint x, GLint y, GLsizei width) {
  copyFilter(target, GL_CONVOLUTION_1D, internalformat, x, y, width, 1);
}

void glCopyConvolutionFilter2D(GLenum target, GLenum internalformat, GLint x, GLint y,
                               GLsizei width, GLsizei height) {
  copyFilter(target, GL_CONVOLUTION_2D, internalformat, x, y, width, height);
}

void glConvolutionParameterf(GLenum target, GLenum pname, GLfloat params) {
  convolutionParameter(target, pname, &params, 1);
}
void glConvolutionParameteri(GLenum target, GLenum pname, GLint params) {
  const float value = static_cast<float>(params);
  convolutionParameter(target, pname, &value, 1);
}
void glConvolutionParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (params) convolutionParameter(target, pname, params, pname == GL_CONVOLUTION_BORDER_MODE ? 1 : 4);
}
void glConvolutionParameteriv(GLenum target, GLenum pname, const GLint* params) {
  if (!params) return;
  const int count = pname == GL_CONVOLUTION_BORDER_MODE ? 1 : 4;
  float values[4] = {};
  for (int i = 0; i < count; ++i) {
    // A border colour given as integers is a colour (table 2.9: the full range maps to [-1, 1]);
    // scales, biases and the mode are numbers.
    values[i] = pname == GL_CONVOLUTION_BORDER_COLOR
                    ? static_cast<float>((2.0 * params[i] + 1.0) / 4294967295.0)
                    : static_cast<float>(params[i]);
  }
  convolutionParameter(target, pname, values, count);
}

void glGetConvolutionFilter(GLenum target, GLenum format, GLenum type, GLvoid* image) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const int index = convolutionTarget(target);
    const bool taken = index == glass::gl::kConvolution1D || index == glass::gl::kConvolution2D;
    if (const GLenum error = glass::gl::checkImagingQuery(taken, format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    const ConvolutionFilter& f = ctx.imaging.filters[index];
    if (image && f.width > 0 && f.height > 0) {
      glass::gl::packRgbaBlock(f.values.data(), f.width, f.height, format, type, ctx.pixelStore.pack, image);
    }
  });
}

void glGetSeparableFilter(GLenum target, GLenum format, GLenum type, GLvoid* row, GLvoid* column,
                          GLvoid*) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (const GLenum error = glass::gl::checkImagingQuery(target == GL_SEPARABLE_2D, format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    const ConvolutionFilter& f = ctx.imaging.filters[glass::gl::kSeparable2D];
    const glass::gl::PixelPacking& pack = ctx.pixelStore.pack;
    if (row && f.width > 0) glass::gl::packRgbaBlock(f.values.data(), f.width, 1, format, type, pack, row);
    if (column && f.height > 0) {
      glass::gl::packRgbaBlock(f.values.data() + static_cast<size_t>(f.width) * 4, f.height, 1, format,
                               type, pack, column);
    }
  });
}

void glGetConvolutionParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::answerParameterQuery(target, pname, params, convolutionParameterValues);
}
void glGetConvolutionParameteriv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::answerParameterQuery(target, pname, params, convolutionParameterValues);
}

}  // extern "C"
