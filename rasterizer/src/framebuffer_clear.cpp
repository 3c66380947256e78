#include "glass/raster/framebuffer_clear.h"

#include <algorithm>
#include <cstring>

namespace glass::raster {

void clearFramebuffer(const ClearRequest& request, const PixelRect& within) {
  Framebuffer& fb = *request.target;
  const int x0 = std::max(request.rect.x0, within.x0), y0 = std::max(request.rect.y0, within.y0);
  const int x1 = std::min(request.rect.x1, within.x1), y1 = std::min(request.rect.y1, within.y1);
  if (x0 >= x1 || y0 >= y1) return;

  if (request.clearColor) {
    const bool* mask = request.colorMask;
    const bool all = mask[0] && mask[1] && mask[2] && mask[3];
    for (int y = y0; y < y1; ++y) {
      uint8_t* pixel = fb.colorAt(x0, y);
      if (all) {
        // The whole pixel at once: a row of identical 4-byte values.
        for (int x = x0; x < x1; ++x, pixel += 4) std::memcpy(pixel, request.color, 4);
        continue;
      }
      for (int x = x0; x < x1; ++x, pixel += 4)
        for (int c = 0; c < 4; ++c)
          if (mask[c]) pixel[c] = request.color[c];
    }
  }
  if (request.clearDepth) {
    for (int y = y0; y < y1; ++y) std::fill(fb.depthAt(x0, y), fb.depthAt(x1, y), request.depth);
  }
  if (request.clearStencil) {
    const uint8_t keep = static_cast<uint8_t>(~request.stencilWriteMask);
    const uint8_t value = static_cast<uint8_t>(request.stencil & request.stencilWriteMask);
    for (int y = y0; y < y1; ++y) {
      uint8_t* s = fb.stencilAt(x0, y);
      for (int x = x0; x < x1; ++x, ++s) *s = static_cast<uint8_t>((*s & keep) | value);
    }
  }
}

}  // namespace glass::raster
