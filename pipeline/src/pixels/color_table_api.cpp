// The colour table commands of the imaging subset (OpenGL 1.4 specification, sections 3.6.3
// "Color Table Specification" and 6.1.7 "Color Table Query"; GL_ARB_imaging): glColorTable,
// glColorSubTable, glCopyColorTable, glCopyColorSubTable, glColorTableParameter and their
// queries.
//
// Display lists (spec 5.4): the specification commands are compiled, with their client data
// unpacked when compiled; glColorTable with a proxy target executes at once, as do the queries.
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

using glass::gl::ColorTable;
using glass::gl::Context;
using glass::gl::recordError;

namespace {

// A colour table target: its stage and whether it names the proxy.
struct TableTarget {
  int stage = -1;
  bool proxy = false;
  bool valid() const { return stage >= 0; }
};

TableTarget tableTarget(GLenum target) {
  switch (target) {
    case GL_COLOR_TABLE: return {glass::gl::kColorTableStage, false};
    case GL_POST_CONVOLUTION_COLOR_TABLE: return {glass::gl::kPostConvolutionStage, false};
    case GL_POST_COLOR_MATRIX_COLOR_TABLE: return {glass::gl::kPostColorMatrixStage, false};
    case GL_PROXY_COLOR_TABLE: return {glass::gl::kColorTableStage, true};
    case GL_PROXY_POST_CONVOLUTION_COLOR_TABLE: return {glass::gl::kPostConvolutionStage, true};
    case GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE: return {glass::gl::kPostColorMatrixStage, true};
    default: return {};
  }
}

// A target the commands other than glColorTable and the parameter queries take: no proxy.
TableTarget realTableTarget(GLenum target) {
  const TableTarget t = tableTarget(target);
  return t.proxy ? TableTarget{} : t;
}

using Entries = std::shared_ptr<const std::vector<float>>;

// Spec 3.6.3: each entry's components are scaled by GL_COLOR_TABLE_SCALE, biased by
// GL_COLOR_TABLE_BIAS and clamped to [0, 1], then kept as the internal format says.
void storeEntries(const Context& ctx, int stage, ColorTable& table, int first, const float* rgba,
                  int count) {
  const float* scale = ctx.imaging.mode.colorTableScale[stage];
  const float* bias = ctx.imaging.mode.colorTableBias[stage];
  for (int i = 0; i < count; ++i) {
    float* entry = &table.entries[static_cast<size_t>(first + i) * 4];
    for (int k = 0; k < 4; ++k) entry[k] = std::clamp(rgba[i * 4 + k] * scale[k] + bias[k], 0.0f, 1.0f);
    glass::gl::keepBaseComponents(table.base, entry);
  }
}

// glColorTable's and glCopyColorTable's work once the arguments passed their checks; `rgba`
// holds width groups, or is empty when no data was given (the entries are then 0).
void specifyTable(Context& ctx, TableTarget t, GLenum internalFormat, int width, const std::vector<float>& rgba) {
  ColorTable& table = t.proxy ? ctx.imaging.proxyTables[t.stage] : ctx.imaging.tables[t.stage];
  if (width > glass::gl::kMaxColorTableWidth) {
    // Too large: a proxy says so with a zero width and format; a real table is an error.
    if (!t.proxy) return recordError(ctx, GL_TABLE_TOO_LARGE);
    table = ColorTable{};
    table.internalFormat = 0;
    return;
  }
  ColorTable specified;
  specified.internalFormat = internalFormat;
  glass::gl::imagingBaseFormat(internalFormat, &specified.base);
  specified.width = width;
  if (!t.proxy) {
    specified.entries.assign(static_cast<size_t>(width) * 4, 0.0f);
    if (!rgba.empty()) storeEntries(ctx, t.stage, specified, 0, rgba.data(), width);
  }
  table = std::move(specified);
}

// Spec 3.6.3: a width that is neither zero nor a power of two is GL_INVALID_VALUE.
bool isTableWidth(GLsizei width) { return width >= 0 && (width & (width - 1)) == 0; }

GLenum colorTableError(TableTarget t, GLenum internalFormat, GLsizei width) {
  if (!t.valid() || !glass::gl::isColorTableFormat(internalFormat)) return GL_INVALID_ENUM;
  return isTableWidth(width) ? GL_NO_ERROR : GL_INVALID_VALUE;
}

// Runs a command compiled into display lists, or at once for a proxy target.
template <class Command>
void compileUnlessProxy(Context& ctx, bool proxy, Command command) {
  if (proxy) {
    command(ctx);
  } else {
    glass::gl::compileOrExecuteOn(ctx, command);
  }
}

// A glCopy* command needs a colour read buffer: none after glReadBuffer(GL_NONE).
GLenum copySourceError(const Context& ctx) {
  return glass::gl::readsColor(ctx.pixelTransfer.readBuffer) ? GL_NO_ERROR : GL_INVALID_OPERATION;
}

void subTable(Context& ctx, TableTarget t, GLsizei start, GLsizei count, const std::vector<float>& rgba) {
  ColorTable& table = ctx.imaging.tables[t.stage];
  if (start < 0 || count < 0 || static_cast<long long>(start) + count > table.width) {
    return recordError(ctx, GL_INVALID_VALUE);
  }
  if (!rgba.empty()) storeEntries(ctx, t.stage, table, start, rgba.data(), count);
}

void tableParameter(GLenum target, GLenum pname, const float values[4]) {
  const std::array<float, 4> v{values[0], values[1], values[2], values[3]};
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const TableTarget t = realTableTarget(target);
    if (!t.valid()) return recordError(ctx, GL_INVALID_ENUM);
    float* destination = pname == GL_COLOR_TABLE_SCALE  ? ctx.imaging.mode.colorTableScale[t.stage]
                         : pname == GL_COLOR_TABLE_BIAS ? ctx.imaging.mode.colorTableBias[t.stage]
                                                        : nullptr;
    if (!destination) return recordError(ctx, GL_INVALID_ENUM);
    std::copy(v.begin(), v.end(), destination);
  });
}

// glGetColorTableParameter's values, or false for a bad target or pname.
bool tableParameterValues(const Context& ctx, GLenum target, GLenum pname, std::vector<double>& out) {
  const TableTarget t = tableTarget(target);
  if (!t.valid()) return false;
  const ColorTable& table = t.proxy ? ctx.imaging.proxyTables[t.stage] : ctx.imaging.tables[t.stage];
  switch (pname) {
    case GL_COLOR_TABLE_SCALE:
    case GL_COLOR_TABLE_BIAS: {
      if (t.proxy) return false;
      const float* v = pname == GL_COLOR_TABLE_SCALE ? ctx.imaging.mode.colorTableScale[t.stage]
                                                     : ctx.imaging.mode.colorTableBias[t.stage];
      out.assign(v, v + 4);
      return true;
    }
    case GL_COLOR_TABLE_FORMAT: out = {double(table.internalFormat)}; return true;
    case GL_COLOR_TABLE_WIDTH: out = {double(table.width)}; return true;
    case GL_COLOR_TABLE_RED_SIZE:
    case GL_COLOR_TABLE_GREEN_SIZE:
    case GL_COLOR_TABLE_BLUE_SIZE:
    case GL_COLOR_TABLE_ALPHA_SIZE:
    case GL_COLOR_TABLE_LUMINANCE_SIZE:
    case GL_COLOR_TABLE_INTENSITY_SIZE:
      out = {table.width == 0 ? 0.0
                              : double(glass::gl::imagingComponentBits(
                                    table.base, static_cast<int>(pname - GL_COLOR_TABLE_RED_SIZE)))};
      return true;
    default: return false;
  }
}

}  // namespace

extern "C" {

void glColorTable(GLenum target, GLenum internalformat, GLsizei width, GLenum format, GLenum type,
                  const GLvoid* table) {
  glass::gl::executeNow([=](Context& ctx) {
    const TableTarget t = tableTarget(target);
    GLenum error = colorTableError(t, internalformat, width);
    if (error == GL_NO_ERROR) error = glass::gl::checkImagingFormatAndType(format, type);
    Entries rgba = std::make_shared<std::vector<float>>();
    const bool reads = error == GL_NO_ERROR && !t.proxy && table != nullptr &&
                       width <= glass::gl::kMaxColorTableWidth && glass::gl::readsClientDataNow(ctx);
    if (reads) {
      try {
        rgba = std::make_shared<const std::vector<float>>(
            glass::gl::unpackRgbaBlock(table, width, 1, format, type, ctx.pixelStore.unpack));
      } catch (const std::bad_alloc&) {
        error = GL_OUT_OF_MEMORY;
      }
    }
    compileUnlessProxy(ctx, t.proxy, [=](Context& c) {
      if (glass::gl::rejectInsideBeginEnd(c)) return;
      if (error != GL_NO_ERROR) return recordError(c, error);
      specifyTable(c, t, internalformat, width, *rgba);
    });
  });
}

void glColorSubTable(GLenum target, GLsizei start, GLsizei count, GLenum format, GLenum type,
                     const GLvoid* data) {
  glass::gl::executeNow([=](Context& ctx) {
    const TableTarget t = realTableTarget(target);
    GLenum error = t.valid() ? glass::gl::checkImagingFormatAndType(format, type) : GL_INVALID_ENUM;
    if (error == GL_NO_ERROR && count < 0) error = GL_INVALID_VALUE;
    Entries rgba = std::make_shared<std::vector<float>>();
    if (error == GL_NO_ERROR && data != nullptr && count <= glass::gl::kMaxColorTableWidth &&
        glass::gl::readsClientDataNow(ctx)) {
      try {
        rgba = std::make_shared<const std::vector<float>>(
            glass::gl::unpackRgbaBlock(data, count, 1, format, type, ctx.pixelStore.unpack));
      } catch (const std::bad_alloc&) {
        error = GL_OUT_OF_MEMORY;
      }
    }
    glass::gl::compileOrExecuteOn(ctx, [=](Context& c) {
      if (glass::gl::rejectInsideBeginEnd(c)) return;
      if (error != GL_NO_ERROR) return recordError(c, error);
      subTable(c, t, start, count, *rgba);
    });
  });
}

void glCopyColorTable(GLenum target, GLenum internalformat, GLint x, GLint y, GLsizei width) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const TableTarget t = realTableTarget(target);
    GLenum error = colorTableError(t, internalformat, width);
    if (error == GL_NO_ERROR) error = copySourceError(ctx);
    if (error != GL_NO_ERROR) return recordError(ctx, error);
    if (width > glass::gl::kMaxColorTableWidth) return recordError(ctx, GL_TABLE_TOO_LARGE);
    glass::gl::finishQueuedDrawing(ctx);
    const glass::gl::ReadBufferSelection read(ctx);
    specifyTable(ctx, t, internalformat, width, glass::gl::readColorBlock(ctx, x, y, width, 1));
  });
}

void glCopyColorSubTable(GLenum target, GLsizei start, GLint x, GLint y, GLsizei width) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const TableTarget t = realTableTarget(target);
    if (!t.valid()) return recordError(ctx, GL_INVALID_ENUM);
    if (width < 0 || start < 0 || static_cast<long long>(start) + width > ctx.imaging.tables[t.stage].width) {
      return recordError(ctx, GL_INVALID_VALUE);
    }
    if (const GLenum error = copySourceError(ctx); error != GL_NO_ERROR) return recordError(ctx, error);
    glass::gl::finishQueuedDrawing(ctx);
    const glass::gl::ReadBufferSelection read(ctx);
    subTable(ctx, t, start, width, glass::gl::readColorBlock(ctx, x, y, width, 1));
  });
}

void glColorTableParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (params) tableParameter(target, pname, params);
}

void glColorTableParameteriv(GLenum target, GLenum pname, const GLint* params) {
  if (!params) return;
  const float values[4] = {float(params[0]), float(params[1]), float(params[2]), float(params[3])};
  tableParameter(target, pname, values);
}

void glGetColorTable(GLenum target, GLenum format, GLenum type, GLvoid* table) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    const TableTarget t = realTableTarget(target);
    if (const GLenum error = glass::gl::checkImagingQuery(t.valid(), format, type); error != GL_NO_ERROR) {
      return recordError(ctx, error);
    }
    const ColorTable& stored = ctx.imaging.tables[t.stage];
    if (table && stored.width > 0) {
      glass::gl::packRgbaBlock(stored.entries.data(), stored.width, 1, format, type, ctx.pixelStore.pack, table);
    }
  });
}

void glGetColorTableParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  glass::gl::answerParameterQuery(target, pname, params, tableParameterValues);
}
void glGetColorTableParameteriv(GLenum target, GLenum pname, GLint* params) {
  glass::gl::answerParameterQuery(target, pname, params, tableParameterValues);
}

}  // extern "C"
