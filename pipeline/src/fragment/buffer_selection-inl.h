// The template of buffer_selection.h.
#pragma once

#include "core/context.h"
#include "fragment/buffer_selection.h"

namespace glass::gl {

template <typename WriteOne>
void forEachDrawnColorBuffer(Context& ctx, WriteOne writeOne) {
  if (!writesBothBuffers(ctx)) return writeOne();
  struct BackSelectedAtEnd {
    Context& ctx;
    ~BackSelectedAtEnd() { selectColorBuffer(ctx, kBackColorBuffer); }
  };
  {
    BackSelectedAtEnd front{ctx};
    selectColorBuffer(ctx, kFrontColorBuffer);
    writeOne();
  }
  writeOne();
}

}  // namespace glass::gl
