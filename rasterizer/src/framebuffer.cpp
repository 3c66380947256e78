// The framebuffer's storage. Contents start as GL leaves them before the first glClear: the
// specification calls them undefined; glass starts from black, depth 1.0 (the far plane) and
// stencil 0, so that a program that forgets to clear still gets a deterministic picture.
#include "glass/raster/framebuffer.h"

#include <cstring>
#include <stdexcept>
#include <utility>

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

void Framebuffer::addSecondColorBuffer() {
  if (otherColor_) return;
  const size_t bytes = pixelCount(width_, height_) * 4;
  otherColor_ = std::make_unique<CacheAlignedPixels<uint8_t>>(bytes, 0);
  std::memcpy(&(*otherColor_)[0], &color_[0], bytes);
}

void Framebuffer::removeSecondColorBuffer() {
  selectColorBuffer(0);
  otherColor_.reset();
}

void Framebuffer::selectColorBuffer(int index) {
  if (index == selected_ || !otherColor_) return;
  std::swap(color_, *otherColor_);
  selected_ = index;
}

}  // namespace glass::raster
