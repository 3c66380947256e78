// The framebuffer's storage. Contents start as GL leaves them before the first glClear: the
// specification calls them undefined; glass starts from black, depth 1.0 (the far plane) and
// stencil 0, so that a program that forgets to clear still gets a deterministic picture.
#include "glass/raster/framebuffer.h"

#include <stdexcept>

#include "glass/raster/fragment.h"

namespace glass::raster {

namespace {

size_t pixelCount(int width, int height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("framebuffer size must be positive");
  return static_cast<size_t>(width) * static_cast<size_t>(height);
}

}  // namespace

Framebuffer::Framebuffer(int width, int height)
    : width_(width),
      height_(height),
      color_(pixelCount(width, height) * 4, 0),
      depth_(pixelCount(width, height), kDepthMax),
      stencil_(pixelCount(width, height), 0) {}

}  // namespace glass::raster
