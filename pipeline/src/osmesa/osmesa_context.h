// An OSMesa context: a GL context and the caller's buffer it is bound to.
//
// glass draws into the context's own framebuffer (RGBA8, 24-bit depth, 8-bit stencil; the tiled
// rasterizer writes it from several threads until the queued drawing is finished) and copies
// between it and the caller's buffer at the points where OSMesa defines the buffer's contents:
//   - OSMesaMakeCurrent loads the buffer into the colour buffer (the buffer is the colour buffer,
//     as in Mesa's original OSMesa, where drawing happened in place);
//   - OSMesaPixelStore changing the layout loads it again, laid out the new way;
//   - glFlush, glFinish, OSMesaGetColorBuffer, and OSMesaMakeCurrent to another buffer or to
//     none store the colour buffer into it.
// So at each of these points the buffer holds what drawing in place would have left there.
// With GLASS_VIEW set, what is stored is the teaching view's picture instead (docs/teaching.md);
// a later OSMesaMakeCurrent then loads that picture as the colour buffer, as for any buffer.
#pragma once

#include <GL/osmesa.h>

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/context.h"
#include "osmesa/buffer_layout.h"

struct osmesa_context {
  osmesa_context(GLenum bufferFormat);

  glass::gl::Context gl;
  GLenum format;

  // Set by OSMesaMakeCurrent; buffer is null until the first binding.
  void* buffer = nullptr;
  glass::osmesa::BufferLayout layout;
  int rowLengthSetting = 0;  // OSMESA_ROW_LENGTH as set: 0 means the buffer's width
  bool yUp = true;           // OSMESA_Y_UP

  // OSMesaGetDepthBuffer's copy, made on first request and refreshed at glFlush and glFinish.
  std::vector<uint32_t> depthCopy;

  // Whether the context is current on some thread: a context is current on one thread at most.
  std::atomic<bool> current{false};
};

namespace glass::osmesa {

// After finishing the queued drawing: framebuffer -> the caller's buffer, and the depth copy if
// there is one. Nothing before the first binding.
void storeBuffers(osmesa_context& ctx);
// After finishing the queued drawing: depth and stencil -> depthCopy (of the framebuffer's size).
void copyDepthBuffer(osmesa_context& ctx);

}  // namespace glass::osmesa
