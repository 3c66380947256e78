// glPixelTransfer, glPixelZoom, glPixelMap and glGetPixelMap (OpenGL 1.5 specification, sections
// 3.6.3, 3.6.5 and 6.1.3). glPixelTransfer, glPixelZoom and glPixelMap are compiled into display
// lists (glPixelMap with a copy of its values); glGetPixelMap executes at once.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/context.h"
#include "lists/command_recording.h"
#include "pixels/imaging_queries.h"
#include "vertex/attribute_conversion.h"

using glass::gl::Context;
using glass::gl::PixelTransferState;
using glass::gl::recordError;

namespace {

void pixelTransfer(GLenum pname, float value) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    PixelTransferState& t = ctx.pixelTransfer;
    switch (pname) {
      case GL_MAP_COLOR: t.mapColor = value != 0.0f; return;
      case GL_MAP_STENCIL: t.mapStencil = value != 0.0f; return;
      case GL_INDEX_SHIFT: t.indexShift = static_cast<int>(std::lround(value)); return;
      case GL_INDEX_OFFSET: t.indexOffset = static_cast<int>(std::lround(value)); return;
      case GL_RED_SCALE: t.scale[0] = value; return;
      case GL_GREEN_SCALE: t.scale[1] = value; return;
      case GL_BLUE_SCALE: t.scale[2] = value; return;
      case GL_ALPHA_SCALE: t.scale[3] = value; return;
      case GL_RED_BIAS: t.bias[0] = value; return;
      case GL_GREEN_BIAS: t.bias[1] = value; return;
      case GL_BLUE_BIAS: t.bias[2] = value; return;
      case GL_ALPHA_BIAS: t.bias[3] = value; return;
      case GL_DEPTH_SCALE: t.depthScale = value; return;
      case GL_DEPTH_BIAS: t.depthBias = value; return;
      default: break;
    }
    // The imaging subset's post-convolution and post-colour-matrix scales and biases.
    if (float* parameter = glass::gl::imagingTransferParameter(ctx.imaging, pname)) {
      *parameter = value;
    } else {
      recordError(ctx, GL_INVALID_ENUM);
    }
  });
}

// Spec 3.6.3: the table for `map` gets `values`, already converted to float. Colour values (maps
// other than I_TO_I and S_TO_S) are clamped to [0, 1].
void pixelMap(GLenum map, GLsizei size, std::vector<float> values) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!glass::gl::isPixelMapName(map)) return recordError(ctx, GL_INVALID_ENUM);
    if (size < 1 || size > glass::gl::kMaxPixelMapTable) return recordError(ctx, GL_INVALID_VALUE);
    if (glass::gl::isIndexInputMap(map) && (size & (size - 1)) != 0) {
      return recordError(ctx, GL_INVALID_VALUE);
    }
    if (static_cast<GLsizei>(values.size()) != size) return;  // no values were given
    std::vector<float> table = values;
    if (!glass::gl::isIndexOutputMap(map)) {
      for (float& v : table) v = std::clamp(v, 0.0f, 1.0f);
    }
    ctx.pixelTransfer.maps[map - GL_PIXEL_MAP_I_TO_I] = std::move(table);
  });
}

// The values of glPixelMapuiv / usv as floats: index maps take them as numbers, colour maps as
// normalized unsigned integers (table 2.9).
template <class T>
std::vector<float> pixelMapValues(GLenum map, GLsizei size, const T* values) {
  std::vector<float> out;
  if (!values || size < 1 || size > glass::gl::kMaxPixelMapTable) return out;
  out.resize(static_cast<size_t>(size));
  for (GLsizei i = 0; i < size; ++i) {
    out[i] = glass::gl::isIndexOutputMap(map) ? static_cast<float>(values[i])
                                              : glass::gl::normalizedToFloat(values[i]);
  }
  return out;
}

// glGetPixelMap: the map's values converted to T (index maps as numbers, colour maps as
// normalized unsigned integers, spec 6.1.3 and table 4.7).
template <class T>
void getPixelMap(GLenum map, T* values, double maxValue) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!glass::gl::isPixelMapName(map)) return recordError(ctx, GL_INVALID_ENUM);
    if (!values) return;
    const std::vector<float>& table = ctx.pixelTransfer.map(map);
    for (size_t i = 0; i < table.size(); ++i) {
      if (maxValue == 0.0) {
        values[i] = static_cast<T>(table[i]);
      } else if (glass::gl::isIndexOutputMap(map)) {
        values[i] = static_cast<T>(std::clamp(static_cast<double>(table[i]), 0.0, maxValue));
      } else {
        values[i] = static_cast<T>(std::nearbyint(static_cast<double>(table[i]) * maxValue));
      }
    }
  });
}

}  // namespace

extern "C" {

void glPixelTransferf(GLenum pname, GLfloat param) { pixelTransfer(pname, param); }
void glPixelTransferi(GLenum pname, GLint param) { pixelTransfer(pname, static_cast<float>(param)); }

void glPixelZoom(GLfloat xfactor, GLfloat yfactor) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    ctx.pixelTransfer.zoomX = xfactor;
    ctx.pixelTransfer.zoomY = yfactor;
  });
}

void glPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values) {
  std::vector<float> v;
  if (values && mapsize >= 1 && mapsize <= glass::gl::kMaxPixelMapTable) v.assign(values, values + mapsize);
  pixelMap(map, mapsize, std::move(v));
}
void glPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values) {
  pixelMap(map, mapsize, pixelMapValues(map, mapsize, values));
}
void glPixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values) {
  pixelMap(map, mapsize, pixelMapValues(map, mapsize, values));
}

void glGetPixelMapfv(GLenum map, GLfloat* values) { getPixelMap(map, values, 0.0); }
void glGetPixelMapuiv(GLenum map, GLuint* values) { getPixelMap(map, values, 4294967295.0); }
void glGetPixelMapusv(GLenum map, GLushort* values) { getPixelMap(map, values, 65535.0); }

}  // extern "C"
