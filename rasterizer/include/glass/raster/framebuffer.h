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

  // A double-buffered framebuffer (a GLUT_DOUBLE window's) has a second colour buffer of the
  // same size, which starts as a copy of the first. colorAt addresses the selected one (buffer 0
  // until selectColorBuffer chooses another) and otherColorAt the other. Selecting costs nothing
  // (the pixels stay where they are); nothing may be drawing into the framebuffer meanwhile.
  void addSecondColorBuffer();
  void removeSecondColorBuffer();  // buffer 0 is kept, and selected
  bool hasSecondColorBuffer() const { return otherColor_ != nullptr; }
  void selectColorBuffer(int index);  // 0, or 1 when there is a second buffer
  int selectedColorBuffer() const { return selected_; }
  // Buffer `index`'s pixels (as colorAt(0, 0) of it), whichever is selected.
  const uint8_t* colorBufferPixels(int index) const {
    return index == selected_ ? &color_[0] : &(*otherColor_)[0];
  }
  uint8_t* colorBufferPixels(int index) { return index == selected_ ? &color_[0] : &(*otherColor_)[0]; }
  uint8_t* otherColorAt(int x, int y) { return &(*otherColor_)[(static_cast<size_t>(y) * width_ + x) * 4]; }
  const uint8_t* otherColorAt(int x, int y) const {
    return &(*otherColor_)[(static_cast<size_t>(y) * width_ + x) * 4];
  }

 private:
  int width_, height_;
  CacheAlignedPixels<uint8_t> color_;
  std::unique_ptr<CacheAlignedPixels<uint8_t>> otherColor_;
  int selected_ = 0;  // which buffer color_ holds
  CacheAlignedPixels<uint32_t> depth_;
  CacheAlignedPixels<uint8_t> stencil_;
};

}  // namespace glass::raster
