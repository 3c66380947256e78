// The framebuffer: RGBA8 colour, 24-bit depth, 8-bit stencil. Row 0 is the bottom row, as in GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glass::raster {

class Framebuffer {
 public:
  // Throws std::bad_alloc when memory runs out; sizes must be positive.
  Framebuffer(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Colour: 4 bytes per pixel in the order R, G, B, A.
  uint8_t* colorAt(int x, int y) { return &color_[(static_cast<size_t>(y) * width_ + x) * 4]; }
  const uint8_t* colorAt(int x, int y) const { return &color_[(static_cast<size_t>(y) * width_ + x) * 4]; }
  uint32_t* depthAt(int x, int y) { return &depth_[static_cast<size_t>(y) * width_ + x]; }
  const uint32_t* depthAt(int x, int y) const { return &depth_[static_cast<size_t>(y) * width_ + x]; }
  uint8_t* stencilAt(int x, int y) { return &stencil_[static_cast<size_t>(y) * width_ + x]; }
  const uint8_t* stencilAt(int x, int y) const { return &stencil_[static_cast<size_t>(y) * width_ + x]; }

 private:
  int width_, height_;
  std::vector<uint8_t> color_;
  std::vector<uint32_t> depth_;
  std::vector<uint8_t> stencil_;
};

}  // namespace glass::raster
