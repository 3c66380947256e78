// GLU mipmaps: gluBuild1DMipmaps, gluBuild2DMipmaps, their *Levels forms and gluScaleImage,
// built on the GL API.
//
// They follow the algorithm of the SGI GLU that Mesa ships, so that a program's mipmaps come out
// the same with glass as with Mesa's libGLU:
//   1. The image size is rounded to the nearest power of two per axis (3 * 2^k rounds up to
//      4 * 2^k, otherwise down), halved further while it exceeds GL_MAX_TEXTURE_SIZE.
//   2. Level 0 is the image itself when its size already is that power of two; otherwise the
//      image is resampled to it by a box filter: each new texel averages the source area it
//      covers, partial texels weighted by the share covered.
//   3. Every further level halves the previous one with a 2 x 2 box filter, in the arithmetic of
//      the client type: for unsigned bytes (a + b + c + d + 2) / 4; along an axis that is already
//      1 texel long the filter is 2 x 1, (a + b) / 2.
// Every level is handed to glTexImage in the client's own format and type. The packed pixel
// types and GL_BITMAP are not accepted (GLU_INVALID_ENUM).
#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

namespace {

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

// GLU's argument check: 0 or a GLU error code.
GLint checkMipmapArguments(GLenum format, GLenum type) {
  if (componentsOfFormat(format) == 0 || format == GL_STENCIL_INDEX) return GLU_INVALID_ENUM;
  if (bytesOfType(type) == 0) return GLU_INVALID_ENUM;
  return 0;
}

// GLU's "nearest power of two": 3 * 2^k goes up to 4 * 2^k, everything else down.
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

// A client image as raw element values (not normalized), tightly packed, row 0 first.
struct ClientImage {
  int width = 0, height = 0, components = 0;
  std::vector<double> values;
  double& at(int i, int j, int c) {
    return values[(static_cast<size_t>(j) * static_cast<size_t>(width) + static_cast<size_t>(i)) * static_cast<size_t>(components) + static_cast<size_t>(c)];
  }
  double at(int i, int j, int c) const {
    return values[(static_cast<size_t>(j) * static_cast<size_t>(width) + static_cast<size_t>(i)) * static_cast<size_t>(components) + static_cast<size_t>(c)];
  }
};

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

void writeElement(double v, GLenum type, unsigned char* p) {
  switch (type) {
    case GL_UNSIGNED_BYTE: { const auto x = static_cast<uint8_t>(v); std::memcpy(p, &x, 1); break; }
    case GL_BYTE: { const auto x = static_cast<int8_t>(v); std::memcpy(p, &x, 1); break; }
    case GL_UNSIGNED_SHORT: { const auto x = static_cast<uint16_t>(v); std::memcpy(p, &x, 2); break; }
    case GL_SHORT: { const auto x = static_cast<int16_t>(v); std::memcpy(p, &x, 2); break; }
    case GL_UNSIGNED_INT: { const auto x = static_cast<uint32_t>(v); std::memcpy(p, &x, 4); break; }
    case GL_INT: { const auto x = static_cast<int32_t>(v); std::memcpy(p, &x, 4); break; }
    case GL_FLOAT: { const auto x = static_cast<float>(v); std::memcpy(p, &x, 4); break; }
    default: break;
  }
}

// Reads the client image with the current GL_UNPACK_* layout (spec 3.6.4).
ClientImage readClientImage(int width, int height, GLenum format, GLenum type, const void* data) {
  GLint alignment = 4, rowLength = 0, skipRows = 0, skipPixels = 0, swapBytes = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swapBytes);
  ClientImage image;
  image.width = width;
  image.height = height;
  image.components = componentsOfFormat(format);
  image.values.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(image.components));
  const size_t elementBytes = static_cast<size_t>(bytesOfType(type));
  const size_t groupBytes = elementBytes * static_cast<size_t>(image.components);
  size_t rowBytes = groupBytes * static_cast<size_t>(rowLength > 0 ? rowLength : width);
  const size_t align = static_cast<size_t>(std::max(alignment, 1));
  if (elementBytes < align) rowBytes = (rowBytes + align - 1) / align * align;
  const auto* base = static_cast<const unsigned char*>(data) + static_cast<size_t>(skipRows) * rowBytes +
                     static_cast<size_t>(skipPixels) * groupBytes;
  const bool swap = swapBytes != 0 && elementBytes > 1;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      for (int c = 0; c < image.components; ++c)
        image.at(i, j, c) = readElement(base + static_cast<size_t>(j) * rowBytes + static_cast<size_t>(i) * groupBytes +
                                            static_cast<size_t>(c) * elementBytes, type, swap);
  return image;
}

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
    case GL_UNSIGNED_INT:
    case GL_INT:
      return std::trunc(n == 4 ? sum / 4.0 + 0.5 : sum / 2.0);
    default:
      return sum / n;
  }
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

// The share of source texel k (covering [k, k + 1)) inside [lo, hi).
double overlap(int k, double lo, double hi) {
  return std::max(0.0, std::min(k + 1.0, hi) - std::max(static_cast<double>(k), lo));
}

// Box-filter resampling to any size (GLU's scale_internal): each output texel averages the source
// area it covers. Integer types truncate the average, as GLU does.
ClientImage scaleImage(const ClientImage& in, int width, int height, GLenum type) {
  ClientImage out;
  out.width = width;
  out.height = height;
  out.components = in.components;
  out.values.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(out.components));
  const double sx = static_cast<double>(in.width) / width, sy = static_cast<double>(in.height) / height;
  for (int j = 0; j < height; ++j) {
    const double y0 = j * sy, y1 = (j + 1) * sy;
    for (int i = 0; i < width; ++i) {
      const double x0 = i * sx, x1 = (i + 1) * sx;
      for (int c = 0; c < out.components; ++c) {
        double total = 0.0, area = 0.0;
        for (int y = static_cast<int>(y0); y < in.height && y < y1; ++y) {
          const double wy = overlap(y, y0, y1);
          for (int x = static_cast<int>(x0); x < in.width && x < x1; ++x) {
            const double w = wy * overlap(x, x0, x1);
            total += w * in.at(x, y, c);
            area += w;
          }
        }
        const double mean = area > 0.0 ? total / area : 0.0;
        // A small allowance keeps an exact average (255 over a uniform area) from truncating to
        // one less through rounding of the weights.
        out.at(i, j, c) = type == GL_FLOAT ? mean : std::trunc(mean + (mean >= 0 ? 1e-7 : -1e-7));
      }
    }
  }
  return out;
}

// Uploads one level with a tightly packed layout, restoring the caller's unpack state.
void uploadLevel(GLenum target, int dimensions, GLint level, GLint internalFormat, const ClientImage& image,
                 GLenum format, GLenum type) {
  const size_t elementBytes = static_cast<size_t>(bytesOfType(type));
  std::vector<unsigned char> data(image.values.size() * elementBytes);
  for (size_t k = 0; k < image.values.size(); ++k) writeElement(image.values[k], type, &data[k * elementBytes]);
  GLint alignment, rowLength, skipRows, skipPixels, swapBytes;
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
    glTexImage1D(target, level, internalFormat, image.width, 0, format, type, data.data());
  } else {
    glTexImage2D(target, level, internalFormat, image.width, image.height, 0, format, type, data.data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, swapBytes);
}

GLint buildMipmaps(GLenum target, int dimensions, GLint internalFormat, GLsizei width, GLsizei height,
                   GLenum format, GLenum type, const void* data) {
  if (isPackedOrBitmapType(type)) return GLU_INVALID_ENUM;
  if (const GLint error = checkMipmapArguments(format, type); error != 0) return error;
  if (width < 1 || height < 1) return GLU_INVALID_VALUE;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (maxSize < 1) maxSize = 1;
  int newWidth = nearestPowerOfTwo(width);
  int newHeight = dimensions == 2 ? nearestPowerOfTwo(height) : 1;
  while (newWidth > maxSize || newHeight > maxSize) {
    newWidth = std::max(1, newWidth / 2);
    newHeight = std::max(1, newHeight / 2);
  }
  try {
    ClientImage image = readClientImage(width, height, format, type, data);
    if (image.width != newWidth || image.height != newHeight)
      image = scaleImage(image, newWidth, newHeight, type);
    const int levels = std::max(log2OfPowerOfTwo(newWidth), log2OfPowerOfTwo(newHeight));
    for (int level = 0; level <= levels; ++level) {
      if (level > 0) image = halveImage(image, type);
      uploadLevel(target, dimensions, level, internalFormat, image, format, type);
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

// log2 of a power of two, -1 for any other size (GLU's computeLog).
int exactLog2(int value) {
  return value > 0 && (value & (value - 1)) == 0 ? log2OfPowerOfTwo(value) : -1;
}

// gluBuild*MipmapLevels (GLU 1.3): the image is level `level`, already of the size the caller
// wants (no resampling); each further level halves the previous one as above, and the levels
// from base to max are loaded. Every level down to 1 x 1 counts: level + log2 of the larger
// side is the last, and base and max must lie in [level, last].
GLint buildMipmapLevels(GLenum target, int dimensions, GLint internalFormat, GLsizei width,
                        GLsizei height, GLenum format, GLenum type, GLint level, GLint base,
                        GLint max, const void* data) {
  if (isPackedOrBitmapType(type)) return GLU_INVALID_ENUM;
  if (const GLint error = checkMipmapArguments(format, type); error != 0) return error;
  if (width < 1 || height < 1) return GLU_INVALID_VALUE;
  const int last = std::max(exactLog2(width), dimensions == 2 ? exactLog2(height) : -1) + level;
  if (base < 0 || base < level || max < base || last < max) return GLU_INVALID_VALUE;
  try {
    ClientImage image = readClientImage(width, height, format, type, data);
    for (int l = level; l <= max; ++l) {
      if (l > level) image = halveImage(image, type);
      if (l >= base) uploadLevel(target, dimensions, l, internalFormat, image, format, type);
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

// Normalizes a raw element value to [0, 1] (or [-1, 1]) as GL does (table 2.9), and back.
double normalize(double v, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return v / 255.0;
    case GL_BYTE: return (2.0 * v + 1.0) / 255.0;
    case GL_UNSIGNED_SHORT: return v / 65535.0;
    case GL_SHORT: return (2.0 * v + 1.0) / 65535.0;
    case GL_UNSIGNED_INT: return v / 4294967295.0;
    case GL_INT: return (2.0 * v + 1.0) / 4294967295.0;
    default: return v;
  }
}

double denormalize(double c, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return std::nearbyint(std::clamp(c, 0.0, 1.0) * 255.0);
    case GL_BYTE: return std::nearbyint((std::clamp(c, -1.0, 1.0) * 255.0 - 1.0) / 2.0);
    case GL_UNSIGNED_SHORT: return std::nearbyint(std::clamp(c, 0.0, 1.0) * 65535.0);
    case GL_SHORT: return std::nearbyint((std::clamp(c, -1.0, 1.0) * 65535.0 - 1.0) / 2.0);
    case GL_UNSIGNED_INT: return std::nearbyint(std::clamp(c, 0.0, 1.0) * 4294967295.0);
    case GL_INT: return std::nearbyint((std::clamp(c, -1.0, 1.0) * 4294967295.0 - 1.0) / 2.0);
    default: return c;
  }
}

// gluScaleImage works on 16-bit unsigned values, as GLU does: an unsigned byte b is 257 b, a float
// f is 65535 f in single precision (truncated; clamped to [0, 1] first), other types their
// normalized value times 65535, rounded. The result goes back as u >> 8 for bytes, u / 65535 for floats.
uint16_t sixteenBitOf(double raw, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<uint16_t>(raw * 257.0);
    case GL_UNSIGNED_SHORT: return static_cast<uint16_t>(raw);
    case GL_FLOAT: return static_cast<uint16_t>(static_cast<float>(std::clamp(raw, 0.0, 1.0)) * 65535.0f);  // in float
    default: return static_cast<uint16_t>(std::nearbyint(std::clamp(normalize(raw, type), 0.0, 1.0) * 65535.0));
  }
}

double fromSixteenBit(uint16_t u, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return u >> 8;
    case GL_UNSIGNED_SHORT: return u;
    case GL_FLOAT: return u / 65535.0;
    default: return denormalize(u / 65535.0, type);
  }
}

// gluScaleImage's resampling (GLU's, which is not the one its mipmaps use): each output pixel is
// the weighted mean of the source area round its centre (x, y) = ((i + 1/2) w_in / w_out, (j +
// 1/2) h_in / h_out): half an output pixel each way along an axis that shrinks, half a source
// texel along one that grows (so enlarging interpolates linearly between the two nearest
// texels), the source indices wrapping round the image; the mean is (sum + 1/2) / area,
// truncated. An image exactly twice the output size each way is halved by 2 x 2 averages
// (sum + 2) / 4 (halveImage in unsigned shorts). Single precision where GLU computes in it, so
// the same values. The images hold 16-bit values (sixteenBitOf).
ClientImage scaleSixteenBit(const ClientImage& in, int widthOut, int heightOut) {
  if (in.width == 2 * widthOut && in.height == 2 * heightOut) return halveImage(in, GL_UNSIGNED_SHORT);
  ClientImage out;
  out.width = widthOut;
  out.height = heightOut;
  out.components = in.components;
  out.values.resize(static_cast<size_t>(widthOut) * static_cast<size_t>(heightOut) * static_cast<size_t>(out.components));
  const float stepX = static_cast<float>(in.width) / static_cast<float>(widthOut);
  const float stepY = static_cast<float>(in.height) / static_cast<float>(heightOut);
  const float halfX = in.width > widthOut ? stepX / 2 : 0.5f, halfY = in.height > heightOut ? stepY / 2 : 0.5f;
  for (int j = 0; j < heightOut; ++j) {
    const auto centreY = static_cast<float>(stepY * (j + 0.5));
    const float lowY = centreY - halfY, highY = centreY + halfY;
    for (int i = 0; i < widthOut; ++i) {
      const auto centreX = static_cast<float>(stepX * (i + 0.5));
      const float lowX = centreX - halfX, highX = centreX + halfX;
      float totals[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      float area = 0.0f;
      // Unit cells from the box's low corner; the first and last are partly inside.
      float y = lowY;
      for (auto row = static_cast<int>(std::floor(y)); y < highY; y = static_cast<float>(++row)) {
        const float shareY = highY < static_cast<float>(row + 1) ? highY - y : static_cast<float>(row + 1) - y;
        const int sourceRow = ((row % in.height) + in.height) % in.height;
        float x = lowX;
        for (auto column = static_cast<int>(std::floor(x)); x < highX; x = static_cast<float>(++column)) {
          const float shareX = highX < static_cast<float>(column + 1) ? highX - x : static_cast<float>(column + 1) - x;
          const int sourceColumn = ((column % in.width) + in.width) % in.width;
          const float share = shareX * shareY;
          area += share;
          for (int c = 0; c < out.components; ++c)
            totals[c] += static_cast<float>(in.at(sourceColumn, sourceRow, c)) * share;
        }
      }
      for (int c = 0; c < out.components; ++c) out.at(i, j, c) = static_cast<uint16_t>((totals[c] + 0.5) / area);
    }
  }
  return out;
}

}  // namespace

// C linkage whether or not GL/glu.h declares these (programs written in C call them).
extern "C" {

GLint GLAPIENTRY gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format,
                                   GLenum type, const void* data) {
  return buildMipmaps(target, 1, internalFormat, width, 1, format, type, data);
}

GLint GLAPIENTRY gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                   GLenum format, GLenum type, const void* data) {
  return buildMipmaps(target, 2, internalFormat, width, height, format, type, data);
}

GLint GLAPIENTRY gluBuild1DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                        GLenum format, GLenum type, GLint level, GLint base,
                                        GLint max, const void* data) {
  return buildMipmapLevels(target, 1, internalFormat, width, 1, format, type, level, base, max,
                           data);
}

GLint GLAPIENTRY gluBuild2DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                        GLsizei height, GLenum format, GLenum type, GLint level,
                                        GLint base, GLint max, const void* data) {
  return buildMipmapLevels(target, 2, internalFormat, width, height, format, type, level, base,
                           max, data);
}

GLint GLAPIENTRY gluScaleImage(GLenum format, GLsizei widthIn, GLsizei heightIn, GLenum typeIn,
                               const void* dataIn, GLsizei widthOut, GLsizei heightOut, GLenum typeOut,
                               void* dataOut) {
  if (widthIn == 0 || heightIn == 0 || widthOut == 0 || heightOut == 0) return 0;
  if (widthIn < 0 || heightIn < 0 || widthOut < 0 || heightOut < 0) return GLU_INVALID_VALUE;
  if (isPackedOrBitmapType(typeIn) || isPackedOrBitmapType(typeOut)) return GLU_INVALID_ENUM;
  if (checkMipmapArguments(format, typeIn) != 0 || checkMipmapArguments(format, typeOut) != 0)
    return GLU_INVALID_ENUM;
  try {
    ClientImage in = readClientImage(widthIn, heightIn, format, typeIn, dataIn);
    for (double& v : in.values) v = sixteenBitOf(v, typeIn);
    ClientImage out = scaleSixteenBit(in, widthOut, heightOut);
    for (double& v : out.values) v = fromSixteenBit(static_cast<uint16_t>(v), typeOut);
    // The result is written with the GL_PACK_* layout.
    GLint alignment = 4, rowLength = 0, skipRows = 0, skipPixels = 0;
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &rowLength);
    glGetIntegerv(GL_PACK_SKIP_ROWS, &skipRows);
    glGetIntegerv(GL_PACK_SKIP_PIXELS, &skipPixels);
    const size_t elementBytes = static_cast<size_t>(bytesOfType(typeOut));
    const size_t groupBytes = elementBytes * static_cast<size_t>(out.components);
    size_t rowBytes = groupBytes * static_cast<size_t>(rowLength > 0 ? rowLength : widthOut);
    const size_t align = static_cast<size_t>(std::max(alignment, 1));
    if (elementBytes < align) rowBytes = (rowBytes + align - 1) / align * align;
    auto* base = static_cast<unsigned char*>(dataOut) + static_cast<size_t>(skipRows) * rowBytes +
                 static_cast<size_t>(skipPixels) * groupBytes;
    for (int j = 0; j < heightOut; ++j)
      for (int i = 0; i < widthOut; ++i)
        for (int c = 0; c < out.components; ++c)
          writeElement(out.at(i, j, c), typeOut,
                       base + static_cast<size_t>(j) * rowBytes + static_cast<size_t>(i) * groupBytes +
                           static_cast<size_t>(c) * elementBytes);
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

}  // extern "C"
