// Rasterization state (spec 3.3-3.5): point size, line width and stipple, shade model, polygon
// mode, culling, front face, polygon offset. All compiled into display lists; none allowed
// between glBegin and glEnd.
#include <GL/gl.h>

#include <algorithm>

#include "core/context.h"
#include "lists/command_recording.h"

using glass::gl::Context;
using glass::gl::recordError;
using glass::gl::RasterState;

namespace {

template <class Update>
void rasterCommand(Update update) {
  glass::gl::compileOrExecute([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    update(ctx, ctx.raster);
  });
}

bool isFace(GLenum face) { return face == GL_FRONT || face == GL_BACK || face == GL_FRONT_AND_BACK; }

}  // namespace

extern "C" {

void glPointSize(GLfloat size) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (!(size > 0.0f)) return recordError(ctx, GL_INVALID_VALUE);
    r.pointSize = size;
  });
}

void glLineWidth(GLfloat width) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (!(width > 0.0f)) return recordError(ctx, GL_INVALID_VALUE);
    r.lineWidth = width;
  });
}

void glLineStipple(GLint factor, GLushort pattern) {
  rasterCommand([=](Context&, RasterState& r) {
    r.lineStippleFactor = std::clamp(factor, 1, 256);  // spec 3.4.2: clamped to [1, 256]
    r.lineStipplePattern = pattern;
  });
}

void glShadeModel(GLenum mode) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (mode != GL_FLAT && mode != GL_SMOOTH && mode != GL_PHONG_WIN) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    r.shadeModel = mode;
  });
}

void glPolygonMode(GLenum face, GLenum mode) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (!isFace(face) || (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)) {
      return recordError(ctx, GL_INVALID_ENUM);
    }
    if (face != GL_BACK) r.polygonModeFront = mode;
    if (face != GL_FRONT) r.polygonModeBack = mode;
  });
}

void glCullFace(GLenum mode) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (!isFace(mode)) return recordError(ctx, GL_INVALID_ENUM);
    r.cullFaceMode = mode;
  });
}

void glFrontFace(GLenum mode) {
  rasterCommand([=](Context& ctx, RasterState& r) {
    if (mode != GL_CW && mode != GL_CCW) return recordError(ctx, GL_INVALID_ENUM);
    r.frontFace = mode;
  });
}

void glPolygonOffset(GLfloat factor, GLfloat units) {
  rasterCommand([=](Context&, RasterState& r) {
    r.polygonOffsetFactor = factor;
    r.polygonOffsetUnits = units;
  });
}

}  // extern "C"
