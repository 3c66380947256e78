// Clearing a rectangle of the framebuffer (what glClear does, spec 4.2.3), kept apart from the GL
// state so that the tiled rasterizer can run it tile by tile, in order with the primitives.
#pragma once

#include <cstdint>

#include "glass/raster/framebuffer.h"
#include "glass/raster/vertex.h"

namespace glass::raster {

struct ClearRequest {
  Framebuffer* target = nullptr;
  PixelRect rect;  // the pixels to clear (the scissor box, or the whole framebuffer)
  bool clearColor = false;
  uint8_t color[4] = {0, 0, 0, 0};
  bool colorMask[4] = {true, true, true, true};  // which of R, G, B, A are written
  bool clearDepth = false;
  uint32_t depth = 0;
  bool clearStencil = false;
  uint8_t stencil = 0;
  uint8_t stencilWriteMask = 0xFF;  // which stencil bits are written

  bool clearsSomething() const { return !rect.empty() && (clearColor || clearDepth || clearStencil); }
};

// Clears the pixels of request.rect that lie inside `within` (a tile, or the whole framebuffer).
void clearFramebuffer(const ClearRequest& request, const PixelRect& within);

}  // namespace glass::raster
