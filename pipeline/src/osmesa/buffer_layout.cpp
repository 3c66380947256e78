#include "osmesa/buffer_layout.h"

#include <GL/osmesa.h>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace glass::osmesa {
namespace {

// The framebuffer component (0 red, 1 green, 2 blue, 3 alpha) stored at each position of a
// pixel, for the formats with one value per component.
struct ComponentOrder {
  int count;
  int component[4];
};

ComponentOrder componentOrder(GLenum format) {
  switch (format) {
    case OSMESA_BGRA: return {4, {2, 1, 0, 3}};
    case OSMESA_ARGB: return {4, {3, 0, 1, 2}};
    case OSMESA_RGB: return {3, {0, 1, 2, 0}};
    case OSMESA_BGR: return {3, {2, 1, 0, 0}};
    default: return {4, {0, 1, 2, 3}};  // OSMESA_RGBA
  }
}

// Unsigned normalized values of n bits from and to 8 bits, rounded to nearest (c * max / 255).
uint32_t widen(uint8_t c, uint32_t max) { return (c * max + 127) / 255; }
uint8_t narrow(uint32_t v, uint32_t max) { return static_cast<uint8_t>((v * 255 + max / 2) / max); }

uint8_t narrowFloat(float f) {
  if (!(f > 0.0f)) return 0;  // also NaN
  if (f >= 1.0f) return 255;
  return static_cast<uint8_t>(std::lround(f * 255.0f));
}

// The address of the buffer's pixel (x, row), row 0 being the framebuffer's bottom row.
std::size_t pixelOffset(const BufferLayout& layout, int x, int row) {
  const int bufferRow = layout.yUp ? row : layout.height - 1 - row;
  return (static_cast<std::size_t>(bufferRow) * static_cast<std::size_t>(layout.rowLength) +
          static_cast<std::size_t>(x)) *
         bytesPerPixel(layout.format, layout.type);
}

template <typename Value>
void storeComponents(const uint8_t* rgba, Value* out, const ComponentOrder& order) {
  for (int i = 0; i < order.count; ++i) {
    const uint8_t c = rgba[order.component[i]];
    if constexpr (sizeof(Value) == 1) {
      out[i] = c;
    } else if constexpr (sizeof(Value) == 2) {
      out[i] = static_cast<Value>(c * 257u);
    } else {
      out[i] = static_cast<float>(c) / 255.0f;
    }
  }
}

template <typename Value>
void loadComponents(const Value* in, uint8_t* rgba, const ComponentOrder& order) {
  rgba[3] = 255;
  for (int i = 0; i < order.count; ++i) {
    uint8_t& c = rgba[order.component[i]];
    if constexpr (sizeof(Value) == 1) {
      c = in[i];
    } else if constexpr (sizeof(Value) == 2) {
      c = narrow(in[i], 65535);
    } else {
      c = narrowFloat(in[i]);
    }
  }
}

}  // namespace

bool isBufferFormat(GLenum format) {
  switch (format) {
    case OSMESA_RGBA:
    case OSMESA_BGRA:
    case OSMESA_ARGB:
    case OSMESA_RGB:
    case OSMESA_BGR:
    case OSMESA_RGB_565: return true;
    default: return false;
  }
}

bool formatHasAlpha(GLenum format) {
  return format == OSMESA_RGBA || format == OSMESA_BGRA || format == OSMESA_ARGB;
}

bool acceptsType(GLenum format, GLenum type) {
  if (!isBufferFormat(format)) return false;
  if (format == OSMESA_RGB_565) return type == GL_UNSIGNED_SHORT_5_6_5;
  return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_FLOAT;
}

std::size_t bytesPerPixel(GLenum format, GLenum type) {
  if (format == OSMESA_RGB_565) return 2;
  const std::size_t components = static_cast<std::size_t>(componentOrder(format).count);
  switch (type) {
    case GL_UNSIGNED_SHORT: return components * 2;
    case GL_FLOAT: return components * 4;
    default: return components;
  }
}

void storeColorBuffer(const uint8_t* picture, const BufferLayout& layout, void* buffer) {
  auto* bytes = static_cast<unsigned char*>(buffer);
  const ComponentOrder order = componentOrder(layout.format);
  const std::size_t pixelBytes = bytesPerPixel(layout.format, layout.type);
  for (int row = 0; row < layout.height; ++row) {
    const uint8_t* rgba = picture + static_cast<std::size_t>(row) * static_cast<std::size_t>(layout.width) * 4;
    unsigned char* out = bytes + pixelOffset(layout, 0, row);
    if (layout.format == OSMESA_RGBA && layout.type == GL_UNSIGNED_BYTE) {
      std::memcpy(out, rgba, static_cast<std::size_t>(layout.width) * 4);
      continue;
    }
    for (int x = 0; x < layout.width; ++x, rgba += 4, out += pixelBytes) {
      // memcpy through a local value: the caller's buffer need not be aligned for the type.
      if (layout.format == OSMESA_RGB_565) {
        const uint16_t packed = static_cast<uint16_t>(widen(rgba[0], 31) << 11 |
                                                      widen(rgba[1], 63) << 5 | widen(rgba[2], 31));
        std::memcpy(out, &packed, 2);
      } else if (layout.type == GL_UNSIGNED_SHORT) {
        uint16_t values[4];
        storeComponents(rgba, values, order);
        std::memcpy(out, values, pixelBytes);
      } else if (layout.type == GL_FLOAT) {
        float values[4];
        storeComponents(rgba, values, order);
        std::memcpy(out, values, pixelBytes);
      } else {
        storeComponents(rgba, out, order);
      }
    }
  }
}

void loadColorBuffer(const void* buffer, const BufferLayout& layout,
                     raster::Framebuffer& framebuffer) {
  const auto* bytes = static_cast<const unsigned char*>(buffer);
  const ComponentOrder order = componentOrder(layout.format);
  const std::size_t pixelBytes = bytesPerPixel(layout.format, layout.type);
  for (int row = 0; row < layout.height; ++row) {
    uint8_t* rgba = framebuffer.colorAt(0, row);
    const unsigned char* in = bytes + pixelOffset(layout, 0, row);
    if (layout.format == OSMESA_RGBA && layout.type == GL_UNSIGNED_BYTE) {
      std::memcpy(rgba, in, static_cast<std::size_t>(layout.width) * 4);
      continue;
    }
    for (int x = 0; x < layout.width; ++x, rgba += 4, in += pixelBytes) {
      if (layout.format == OSMESA_RGB_565) {
        uint16_t packed;
        std::memcpy(&packed, in, 2);
        rgba[0] = narrow(packed >> 11, 31);
        rgba[1] = narrow((packed >> 5) & 63u, 63);
        rgba[2] = narrow(packed & 31u, 31);
        rgba[3] = 255;
      } else if (layout.type == GL_UNSIGNED_SHORT) {
        uint16_t values[4];
        std::memcpy(values, in, pixelBytes);
        loadComponents(values, rgba, order);
      } else if (layout.type == GL_FLOAT) {
        float values[4];
        std::memcpy(values, in, pixelBytes);
        loadComponents(values, rgba, order);
      } else {
        loadComponents(in, rgba, order);
      }
    }
  }
}

}  // namespace glass::osmesa
