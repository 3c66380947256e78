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
// The packed pixel types and GL_BITMAP are not accepted (GLU_INVALID_ENUM). Images of unsigned
// bytes that need no resampling are halved on their bytes (glu/byte_mipmaps.h, a fast path).
#include <GL/gl.h>
#include <GL/glu.h>

#include "core/fast_paths.h"
#include "glu/byte_mipmaps.h"
#include "glu/client_image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace {

using namespace glass::glu;  // NOLINT(google-build-using-namespace): the shared GLU pieces

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

// The 1D mipmaps as GLU builds them (unlike its 2D ones, in gluScaleImage's arithmetic): the
// client image converted to 16-bit values (sixteenBitOf), each level from `level` to `max`
// resampled from the one before to `width` halved level by level (scaleSixteenBit), the levels
// from `base` on loaded as GL_UNSIGNED_SHORT.
void loadOneDimensionalLevels(GLenum target, GLint internalFormat, ClientImage image, GLenum format, GLenum type,
                              int width, GLint level, GLint base, GLint max) {
  for (double& value : image.values) value = sixteenBitOf(value, type, isIndexFormat(format));
  for (GLint l = level; l <= max; ++l) {
    if (image.width != width) image = scaleSixteenBit(image, width, 1, 1);
    if (l >= base) uploadLevel(target, 1, l, internalFormat, image, format, GL_UNSIGNED_SHORT);
    width = std::max(1, width / 2);
  }
}

// The 2D mipmaps from `image`, which is level `level`: each level to `max` halves the one before
// (halveImage, in GLU's arithmetic for `type`), and the levels from `base` on are loaded.
void loadTwoDimensionalLevels(GLenum target, GLint internalFormat, ClientImage image, GLenum format, GLenum type,
                              GLint level, GLint base, GLint max) {
  for (GLint l = level; l <= max; ++l) {
    if (l > level) image = halveImage(image, type);
    if (l >= base) uploadLevel(target, 2, l, internalFormat, image, format, type);
  }
}

// Whether the 2D levels of an image of `type` are made by the fast path on bytes
// (glu/byte_mipmaps.h) rather than by halveImage.
bool takesByteLevels(int dimensions, GLenum type) {
  return dimensions == 2 && type == GL_UNSIGNED_BYTE && glass::gl::fastPathsEnabled();
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
    const int levels = std::max(log2OfPowerOfTwo(newWidth), log2OfPowerOfTwo(newHeight));
    if (takesByteLevels(dimensions, type) && width == newWidth && height == newHeight) {
      loadByteLevels(target, internalFormat, width, height, format, data, 0, 0, levels);
      return 0;
    }
    ClientImage image = readClientImage(dimensions, width, height, 1, format, type, data);
    if (dimensions == 1) {
      loadOneDimensionalLevels(target, internalFormat, std::move(image), format, type, newWidth, 0, 0, levels);
      return 0;
    }
    if (image.width != newWidth || image.height != newHeight)
      image = scaleImage(image, newWidth, newHeight, type);
    loadTwoDimensionalLevels(target, internalFormat, std::move(image), format, type, 0, 0, levels);
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
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
    if (takesByteLevels(dimensions, type)) {
      loadByteLevels(target, internalFormat, width, height, format, data, level, base, max);
      return 0;
    }
    ClientImage image = readClientImage(dimensions, width, height, 1, format, type, data);
    if (dimensions == 1) {
      loadOneDimensionalLevels(target, internalFormat, std::move(image), format, type, width, level, base, max);
      return 0;
    }
    loadTwoDimensionalLevels(target, internalFormat, std::move(image), format, type, level, base, max);
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
    ClientImage in = readClientImage(2, widthIn, heightIn, 1, format, typeIn, dataIn);
    for (double& v : in.values) v = sixteenBitOf(v, typeIn, isIndexFormat(format));
    // GLU halves an image exactly twice the output size each way by 2 x 2 means (sum + 2) / 4.
    ClientImage out = in.width == 2 * widthOut && in.height == 2 * heightOut
                          ? halveImage(in, GL_UNSIGNED_SHORT)
                          : scaleSixteenBit(in, widthOut, heightOut, 1);
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
