#include "core/ancillary_buffers.h"

#include "core/context.h"
#include "fragment/color_conversion.h"
#include "glass/raster/framebuffer.h"
#include "primitive/queued_drawing.h"

namespace glass::gl {

bool hasBufferToRead(const Context& ctx, GLenum formatOrType) {
  switch (formatOrType) {
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH: return ctx.buffers.depth;
    case GL_STENCIL_INDEX:
    case GL_STENCIL: return ctx.buffers.stencil;
    default: return true;
  }
}

bool depthTestActive(const Context& ctx) { return ctx.fragment.depthTest && ctx.buffers.depth; }

bool stencilTestActive(const Context& ctx) { return ctx.fragment.stencilTest && ctx.buffers.stencil; }

uint32_t storedAlphaWord(const Context& ctx) { return ctx.buffers.colorAlpha ? 0u : packColorBytes(0, 0, 0, 255); }

void fillColorAlpha(raster::Framebuffer& framebuffer) {
  const bool both = framebuffer.hasSecondColorBuffer();  // a double-buffered framebuffer's front too
  for (int y = 0; y < framebuffer.height(); ++y) {
    uint8_t* pixel = framebuffer.colorAt(0, y);
    uint8_t* other = both ? framebuffer.otherColorAt(0, y) : nullptr;
    for (int x = 0; x < framebuffer.width(); ++x) {
      pixel[4 * x + 3] = 255;
      if (other) other[4 * x + 3] = 255;
    }
  }
}

void setAlphaBitplanes(Context& ctx, bool alpha) {
  finishQueuedDrawing(ctx);
  ctx.buffers.colorAlpha = alpha;
  if (!alpha) fillColorAlpha(ctx.framebuffer);
}

}  // namespace glass::gl
