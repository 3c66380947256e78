#include "fragment/clear.h"

#include <algorithm>

#include "accum/accumulation.h"
#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "fragment/color_conversion.h"
#include "glass/raster/depth_value.h"
#include "glass/raster/fragment.h"
#include "glass/raster/framebuffer_clear.h"
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

  // Colour, depth and stencil are cleared by the tiles, in order with the draws (queueClear),
  // or here when there is no draw pipeline yet.
  raster::ClearRequest request;
  request.target = &fb;
  request.rect = raster::PixelRect{x0, y0, x1, y1};
  if ((mask & GL_COLOR_BUFFER_BIT) && drawsColor(f.drawBuffer)) {
    restartTeachingFrame(ctx);
    request.clearColor = true;
    for (int c = 0; c < 4; ++c) {
      request.color[c] = floatToColorByte(f.clearColor[c]);
      request.colorMask[c] = f.colorMask[c];
    }
    // Without alpha bitplanes the stored alpha is 255 and stays so; writing it whatever the mask
    // keeps a clear of red, green and blue a clear of whole pixels.
    if (!ctx.buffers.colorAlpha) {
      request.color[3] = 255;
      request.colorMask[3] = true;
    }
  }
  if ((mask & GL_DEPTH_BUFFER_BIT) && f.depthMask && ctx.buffers.depth) {
    request.clearDepth = true;
    request.depth = raster::depthValue(f.clearDepth);
  }
  if ((mask & GL_STENCIL_BUFFER_BIT) && ctx.buffers.stencil) {
    request.clearStencil = true;
    request.stencil = static_cast<uint8_t>(f.clearStencil & 0xFF);
    request.stencilWriteMask = static_cast<uint8_t>(f.stencilWriteMask & 0xFFu);
  }
  const auto clearOne = [&](const raster::ClearRequest& one) {
    if (one.clearsSomething() && !queueClear(ctx, one)) raster::clearFramebuffer(one, one.rect);
  };
  if (request.clearColor && writesBothBuffers(ctx)) {
    // GL_FRONT_AND_BACK: the front buffer's colour first, then the back's with the rest.
    raster::ClearRequest colorOnly = request;
    colorOnly.clearDepth = colorOnly.clearStencil = false;
    bool front = true;
    forEachDrawnColorBuffer(ctx, [&] {
      clearOne(front ? colorOnly : request);
      front = false;
    });
  } else {
    clearOne(request);
  }
  if ((mask & GL_ACCUM_BUFFER_BIT) && ctx.buffers.accumulation) clearAccumulationBuffer(ctx, x0, y0, x1, y1);
}

}  // namespace glass::gl
