// GLU's shared pieces (client_image.h), as the SGI GLU that Mesa ships computes them.
#include "glu/client_image.h"

#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glass::glu {

int componentsOfFormat(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
    case GL_BGR: return 3;
    case GL_RGBA:
    case GL_BGRA: return 4;
    default: return 0;
  }
}

bool isIndexFormat(GLenum format) { return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX; }

int bytesOfType(GLenum type) {
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

bool isPackedOrBitmapType(GLenum type) {
  switch (type) {
    case GL_BITMAP:
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV: return true;
    default: return false;
  }
}

GLint checkMipmapArguments(GLenum format, GLenum type) {
  if (componentsOfFormat(format) == 0 || format == GL_STENCIL_INDEX) return GLU_INVALID_ENUM;
  if (bytesOfType(type) == 0) return GLU_INVALID_ENUM;
  return 0;
}

int nearestPowerOfTwo(int value) {
  int power = 1;
  for (;;) {
    if (value == 1) return power;
    if (value == 3) return power * 4;
    value >>= 1;
    power *= 2;
  }
}

int log2OfPowerOfTwo(int value) {
  int log = 0;
  while (value > 1) {
    value >>= 1;
    ++log;
  }
  return log;
}

int exactLog2(int value) {
  return value > 0 && (value & (value - 1)) == 0 ? log2OfPowerOfTwo(value) : -1;
}

namespace {

double readElement(const unsigned char* p, GLenum type, bool swap) {
  unsigned char b[4];
  const int n = bytesOfType(type);
  std::memcpy(b, p, static_cast<size_t>(n));
  if (swap) std::reverse(b, b + n);
  switch (type) {
    case GL_UNSIGNED_BYTE: return b[0];
    case GL_BYTE: return static_cast<int8_t>(b[0]);
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, b, 2); return v; }
    case GL_SHORT: { int16_t v; std::memcpy(&v, b, 2); return v; }
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, b, 4); return v; }
    case GL_INT: { int32_t v; std::memcpy(&v, b, 4); return v; }
    case GL_FLOAT: { float v; std::memcpy(&v, b, 4); return v; }
    default: return 0.0;
  }
}

}  // namespace

void writeElement(double v, GLenum type, unsigned char* p) {
  // Integer types: truncated towards zero to a 64-bit integer, then wrapped to the element's
  // width, as C converts GLU's integer working values (an index of 137 written as a GL_BYTE is
  // -119). Converting the double straight to a narrower type is undefined out of its range.
  const long long whole = v > -9.0e18 && v < 9.0e18 ? static_cast<long long>(v) : 0;
  switch (type) {
    case GL_UNSIGNED_BYTE: { const auto x = static_cast<uint8_t>(whole); std::memcpy(p, &x, 1); break; }
    case GL_BYTE: { const auto x = static_cast<int8_t>(whole); std::memcpy(p, &x, 1); break; }
    case GL_UNSIGNED_SHORT: { const auto x = static_cast<uint16_t>(whole); std::memcpy(p, &x, 2); break; }
    case GL_SHORT: { const auto x = static_cast<int16_t>(whole); std::memcpy(p, &x, 2); break; }
    case GL_UNSIGNED_INT: { const auto x = static_cast<uint32_t>(whole); std::memcpy(p, &x, 4); break; }
    case GL_INT: { const auto x = static_cast<int32_t>(whole); std::memcpy(p, &x, 4); break; }
    case GL_FLOAT: { const auto x = static_cast<float>(v); std::memcpy(p, &x, 4); break; }
    default: break;
  }
}

namespace {

// GLU's 2 x 2 (or 2 x 1) average in the arithmetic of each client type.
double averageOf(const double* v, int n, GLenum type) {
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += v[k];
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: {
      // C integer division, truncating towards zero; the 2 x 2 filter adds 2 first.
      const long long s = static_cast<long long>(sum) + (n == 4 ? 2 : 0);
      return static_cast<double>(s / n);
    }
    case GL_UNSIGNED_INT:  // summed in double, which holds every unsigned int
      return std::trunc(n == 4 ? sum / 4.0 + 0.5 : sum / 2.0);
    case GL_INT: {  // summed in single precision
      float single = static_cast<float>(v[0]);
      for (int k = 1; k < n; ++k) single += static_cast<float>(v[k]);
      return std::trunc(n == 4 ? static_cast<double>(single / 4.0f) + 0.5 : single / 2.0);
    }
    default: {  // GL_FLOAT: summed in single precision
      float single = static_cast<float>(v[0]);
      for (int k = 1; k < n; ++k) single += static_cast<float>(v[k]);
      return single / static_cast<float>(n);
    }
  }
}

}  // namespace

ClientLayout clientLayout(int dimensions, int width, int height, GLenum format, GLenum type, const void* data) {
  GLint alignment = 4, rowLength = 0, skipRows = 0, skipPixels = 0, swapBytes = 0, imageHeight = 0, skipImages = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swapBytes);
  if (dimensions == 3) {
    glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
    glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &skipImages);
  }
  ClientLayout layout;
  layout.elementBytes = static_cast<size_t>(bytesOfType(type));
  layout.groupBytes = layout.elementBytes * static_cast<size_t>(componentsOfFormat(format));
  layout.rowBytes = layout.groupBytes * static_cast<size_t>(rowLength > 0 ? rowLength : width);
  const size_t align = static_cast<size_t>(std::max(alignment, 1));
  if (layout.elementBytes < align) layout.rowBytes = (layout.rowBytes + align - 1) / align * align;
  layout.imageBytes = layout.rowBytes * static_cast<size_t>(imageHeight > 0 ? imageHeight : height);
  layout.first = static_cast<const unsigned char*>(data) + static_cast<size_t>(skipImages) * layout.imageBytes +
                 static_cast<size_t>(skipRows) * layout.rowBytes + static_cast<size_t>(skipPixels) * layout.groupBytes;
  layout.swapBytes = swapBytes != 0 && layout.elementBytes > 1;
  return layout;
}

ClientImage readClientImage(int dimensions, int width, int height, int depth, GLenum format, GLenum type,
                            const void* data) {
  const ClientLayout layout = clientLayout(dimensions, width, height, format, type, data);
  ClientImage image;
  image.width = width;
  image.height = height;
  image.depth = depth;
  image.components = componentsOfFormat(format);
  image.values.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(depth) *
                      static_cast<size_t>(image.components));
  for (int k = 0; k < depth; ++k)
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i)
        for (int c = 0; c < image.components; ++c)
          image.at(i, j, k, c) = readElement(layout.first + static_cast<size_t>(k) * layout.imageBytes +
                                                 static_cast<size_t>(j) * layout.rowBytes +
                                                 static_cast<size_t>(i) * layout.groupBytes +
                                                 static_cast<size_t>(c) * layout.elementBytes,
                                             type, layout.swapBytes);
  return image;
}

ClientImage halveImage(const ClientImage& in, GLenum type) {
  ClientImage out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.components = in.components;
  out.values.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * static_cast<size_t>(out.components));
  const bool oneDimensional = in.width == 1 || in.height == 1;
  for (int j = 0; j < out.height; ++j) {
    for (int i = 0; i < out.width; ++i) {
      for (int c = 0; c < out.components; ++c) {
        double v[4];
        int n;
        if (!oneDimensional) {
          v[0] = in.at(2 * i, 2 * j, c);
          v[1] = in.at(2 * i + 1, 2 * j, c);
          v[2] = in.at(2 * i, 2 * j + 1, c);
          v[3] = in.at(2 * i + 1, 2 * j + 1, c);
          n = 4;
        } else if (in.height == 1) {
          v[0] = in.at(2 * i, 0, c);
          v[1] = in.at(2 * i + 1, 0, c);
          n = 2;
        } else {
          v[0] = in.at(0, 2 * j, c);
          v[1] = in.at(0, 2 * j + 1, c);
          n = 2;
        }
        out.at(i, j, c) = averageOf(v, n, type);
      }
    }
  }
  return out;
}

void uploadLevel(GLenum target, int dimensions, GLint level, GLint internalFormat, const ClientImage& image,
                 GLenum format, GLenum type) {
  const size_t elementBytes = static_cast<size_t>(bytesOfType(type));
  std::vector<unsigned char> data(image.values.size() * elementBytes);
  for (size_t k = 0; k < image.values.size(); ++k) writeElement(image.values[k], type, &data[k * elementBytes]);
  uploadPackedLevel(target, dimensions, level, internalFormat, image.width, image.height, image.depth, format, type,
                    data.data());
}

void uploadPackedLevel(GLenum target, int dimensions, GLint level, GLint internalFormat, int width, int height,
                       int depth, GLenum format, GLenum type, const void* data) {
  GLint alignment, rowLength, skipRows, skipPixels, swapBytes, imageHeight = 0, skipImages = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swapBytes);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  if (dimensions == 1) {
    glTexImage1D(target, level, internalFormat, width, 0, format, type, data);
  } else if (dimensions == 2) {
    glTexImage2D(target, level, internalFormat, width, height, 0, format, type, data);
  } else {
    glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
    glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &skipImages);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    glTexImage3D(target, level, internalFormat, width, height, depth, 0, format, type, data);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, imageHeight);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, skipImages);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, swapBytes);
}

// gluScaleImage and the 1D mipmaps work on 16-bit unsigned values, converted as GLU converts
// them (its "rough" scales, kept so that the values come out as libGLU's): an unsigned byte b is
// 257 b, a byte 516 b, a short 2 s, an unsigned int u >> 16, an int i >> 15 (the signed products
// and shifts wrapped to 16 bits as C converts them), a float 65535 f in single precision
// (truncated, through a 32-bit integer as on x86). Colour and stencil indices are taken as they
// are.
uint16_t sixteenBitOf(double raw, GLenum type, bool index) {
  if (type == GL_FLOAT) {
    const float scaled = index ? static_cast<float>(raw) : 65535.0f * static_cast<float>(raw);
    if (!(scaled > -2147483648.0f && scaled < 2147483648.0f)) return 0;  // x86 gives 0x80000000
    return static_cast<uint16_t>(static_cast<int32_t>(scaled));
  }
  const auto value = static_cast<int64_t>(raw);  // every other type's values are integers
  if (index) return static_cast<uint16_t>(value);
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<uint16_t>(value * 257);
    case GL_BYTE: return static_cast<uint16_t>(value * 516);
    case GL_SHORT: return static_cast<uint16_t>(value * 2);
    case GL_UNSIGNED_INT: return static_cast<uint16_t>(value >> 16);
    case GL_INT: return static_cast<uint16_t>(value >> 15);  // arithmetic shift of the signed value
    default: return static_cast<uint16_t>(value);            // GL_UNSIGNED_SHORT
  }
}

// The client value GLU writes for a 16-bit value u: u >> 8 for unsigned bytes, u >> 9 for bytes,
// u >> 1 for shorts, 65537 u for unsigned ints (half of that for ints), u / 65535 in single
// precision for floats; indices as they are.
double fromSixteenBit(uint16_t u, GLenum type, bool index) {
  if (index) return type == GL_FLOAT ? static_cast<double>(static_cast<float>(u)) : u;
  switch (type) {
    case GL_UNSIGNED_BYTE: return u >> 8;
    case GL_BYTE: return u >> 9;
    case GL_SHORT: return u >> 1;
    case GL_UNSIGNED_INT: return static_cast<uint32_t>(u) * 65537u;
    case GL_INT: return static_cast<uint32_t>(u) * 65537u / 2u;
    case GL_FLOAT: return static_cast<float>(u) / 65535.0f;
    default: return u;  // GL_UNSIGNED_SHORT
  }
}

// GLU's box filter on 16-bit values: each output texel is the weighted mean of the source volume
// round its centre ((i + 1/2) w_in / w_out, ...): half an output texel each way along an axis that
// shrinks, half a source texel along one that grows (so enlarging interpolates linearly between
// the two nearest texels), the source indices wrapping round the image; the mean is (sum + 1/2) /
// volume, truncated. Single precision where GLU computes in it, in its order (depth, rows,
// columns; each share the product of the column's, the row's and the image's), so the same
// values; with a depth of 1 the image's share is 1 and this is GLU's 2D filter.
ClientImage scaleSixteenBit(const ClientImage& in, int widthOut, int heightOut, int depthOut) {
  ClientImage out;
  out.width = widthOut;
  out.height = heightOut;
  out.depth = depthOut;
  out.components = in.components;
  out.values.resize(static_cast<size_t>(widthOut) * static_cast<size_t>(heightOut) * static_cast<size_t>(depthOut) *
                    static_cast<size_t>(out.components));
  // The box of output index n along an axis of `sizeIn` source texels and `sizeOut` output ones.
  struct Box {
    float low, high;
  };
  auto boxOf = [](int n, int sizeIn, int sizeOut) {
    const float step = static_cast<float>(sizeIn) / static_cast<float>(sizeOut);
    const float half = sizeIn > sizeOut ? step / 2 : 0.5f;
    const auto centre = static_cast<float>(step * (n + 0.5));
    return Box{centre - half, centre + half};
  };
  // Calls visit(index, share) for the unit cells from the box's low end; the first and last
  // are partly inside, indices wrap round `size`.
  auto forEachCell = [](const Box& box, int size, auto&& visit) {
    float x = box.low;
    for (auto cell = static_cast<int>(std::floor(x)); x < box.high; x = static_cast<float>(++cell)) {
      const float share = box.high < static_cast<float>(cell + 1) ? box.high - x : static_cast<float>(cell + 1) - x;
      visit(((cell % size) + size) % size, share);
    }
  };
  for (int k = 0; k < depthOut; ++k) {
    const Box boxZ = boxOf(k, in.depth, depthOut);
    for (int j = 0; j < heightOut; ++j) {
      const Box boxY = boxOf(j, in.height, heightOut);
      for (int i = 0; i < widthOut; ++i) {
        const Box boxX = boxOf(i, in.width, widthOut);
        float totals[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        float volume = 0.0f;
        forEachCell(boxZ, in.depth, [&](int sourceImage, float shareZ) {
          forEachCell(boxY, in.height, [&](int sourceRow, float shareY) {
            forEachCell(boxX, in.width, [&](int sourceColumn, float shareX) {
              const float share = shareX * shareY * shareZ;  // shareZ is 1 for one image
              volume += share;
              for (int c = 0; c < out.components; ++c)
                totals[c] += static_cast<float>(in.at(sourceColumn, sourceRow, sourceImage, c)) * share;
            });
          });
        });
        for (int c = 0; c < out.components; ++c)
          out.at(i, j, k, c) = static_cast<uint16_t>((totals[c] + 0.5) / volume);
      }
    }
  }
  return out;
}

}  // namespace glass::glu
