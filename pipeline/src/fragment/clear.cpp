#include "fragment/clear.h"

#include <algorithm>

#include "accum/accumulation.h"
#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "fragment/color_conversion.h"
#include "glass/raster/depth_value.h"
#include "glass/raster/fragment.h"
#include "primitive/queued_drawing.h"
#include "teaching/teaching_view.h"

namespace glass::gl {

void clearBuffers(Context& ctx, GLbitfield mask) {
  // As in Mesa, glClear does nothing in selection and feedback modes, where nothing is drawn.
  if (ctx.renderMode.mode != GL_RENDER) return;
  finishQueuedDrawing(ctx);
  raster::Framebuffer& fb = ctx.framebuffer;
  const FragmentState& f = ctx.fragment;
  int x0 = 0, y0 = 0, x1 = fb.width(), y1 = fb.height();
  if (f.scissorTest) {
    x0 = std::max(x0, f.scissor.x);
    y0 = std::max(y0, f.scissor.y);
    x1 = static_cast<int>(std::min<long long>(x1, static_cast<long long>(f.scissor.x) + f.scissor.width));
    y1 = static_cast<int>(std::min<long long>(y1, static_cast<long long>(f.scissor.y) + f.scissor.height));
  }
  if (x0 >= x1 || y0 >= y1) return;

  if ((mask & GL_COLOR_BUFFER_BIT) && drawsColor(f.drawBuffer)) {
    restartTeachingFrame(ctx);
    uint8_t color[4];
    for (int c = 0; c < 4; ++c) color[c] = floatToColorByte(f.clearColor[c]);
    const bool all = f.colorMask[0] && f.colorMask[1] && f.colorMask[2] && f.colorMask[3];
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        uint8_t* pixel = fb.colorAt(x, y);
        for (int c = 0; c < 4; ++c) {
          if (all || f.colorMask[c]) pixel[c] = color[c];
        }
      }
    }
  }
  if ((mask & GL_DEPTH_BUFFER_BIT) && f.depthMask && ctx.buffers.depth) {
    const uint32_t depth = raster::depthValue(f.clearDepth);
    for (int y = y0; y < y1; ++y) std::fill(fb.depthAt(x0, y), fb.depthAt(x0, y) + (x1 - x0), depth);
  }
  if ((mask & GL_ACCUM_BUFFER_BIT) && ctx.buffers.accumulation) clearAccumulationBuffer(ctx, x0, y0, x1, y1);
  if ((mask & GL_STENCIL_BUFFER_BIT) && ctx.buffers.stencil) {
    const unsigned writeMask = f.stencilWriteMask & 0xFFu;
    const uint8_t value = static_cast<uint8_t>(f.clearStencil & 0xFF);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        uint8_t* s = fb.stencilAt(x, y);
        *s = static_cast<uint8_t>((*s & ~writeMask) | (value & writeMask));
      }
    }
  }
}

}  // namespace glass::gl
