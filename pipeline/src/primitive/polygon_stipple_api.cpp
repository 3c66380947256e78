// glPolygonStipple and glGetPolygonStipple (OpenGL 1.5 specification, sections 3.5.2 and 6.1.6).
// The pattern is unpacked like a 32 x 32 glBitmap image with the GL_UNPACK_* parameters (and, in
// a display list, when the list is compiled); glGetPolygonStipple packs it with the GL_PACK_*
// parameters and is not compiled.
#include <GL/gl.h>

#include <cstdint>

#include "core/context.h"
#include "lists/command_recording.h"
#include "texture/client_pixels.h"

using glass::gl::Context;
using glass::gl::PolygonStipplePattern;

extern "C" {

void glPolygonStipple(const GLubyte* mask) {
  glass::gl::executeNow([=](Context& ctx) {
    if (!mask) return;
    PolygonStipplePattern pattern;
    int32_t bits[32];
    for (int y = 0; y < 32; ++y) {
      glass::gl::unpackIndexRow(mask, 32, y, GL_BITMAP, ctx.pixelStore.unpack, bits);
      uint32_t row = 0;
      for (int x = 0; x < 32; ++x) row |= static_cast<uint32_t>(bits[x] & 1) << x;
      pattern.rows[y] = row;
    }
    glass::gl::compileOrExecuteOn(ctx, [pattern](Context& c) {
      if (glass::gl::rejectInsideBeginEnd(c)) return;
      c.raster.polygonStipplePattern = pattern;
    });
  });
}

void glGetPolygonStipple(GLubyte* mask) {
  glass::gl::executeNow([=](Context& ctx) {
    if (glass::gl::rejectInsideBeginEnd(ctx)) return;
    if (!mask) return;
    uint32_t bits[32];
    for (int y = 0; y < 32; ++y) {
      const uint32_t row = ctx.raster.polygonStipplePattern.rows[y];
      for (int x = 0; x < 32; ++x) bits[x] = (row >> x) & 1u;
      glass::gl::packIndexSpan(bits, 32, 32, 0, y, GL_BITMAP, ctx.pixelStore.pack, mask);
    }
  });
}

}  // extern "C"
