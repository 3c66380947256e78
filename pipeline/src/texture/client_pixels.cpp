#include "texture/client_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace glass::gl {
namespace {

// Which RGBA slot each component of a format goes to (index 4 means luminance: R, G and B).
constexpr int kLuminance = 4;

struct FormatComponents {
  int count;
  int slot[4];
};

bool formatComponents(GLenum format, FormatComponents* out) {
  switch (format) {
    case GL_RED: *out = {1, {0}}; return true;
    case GL_GREEN: *out = {1, {1}}; return true;
    case GL_BLUE: *out = {1, {2}}; return true;
    case GL_ALPHA: *out = {1, {3}}; return true;
    case GL_RGB: *out = {3, {0, 1, 2}}; return true;
    case GL_BGR: *out = {3, {2, 1, 0}}; return true;
    case GL_RGBA: *out = {4, {0, 1, 2, 3}}; return true;
    case GL_BGRA: *out = {4, {2, 1, 0, 3}}; return true;
    case GL_LUMINANCE: *out = {1, {kLuminance}}; return true;
    case GL_LUMINANCE_ALPHA: *out = {2, {kLuminance, 3}}; return true;
    default: return false;
  }
}

// A packed type (tables 3.8 to 3.11): the element size in bytes and the bit fields of its
// components, first component first, each as (shift, width).
struct PackedType {
  int bytes;
  int count;
  int shift[4];
  int width[4];
};

bool packedType(GLenum type, PackedType* out) {
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: *out = {1, 3, {5, 2, 0}, {3, 3, 2}}; return true;
    case GL_UNSIGNED_BYTE_2_3_3_REV: *out = {1, 3, {0, 3, 6}, {3, 3, 2}}; return true;
    case GL_UNSIGNED_SHORT_5_6_5: *out = {2, 3, {11, 5, 0}, {5, 6, 5}}; return true;
    case GL_UNSIGNED_SHORT_5_6_5_REV: *out = {2, 3, {0, 5, 11}, {5, 6, 5}}; return true;
    case GL_UNSIGNED_SHORT_4_4_4_4: *out = {2, 4, {12, 8, 4, 0}, {4, 4, 4, 4}}; return true;
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: *out = {2, 4, {0, 4, 8, 12}, {4, 4, 4, 4}}; return true;
    case GL_UNSIGNED_SHORT_5_5_5_1: *out = {2, 4, {11, 6, 1, 0}, {5, 5, 5, 1}}; return true;
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: *out = {2, 4, {0, 5, 10, 15}, {5, 5, 5, 1}}; return true;
    case GL_UNSIGNED_INT_8_8_8_8: *out = {4, 4, {24, 16, 8, 0}, {8, 8, 8, 8}}; return true;
    case GL_UNSIGNED_INT_8_8_8_8_REV: *out = {4, 4, {0, 8, 16, 24}, {8, 8, 8, 8}}; return true;
    case GL_UNSIGNED_INT_10_10_10_2: *out = {4, 4, {22, 12, 2, 0}, {10, 10, 10, 2}}; return true;
    case GL_UNSIGNED_INT_2_10_10_10_REV: *out = {4, 4, {0, 10, 20, 30}, {10, 10, 10, 2}}; return true;
    default: return false;
  }
}

int scalarTypeBytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return 4;
    default: return 0;
  }
}

// The memory layout of a block of pixels (spec 3.6.4, "Unpacking"): where group (i, j) starts.
struct BlockLayout {
  size_t elementBytes;  // s
  size_t groupBytes;    // n * s, or the packed element size
  size_t rowBytes;      // k * s
  size_t firstByte;     // the skipped rows and pixels
};

BlockLayout blockLayout(int width, int elementsPerGroup, int elementBytes, const PixelLayout& layout) {
  BlockLayout b;
  b.elementBytes = static_cast<size_t>(elementBytes);
  b.groupBytes = b.elementBytes * static_cast<size_t>(elementsPerGroup);
  const size_t rowGroups = static_cast<size_t>(layout.rowLength > 0 ? layout.rowLength : width);
  const size_t alignment = static_cast<size_t>(std::max(layout.alignment, 1));
  // k = n l when s >= a, else (a / s) ceil(s n l / a); in bytes: round n l s up to a multiple of a.
  size_t rowBytes = b.groupBytes * rowGroups;
  if (b.elementBytes < alignment) rowBytes = (rowBytes + alignment - 1) / alignment * alignment;
  b.rowBytes = rowBytes;
  b.firstByte = static_cast<size_t>(layout.skipRows) * rowBytes +
                static_cast<size_t>(layout.skipPixels) * b.groupBytes;
  return b;
}

// How a span of pixels of the given format and type sits in memory: the format's components, the
// packed type if it is one, the block layout and whether bytes are swapped.
struct SpanFormat {
  FormatComponents components;
  PackedType packed;
  bool isPacked;
  BlockLayout block;
  bool swap;
};

SpanFormat spanFormat(int width, GLenum format, GLenum type, const PixelLayout& layout) {
  SpanFormat f{};
  formatComponents(format, &f.components);
  f.isPacked = packedType(type, &f.packed);
  const int elementBytes = f.isPacked ? f.packed.bytes : scalarTypeBytes(type);
  f.block = blockLayout(width, f.isPacked ? 1 : f.components.count, elementBytes, layout);
  f.swap = layout.swapBytes && elementBytes > 1;
  return f;
}

uint32_t readUnsigned(const unsigned char* p, int bytes, bool swap) {
  unsigned char b[4] = {0, 0, 0, 0};
  std::memcpy(b, p, static_cast<size_t>(bytes));
  if (swap) std::reverse(b, b + bytes);
  if (bytes == 1) return b[0];
  if (bytes == 2) {
    uint16_t v;
    std::memcpy(&v, b, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, b, 4);
  return v;
}

void writeUnsigned(unsigned char* p, int bytes, bool swap, uint32_t value) {
  unsigned char b[4];
  if (bytes == 1) {
    b[0] = static_cast<unsigned char>(value);
  } else if (bytes == 2) {
    const uint16_t v = static_cast<uint16_t>(value);
    std::memcpy(b, &v, 2);
  } else {
    std::memcpy(b, &value, 4);
  }
  if (swap) std::reverse(b, b + bytes);
  std::memcpy(p, b, static_cast<size_t>(bytes));
}

// Table 2.9: an element of the given type as a float (unsigned: c / (2^b - 1); signed:
// (2c + 1) / (2^b - 1); float as it is).
float elementToFloat(const unsigned char* p, GLenum type, bool swap) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<float>(p[0]) / 255.0f;
    case GL_BYTE: {
      const int8_t c = static_cast<int8_t>(p[0]);
      return (2.0f * c + 1.0f) / 255.0f;
    }
    case GL_UNSIGNED_SHORT: return static_cast<float>(readUnsigned(p, 2, swap)) / 65535.0f;
    case GL_SHORT: {
      const int16_t c = static_cast<int16_t>(readUnsigned(p, 2, swap));
      return (2.0f * c + 1.0f) / 65535.0f;
    }
    case GL_UNSIGNED_INT:
      return static_cast<float>(static_cast<double>(readUnsigned(p, 4, swap)) / 4294967295.0);
    case GL_INT: {
      const int32_t c = static_cast<int32_t>(readUnsigned(p, 4, swap));
      return static_cast<float>((2.0 * c + 1.0) / 4294967295.0);
    }
    case GL_FLOAT: {
      const uint32_t bits = readUnsigned(p, 4, swap);
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    default: return 0.0f;
  }
}

// Writes an element of the given type: for an integer type, a value already in its range.
void writeElement(GLenum type, bool swap, unsigned char* p, double value) {
  switch (type) {
    case GL_UNSIGNED_BYTE: p[0] = static_cast<unsigned char>(value); break;
    case GL_BYTE: p[0] = static_cast<unsigned char>(static_cast<int8_t>(value)); break;
    case GL_UNSIGNED_SHORT: writeUnsigned(p, 2, swap, static_cast<uint32_t>(value)); break;
    case GL_SHORT: writeUnsigned(p, 2, swap, static_cast<uint16_t>(static_cast<int16_t>(value))); break;
    case GL_UNSIGNED_INT: writeUnsigned(p, 4, swap, static_cast<uint32_t>(value)); break;
    case GL_INT: writeUnsigned(p, 4, swap, static_cast<uint32_t>(static_cast<int32_t>(value))); break;
    case GL_FLOAT: {
      const float v = static_cast<float>(value);
      uint32_t bits;
      std::memcpy(&bits, &v, 4);
      writeUnsigned(p, 4, swap, bits);
      break;
    }
    default: break;
  }
}

// The largest value of an unsigned integer type, 2^n - 1: 255, 65535, 4294967295 for the
// types of 1, 2 and 4 bytes, signed or not.
double typeRange(GLenum type) {
  const int bytes = scalarTypeBytes(type);
  return bytes == 1 ? 255.0 : bytes == 2 ? 65535.0 : 4294967295.0;
}

bool isSignedType(GLenum type) { return type == GL_BYTE || type == GL_SHORT || type == GL_INT; }

// Table 4.7 (packing): a component clamped to [0, 1] as an element of the given type; signed
// types take (c (2^n - 1) - 1) / 2.
void floatToElement(float c, GLenum type, bool swap, unsigned char* p) {
  if (type == GL_FLOAT) return writeElement(type, swap, p, std::clamp(c, 0.0f, 1.0f));
  const double f = std::clamp(static_cast<double>(c), 0.0, 1.0);
  const double scaled = f * typeRange(type);
  writeElement(type, swap, p, std::nearbyint(isSignedType(type) ? (scaled - 1.0) / 2.0 : scaled));
}

}  // namespace

GLenum checkTexelFormatAndType(GLenum format, GLenum type) {
  // Textures take colour formats only, and no bitmaps.
  if (!isColorFormat(format) || type == GL_BITMAP) return GL_INVALID_ENUM;
  return checkPixelFormatAndType(format, type);
}

GLenum checkTexImageFormatAndType(GLenum format, GLenum type) {
  if (format == GL_COLOR_INDEX) return checkPixelFormatAndType(format, type);
  return checkTexelFormatAndType(format, type);
}

GLenum checkPixelFormatAndType(GLenum format, GLenum type) {
  FormatComponents components{};
  const bool indexOrDepth =
      format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT;
  const bool formatKnown = formatComponents(format, &components) || indexOrDepth;
  PackedType packed;
  const bool isPacked = packedType(type, &packed);
  const bool typeKnown = isPacked || scalarTypeBytes(type) > 0 || type == GL_BITMAP;
  if (!formatKnown || !typeKnown) return GL_INVALID_ENUM;
  // Spec 3.6.4: bitmaps hold indices only.
  if (type == GL_BITMAP && format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX) {
    return GL_INVALID_ENUM;
  }
  // Table 3.8: 3-component packed types go with RGB (and BGR), 4-component ones with RGBA/BGRA.
  if (isPacked && (indexOrDepth || packed.count != components.count)) return GL_INVALID_OPERATION;
  if (isPacked && packed.count == 3 && format != GL_RGB && format != GL_BGR) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

bool isColorFormat(GLenum format) {
  FormatComponents components;
  return formatComponents(format, &components);
}

PixelLayout sliceLayout(const PixelLayout& layout, int height, int slice) {
  const int imageRows = layout.imageHeight > 0 ? layout.imageHeight : height;
  PixelLayout l = layout;
  l.skipRows = layout.skipRows + (layout.skipImages + slice) * imageRows;
  return l;
}

void unpackTexels(const void* pixels, int width, int height, GLenum format, GLenum type,
                  const PixelLayout& layout, BaseFormat base, std::vector<uint8_t>& texels) {
  texels.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  if (format == GL_RGBA && type == GL_UNSIGNED_BYTE && base == BaseFormat::RGBA) {
    // Each byte b would become b / 255 and be stored back as b (the unit test
    // unpack_rgba_bytes_copies_conversion checks every byte value): the rows are copied.
    const BlockLayout block = spanFormat(width, format, type, layout).block;
    for (int j = 0; j < height; ++j) {
      std::memcpy(&texels[static_cast<size_t>(j) * static_cast<size_t>(width) * 4],
                  static_cast<const unsigned char*>(pixels) + block.firstByte + static_cast<size_t>(j) * block.rowBytes,
                  static_cast<size_t>(width) * 4);
    }
    return;
  }
  std::vector<float> rgba(static_cast<size_t>(width) * 4);
  for (int j = 0; j < height; ++j) {
    unpackColorRow(pixels, width, j, format, type, layout, rgba.data());
    for (int i = 0; i < width; ++i) {
      storeTexel(base, &rgba[static_cast<size_t>(i) * 4],
                 &texels[(static_cast<size_t>(j) * static_cast<size_t>(width) + static_cast<size_t>(i)) * 4]);
    }
  }
}

void unpackColorRow(const void* pixels, int width, int row, GLenum format, GLenum type,
                    const PixelLayout& layout, float* rgbaOut) {
  const SpanFormat span = spanFormat(width, format, type, layout);
  const FormatComponents& components = span.components;
  const PackedType& packed = span.packed;
  const bool isPacked = span.isPacked;
  const BlockLayout& block = span.block;
  const bool swap = span.swap;

  const unsigned char* first = static_cast<const unsigned char*>(pixels) + block.firstByte +
                               static_cast<size_t>(row) * block.rowBytes;
  for (int i = 0; i < width; ++i) {
    const unsigned char* group = first + static_cast<size_t>(i) * block.groupBytes;
    float values[4];
    if (isPacked) {
      const uint32_t element = readUnsigned(group, packed.bytes, swap);
      for (int c = 0; c < packed.count; ++c) {
        const uint32_t max = (1u << packed.width[c]) - 1u;
        values[c] = static_cast<float>((element >> packed.shift[c]) & max) / static_cast<float>(max);
      }
    } else {
      for (int c = 0; c < components.count; ++c)
        values[c] = elementToFloat(group + static_cast<size_t>(c) * block.elementBytes, type, swap);
    }
    float* rgba = rgbaOut + static_cast<size_t>(i) * 4;
    rgba[0] = rgba[1] = rgba[2] = 0.0f;
    rgba[3] = 1.0f;
    for (int c = 0; c < components.count; ++c) {
      if (components.slot[c] == kLuminance) {
        rgba[0] = rgba[1] = rgba[2] = values[c];
      } else {
        rgba[components.slot[c]] = values[c];
      }
    }
  }
}

bool unpackByteColorSpan(const void* pixels, int count, int width, int column, int row, GLenum format,
                         GLenum type, const PixelLayout& layout, uint8_t* rgba8) {
  if (type != GL_UNSIGNED_BYTE) return false;
  const SpanFormat span = spanFormat(width, format, type, layout);
  const FormatComponents& components = span.components;
  const unsigned char* first = static_cast<const unsigned char*>(pixels) + span.block.firstByte +
                               static_cast<size_t>(row) * span.block.rowBytes +
                               static_cast<size_t>(column) * span.block.groupBytes;
  if (format == GL_RGBA) {
    std::memcpy(rgba8, first, static_cast<size_t>(count) * 4);
    return true;
  }
  for (int i = 0; i < count; ++i) {
    const unsigned char* group = first + static_cast<size_t>(i) * span.block.groupBytes;
    uint8_t* out = rgba8 + static_cast<size_t>(i) * 4;
    out[0] = out[1] = out[2] = 0;
    out[3] = 255;
    for (int c = 0; c < components.count; ++c) {
      if (components.slot[c] == kLuminance) {
        out[0] = out[1] = out[2] = group[c];
      } else {
        out[components.slot[c]] = group[c];
      }
    }
  }
  return true;
}

void packPixelRow(const float* rgba, int width, int row, GLenum format, GLenum type,
                  const PixelLayout& layout, void* pixels) {
  packColorSpan(rgba, width, width, 0, row, format, type, layout, LuminancePacking::Red, pixels);
}

void packColorSpan(const float* rgba, int count, int width, int column, int row, GLenum format,
                   GLenum type, const PixelLayout& layout, LuminancePacking luminance, void* pixels) {
  const SpanFormat span = spanFormat(width, format, type, layout);
  const FormatComponents& components = span.components;
  const PackedType& packed = span.packed;
  const bool isPacked = span.isPacked;
  const BlockLayout& block = span.block;
  const bool swap = span.swap;

  unsigned char* out = static_cast<unsigned char*>(pixels) + block.firstByte +
                       static_cast<size_t>(row) * block.rowBytes +
                       static_cast<size_t>(column) * block.groupBytes;
  for (int i = 0; i < count; ++i) {
    unsigned char* group = out + static_cast<size_t>(i) * block.groupBytes;
    const float* in = rgba + static_cast<size_t>(i) * 4;
    float values[4];
    for (int c = 0; c < components.count; ++c) {
      if (components.slot[c] != kLuminance) {
        values[c] = in[components.slot[c]];
      } else if (luminance == LuminancePacking::Red) {
        values[c] = in[0];
      } else {
        values[c] = std::min(1.0f, in[0] + in[1] + in[2]);
      }
    }
    if (isPacked) {
      uint32_t element = 0;
      for (int c = 0; c < packed.count; ++c) {
        const uint32_t max = (1u << packed.width[c]) - 1u;
        const double f = std::clamp(static_cast<double>(values[c]), 0.0, 1.0);
        element |= static_cast<uint32_t>(std::nearbyint(f * max)) << packed.shift[c];
      }
      writeUnsigned(group, packed.bytes, swap, element);
    } else {
      for (int c = 0; c < components.count; ++c)
        floatToElement(values[c], type, swap, group + static_cast<size_t>(c) * block.elementBytes);
    }
  }
}

bool packByteColorSpan(const uint8_t* rgba8, int count, int width, int column, int row, GLenum format,
                       GLenum type, const PixelLayout& layout, void* pixels) {
  if (type != GL_UNSIGNED_BYTE) return false;
  const SpanFormat span = spanFormat(width, format, type, layout);
  const FormatComponents& components = span.components;
  for (int c = 0; c < components.count; ++c)
    if (components.slot[c] == kLuminance) return false;  // a sum, not a copy
  unsigned char* out = static_cast<unsigned char*>(pixels) + span.block.firstByte +
                       static_cast<size_t>(row) * span.block.rowBytes +
                       static_cast<size_t>(column) * span.block.groupBytes;
  if (format == GL_RGBA) {
    std::memcpy(out, rgba8, static_cast<size_t>(count) * 4);
    return true;
  }
  for (int i = 0; i < count; ++i) {
    unsigned char* group = out + static_cast<size_t>(i) * span.block.groupBytes;
    const uint8_t* in = rgba8 + static_cast<size_t>(i) * 4;
    for (int c = 0; c < components.count; ++c) group[c] = in[components.slot[c]];
  }
  return true;
}

namespace {

// A count as an element of the given type: the number itself, saturated to the type's range.
void countToElement(double v, GLenum type, bool swap, unsigned char* p) {
  if (type == GL_FLOAT) return writeElement(type, swap, p, v);
  const double range = typeRange(type);
  writeElement(type, swap, p, std::min(v, isSignedType(type) ? (range - 1.0) / 2.0 : range));
}

}  // namespace

void packCountSpan(const uint32_t* counts, int count, GLenum format, GLenum type,
                   const PixelLayout& layout, void* pixels) {
  const SpanFormat span = spanFormat(count, format, type, layout);
  const FormatComponents& components = span.components;
  const PackedType& packed = span.packed;
  const bool isPacked = span.isPacked;
  const BlockLayout& block = span.block;
  const bool swap = span.swap;
  unsigned char* out = static_cast<unsigned char*>(pixels) + block.firstByte;
  for (int i = 0; i < count; ++i) {
    unsigned char* group = out + static_cast<size_t>(i) * block.groupBytes;
    const uint32_t* in = counts + static_cast<size_t>(i) * 4;
    double values[4];
    for (int c = 0; c < components.count; ++c) {
      values[c] = static_cast<double>(in[components.slot[c] == kLuminance ? 0 : components.slot[c]]);
    }
    if (isPacked) {
      uint32_t element = 0;
      for (int c = 0; c < packed.count; ++c) {
        const uint32_t max = (1u << packed.width[c]) - 1u;
        element |= static_cast<uint32_t>(std::min(values[c], static_cast<double>(max))) << packed.shift[c];
      }
      writeUnsigned(group, packed.bytes, swap, element);
    } else {
      for (int c = 0; c < components.count; ++c)
        countToElement(values[c], type, swap, group + static_cast<size_t>(c) * block.elementBytes);
    }
  }
}

namespace {

// Bitmaps (spec 3.6.4, "Unpacking of bitmaps"): a row of l bits (l the row length or the width)
// takes a ceil(l / 8a) bytes, a the alignment; pixel i of a row is bit skipPixels + i, counted
// from the most significant bit of each byte, or from the least with GL_*_LSB_FIRST.
struct BitPosition {
  size_t byte;
  unsigned mask;
};

BitPosition bitmapBit(int width, int column, int row, const PixelLayout& layout) {
  const size_t rowBits = static_cast<size_t>(layout.rowLength > 0 ? layout.rowLength : width);
  const size_t alignment = static_cast<size_t>(std::max(layout.alignment, 1));
  const size_t rowBytes = (rowBits + 8 * alignment - 1) / (8 * alignment) * alignment;
  const size_t bit = static_cast<size_t>(layout.skipPixels) + static_cast<size_t>(column);
  const unsigned shift = static_cast<unsigned>(bit % 8);
  return {(static_cast<size_t>(layout.skipRows) + static_cast<size_t>(row)) * rowBytes + bit / 8,
          layout.lsbFirst ? 1u << shift : 0x80u >> shift};
}

// A one-component block (depth or index) of a scalar type: where pixel `column` of `row` starts.
const unsigned char* scalarElement(const void* pixels, int width, int column, int row, GLenum type,
                                   const PixelLayout& layout) {
  const BlockLayout block = blockLayout(width, 1, scalarTypeBytes(type), layout);
  return static_cast<const unsigned char*>(pixels) + block.firstByte +
         static_cast<size_t>(row) * block.rowBytes + static_cast<size_t>(column) * block.groupBytes;
}

}  // namespace

void unpackDepthRow(const void* pixels, int width, int row, GLenum type, const PixelLayout& layout,
                    float* depth) {
  const bool swap = layout.swapBytes && scalarTypeBytes(type) > 1;
  for (int i = 0; i < width; ++i) {
    depth[i] = elementToFloat(scalarElement(pixels, width, i, row, type, layout), type, swap);
  }
}

void unpackIndexRow(const void* pixels, int width, int row, GLenum type, const PixelLayout& layout,
                    int32_t* indices) {
  if (type == GL_BITMAP) {
    const auto* bytes = static_cast<const unsigned char*>(pixels);
    for (int i = 0; i < width; ++i) {
      const BitPosition bit = bitmapBit(width, i, row, layout);
      indices[i] = (bytes[bit.byte] & bit.mask) ? 1 : 0;
    }
    return;
  }
  const int bytes = scalarTypeBytes(type);
  const bool swap = layout.swapBytes && bytes > 1;
  for (int i = 0; i < width; ++i) {
    const unsigned char* p = scalarElement(pixels, width, i, row, type, layout);
    const uint32_t raw = readUnsigned(p, bytes, swap);
    switch (type) {
      case GL_BYTE: indices[i] = static_cast<int8_t>(raw); break;
      case GL_SHORT: indices[i] = static_cast<int16_t>(raw); break;
      case GL_FLOAT: {
        float f;
        std::memcpy(&f, &raw, 4);
        // Spec 3.6.4: a floating-point index keeps its integer part; out-of-range values are
        // clamped rather than left undefined.
        indices[i] = static_cast<int32_t>(std::clamp(std::trunc(static_cast<double>(f)), -2147483648.0, 2147483647.0));
        break;
      }
      default: indices[i] = static_cast<int32_t>(raw); break;  // unsigned types and GL_INT
    }
  }
}

void packDepthSpan(const float* depth, int count, int width, int column, int row, GLenum type,
                   const PixelLayout& layout, void* pixels) {
  const bool swap = layout.swapBytes && scalarTypeBytes(type) > 1;
  for (int i = 0; i < count; ++i) {
    auto* p = const_cast<unsigned char*>(scalarElement(pixels, width, column + i, row, type, layout));
    floatToElement(depth[i], type, swap, p);
  }
}

void packIndexSpan(const uint32_t* indices, int count, int width, int column, int row, GLenum type,
                   const PixelLayout& layout, void* pixels) {
  if (type == GL_BITMAP) {
    auto* bytes = static_cast<unsigned char*>(pixels);
    for (int i = 0; i < count; ++i) {
      const BitPosition bit = bitmapBit(width, column + i, row, layout);
      if (indices[i] & 1u) {
        bytes[bit.byte] = static_cast<unsigned char>(bytes[bit.byte] | bit.mask);
      } else {
        bytes[bit.byte] = static_cast<unsigned char>(bytes[bit.byte] & ~bit.mask);
      }
    }
    return;
  }
  const int bytes = scalarTypeBytes(type);
  const bool swap = layout.swapBytes && bytes > 1;
  for (int i = 0; i < count; ++i) {
    auto* p = const_cast<unsigned char*>(scalarElement(pixels, width, column + i, row, type, layout));
    if (type == GL_FLOAT) {
      const float f = static_cast<float>(indices[i]);
      uint32_t bits;
      std::memcpy(&bits, &f, 4);
      writeUnsigned(p, 4, swap, bits);
    } else {
      writeUnsigned(p, bytes, swap, indices[i]);  // masked to the type's width
    }
  }
}

}  // namespace glass::gl
