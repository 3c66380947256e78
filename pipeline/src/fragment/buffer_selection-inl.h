// The template of buffer_selection.h.
#pragma once

#include "core/context.h"
#include "fragment/buffer_selection.h"
#include "primitive/queued_drawing.h"

namespace glass::gl {

template <typename WriteOne>
void forEachDrawnColorBuffer(Context& ctx, WriteOne writeOne) {
  if (!writesBothBuffers(ctx)) return writeOne();
  struct BackSelectedAtEnd {
    Context& ctx;
    ~BackSelectedAtEnd() {
      finishQueuedDrawing(ctx);
      ctx.framebuffer.selectColorBuffer(kBackColorBuffer);
    }
  };
  {
    BackSelectedAtEnd front{ctx};
    finishQueuedDrawing(ctx);
    ctx.framebuffer.selectColorBuffer(kFrontColorBuffer);
    writeOne();
  }
  writeOne();
}

}  // namespace glass::gl
