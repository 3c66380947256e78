// The framebuffer: RGBA8 colour, 24-bit depth, 8-bit stencil. Row 0 is the bottom row, as in GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace glass::raster {

// The pixels of one buffer, starting on a cache line. Threads draw neighbouring 64 x 64 tiles at
// the same time, and a tile's rows begin at multiples of 64 pixels: with the rows' start on a
// cache line (and a width of a multiple of 16 pixels), no cache line holds pixels of two tiles,
// so two threads never write the same line. (From malloc, a large buffer starts 16 bytes into a
// page, and the lines at the tiles' left and right edges held pixels of both neighbours.)
template <typename T>
class CacheAlignedPixels {
 public:
  static constexpr std::align_val_t kAlignment{64};
  CacheAlignedPixels(size_t count, T value)
      : data_(static_cast<T*>(::operator new(count * sizeof(T), kAlignment))) {
    std::uninitialized_fill_n(data_.get(), count, value);
  }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }

 private:
  struct Release {
    void operator()(T* p) const { ::operator delete(p, kAlignment); }
  };
  std::unique_ptr<T[], Release> data_;
};

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
  CacheAlignedPixels<uint8_t> color_;
  CacheAlignedPixels<uint32_t> depth_;
  CacheAlignedPixels<uint8_t> stencil_;
};

}  // namespace glass::raster
