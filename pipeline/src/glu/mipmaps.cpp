// GLU mipmaps: gluBuild1DMipmaps, gluBuild2DMipmaps, their *Levels forms and gluScaleImage,
// built on the GL API.
//
// They follow the algorithm of the SGI GLU that Mesa ships, so that a program's mipmaps come out
// the same with glass as with Mesa's libGLU:
//   1. The image size is rounded to the nearest power of two per axis (3 * 2^k rounds up to
//      4 * 2^k, otherwise down), halved further while it exceeds GL_MAX_TEXTURE_SIZE.
//   2. Level 0 is the image itself when its size already is that power of two; otherwise the
//      image is resampled to it by a box filter: each new texel averages the source area it
//      covers, partial texels weighted by the share covered, in GLU's single-precision steps.
//   3. Every further level halves the previous one with a 2 x 2 box filter, in the arithmetic of
//      the client type: for unsigned bytes (a + b + c + d + 2) / 4; along an axis that is already
//      1 texel long the filter is 2 x 1, (a + b) / 2.
// Every 2D level is handed to glTexImage in the client's own format and type. The 1D builders
// work as gluScaleImage does, in 16-bit values, and load GL_UNSIGNED_SHORT levels (as GLU does).
// The packed pixel types and GL_BITMAP are not accepted (GLU_INVALID_ENUM).
#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <utility>
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

// The formats whose values GLU takes as they are, not as colours.
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

// The value GLU stores for a box filter's result `mean` (single precision) in the client type:
// integer types truncate towards zero, unsigned ints clamp at their largest value.
double storedScaledValue(float mean, GLenum type) {
  switch (type) {
    case GL_FLOAT: return mean;
    case GL_UNSIGNED_INT: return mean >= static_cast<float>(UINT32_MAX) ? UINT32_MAX : std::trunc(mean);
    default: return std::trunc(mean);
  }
}

// Box-filter resampling to any size as gluBuild*Mipmaps does it (GLU's scale_internal_<type>):
// each output texel averages the source area it covers, partial texels weighted by the share
// covered, the sum divided by the box's area. The box's edges step along the source by the
// ratio's whole and fractional parts, and every operation is GLU's, in single precision and in
// its order (first and last rows, first and last columns, then the inside), so that the values
// come out as libGLU's to the bit. An image exactly twice the size each way is halved instead.
ClientImage scaleImage(const ClientImage& in, int width, int height, GLenum type) {
  if (in.width == 2 * width && in.height == 2 * height) return halveImage(in, type);
  ClientImage out;
  out.width = width;
  out.height = height;
  out.components = in.components;
  out.values.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(out.components));
  const float ratioY = static_cast<float>(in.height) / static_cast<float>(height);
  const float ratioX = static_cast<float>(in.width) / static_cast<float>(width);
  const int wholeY = static_cast<int>(std::floor(ratioY)), wholeX = static_cast<int>(std::floor(ratioX));
  const float fractionY = ratioY - static_cast<float>(wholeY), fractionX = ratioX - static_cast<float>(wholeX);
  const float area = ratioX * ratioY;
  // A box edge steps to the next texel when its fraction passes 1 (GLU's test, strictly above).
  auto step = [](int& whole, float& fraction, int wholeStep, float fractionStep) {
    whole += wholeStep;
    fraction += fractionStep;
    if (fraction > 1.0f) {
      fraction -= 1.0f;
      ++whole;
    }
  };
  const int components = in.components;
  // A box edge that ends exactly on the image's far side names the texel past it, with weight 0:
  // read the last one instead.
  auto texel = [&](int x, int y, int c) {
    return static_cast<float>(in.at(std::min(x, in.width - 1), std::min(y, in.height - 1), c));
  };
  int lowY = 0, highY = wholeY;
  float lowYFraction = 0.0f, highYFraction = fractionY;
  for (int j = 0; j < height; ++j) {
    int lowX = 0, highX = wholeX;
    float lowXFraction = 0.0f, highXFraction = fractionX;
    for (int i = 0; i < width; ++i) {
      float totals[4] = {};
      auto add = [&](int x, int y, float weight) {
        for (int c = 0; c < components; ++c) totals[c] += texel(x, y, c) * weight;
      };
      if (highY > lowY && highX > lowX) {  // the box spans several rows and columns
        float rowShare = 1.0f - lowYFraction;
        add(lowX, lowY, rowShare * (1.0f - lowXFraction));
        for (int x = lowX + 1; x < highX; ++x) add(x, lowY, rowShare);
        add(highX, lowY, rowShare * highXFraction);
        rowShare = highYFraction;
        add(lowX, highY, rowShare * (1.0f - lowXFraction));
        for (int x = lowX + 1; x < highX; ++x) add(x, highY, rowShare);
        add(highX, highY, rowShare * highXFraction);
        for (int y = lowY + 1; y < highY; ++y)
          for (int c = 0; c < components; ++c)
            totals[c] += texel(lowX, y, c) * (1.0f - lowXFraction) + texel(highX, y, c) * highXFraction;
      } else if (highY > lowY) {  // one column, several rows
        const float columnShare = highXFraction - lowXFraction;
        add(lowX, lowY, (1.0f - lowYFraction) * columnShare);
        for (int y = lowY + 1; y < highY; ++y) add(lowX, y, columnShare);
        add(lowX, highY, columnShare * highYFraction);
      } else if (highX > lowX) {  // one row, several columns
        const float rowShare = highYFraction - lowYFraction;
        add(lowX, lowY, (1.0f - lowXFraction) * rowShare);
        for (int x = lowX + 1; x < highX; ++x) add(x, lowY, rowShare);
        add(highX, lowY, rowShare * highXFraction);
      } else {  // inside one texel
        add(lowX, lowY, (highYFraction - lowYFraction) * (highXFraction - lowXFraction));
      }
      for (int y = lowY + 1; y < highY; ++y)  // the texels wholly inside
        for (int x = lowX + 1; x < highX; ++x)
          for (int c = 0; c < components; ++c) totals[c] += texel(x, y, c);
      for (int c = 0; c < components; ++c) out.at(i, j, c) = storedScaledValue(totals[c] / area, type);
      lowX = highX;
      lowXFraction = highXFraction;
      step(highX, highXFraction, wholeX, fractionX);
    }
    lowY = highY;
    lowYFraction = highYFraction;
    step(highY, highYFraction, wholeY, fractionY);
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

// The 1D mipmaps as GLU builds them (unlike its 2D ones, in gluScaleImage's arithmetic): the
// client image converted to 16-bit values (sixteenBitOf), each level from `level` to `max`
// resampled from the one before to `width` halved level by level (scaleSixteenBit), the levels
// from `base` on loaded as GL_UNSIGNED_SHORT.
void loadOneDimensionalLevels(GLenum target, GLint internalFormat, ClientImage image, GLenum format, GLenum type,
                              int width, GLint level, GLint base, GLint max) {
  for (double& value : image.values) value = sixteenBitOf(value, type, isIndexFormat(format));
  for (GLint l = level; l <= max; ++l) {
    if (image.width != width) image = scaleSixteenBit(image, width, 1);
    if (l >= base) uploadLevel(target, 1, l, internalFormat, image, format, GL_UNSIGNED_SHORT);
    width = std::max(1, width / 2);
  }
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
    const int levels = std::max(log2OfPowerOfTwo(newWidth), log2OfPowerOfTwo(newHeight));
    if (dimensions == 1) {
      loadOneDimensionalLevels(target, internalFormat, std::move(image), format, type, newWidth, 0, 0, levels);
      return 0;
    }
    if (image.width != newWidth || image.height != newHeight)
      image = scaleImage(image, newWidth, newHeight, type);
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
    if (dimensions == 1) {
      loadOneDimensionalLevels(target, internalFormat, std::move(image), format, type, width, level, base, max);
      return 0;
    }
    for (int l = level; l <= max; ++l) {
      if (l > level) image = halveImage(image, type);
      if (l >= base) uploadLevel(target, dimensions, l, internalFormat, image, format, type);
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
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
    for (double& v : in.values) v = sixteenBitOf(v, typeIn, isIndexFormat(format));
    ClientImage out = scaleSixteenBit(in, widthOut, heightOut);
    for (double& v : out.values) v = fromSixteenBit(static_cast<uint16_t>(v), typeOut, isIndexFormat(format));
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
