// gluBuild3DMipmaps and gluBuild3DMipmapLevels (GLU 1.3, section 3.2), as the SGI GLU that Mesa
// ships builds them, so that a program hands GL the same levels with glass as with Mesa's libGLU:
//   1. gluBuild3DMipmaps rounds each side to GLU's "nearest" power of two (3 * 2^k up to 4 * 2^k,
//      anything else down), all three halved further while one exceeds GL_MAX_3D_TEXTURE_SIZE;
//      an image of another size is resampled to it in GLU's 16-bit values (its gluScaleImage3D:
//      the box filter of client_image.h, then back to the client type).
//   2. Every further level halves the previous one: with more than one image, the mean of 2 x 2 x
//      2 texels in double precision (of 2 x 2 across the images when a side is 1 texel long, of 2
//      when both are), truncated for integer types; with one image, GLU's 2D halving in the
//      client type. Each level is loaded with glTexImage3D in the client's format and type.
// gluBuild3DMipmapLevels takes the image as level `level` (sides powers of two) and loads the
// levels from base to max. The arguments are checked as GLU checks them (GLU_INVALID_VALUE for a
// size below 1 or levels out of order, GLU_INVALID_ENUM for a target other than GL_TEXTURE_3D or
// an unknown format or type; the packed types are not taken, as in 1D and 2D).
#include <GL/gl.h>
#include <GL/glu.h>

#include "glu/client_image.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace {

using namespace glass::glu;  // NOLINT(google-build-using-namespace): the shared GLU pieces

GLint check3DArguments(GLenum target, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type) {
  if (width < 1 || height < 1 || depth < 1) return GLU_INVALID_VALUE;
  if (target != GL_TEXTURE_3D || checkMipmapArguments(format, type) != 0) return GLU_INVALID_ENUM;
  return 0;
}

// What GLU stores for a mean of its 3D halving: integer types truncate it, floats round it to
// single precision.
double storedMean(double mean, GLenum type) {
  return type == GL_FLOAT ? static_cast<double>(static_cast<float>(mean)) : std::trunc(mean);
}

// GLU's halving of a 3D image (halveImage3D and halveImageSlice; one image: its 2D halving).
ClientImage halveImage3D(const ClientImage& in, GLenum type) {
  if (in.depth == 1) return halveImage(in, type);
  ClientImage out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.depth = in.depth / 2;
  out.components = in.components;
  out.values.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) *
                    static_cast<size_t>(out.depth) * static_cast<size_t>(out.components));
  // The texels averaged, in GLU's order: along x, then y, then z; a side 1 texel long is not halved.
  const int stepsX = in.width > 1 ? 2 : 1, stepsY = in.height > 1 ? 2 : 1;
  for (int k = 0; k < out.depth; ++k)
    for (int j = 0; j < out.height; ++j)
      for (int i = 0; i < out.width; ++i)
        for (int c = 0; c < out.components; ++c) {
          double sum = 0.0;
          int count = 0;
          for (int z = 0; z < 2; ++z)
            for (int y = 0; y < stepsY; ++y)
              for (int x = 0; x < stepsX; ++x, ++count)
                sum += in.at(stepsX * i + x, stepsY * j + y, 2 * k + z, c);
          out.at(i, j, k, c) = storedMean(sum / count, type);
        }
  return out;
}

// The levels `level` to `max` from the client image, resampled first to the given powers of two
// when it has another size; the levels from `base` on are loaded.
GLint buildLevels(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLsizei depth, int widthOut,
                  int heightOut, int depthOut, GLenum format, GLenum type, GLint level, GLint base, GLint max,
                  const void* data) {
  try {
    ClientImage image = readClientImage(3, width, height, depth, format, type, data);
    if (width != widthOut || height != heightOut || depth != depthOut) {
      const bool index = isIndexFormat(format);
      for (double& value : image.values) value = sixteenBitOf(value, type, index);
      image = scaleSixteenBit(image, widthOut, heightOut, depthOut);
      for (double& value : image.values) value = fromSixteenBit(static_cast<uint16_t>(value), type, index);
    }
    for (GLint l = level; l <= max; ++l) {
      if (l > level) image = halveImage3D(image, type);
      if (l >= base) uploadLevel(target, 3, l, internalFormat, image, format, type);
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

}  // namespace

extern "C" {

GLint GLAPIENTRY gluBuild3DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLsizei depth,
                                   GLenum format, GLenum type, const void* data) {
  if (const GLint error = check3DArguments(target, width, height, depth, format, type)) return error;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  maxSize = std::max(maxSize, 1);
  int widthOut = nearestPowerOfTwo(width), heightOut = nearestPowerOfTwo(height), depthOut = nearestPowerOfTwo(depth);
  while (widthOut > maxSize || heightOut > maxSize || depthOut > maxSize) {
    widthOut = std::max(1, widthOut / 2);
    heightOut = std::max(1, heightOut / 2);
    depthOut = std::max(1, depthOut / 2);
  }
  const int levels =
      std::max({log2OfPowerOfTwo(widthOut), log2OfPowerOfTwo(heightOut), log2OfPowerOfTwo(depthOut)});
  return buildLevels(target, internalFormat, width, height, depth, widthOut, heightOut, depthOut, format, type, 0, 0,
                     levels, data);
}

GLint GLAPIENTRY gluBuild3DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                        GLsizei depth, GLenum format, GLenum type, GLint level, GLint base,
                                        GLint max, const void* data) {
  if (const GLint error = check3DArguments(target, width, height, depth, format, type)) return error;
  const int last = std::max({exactLog2(width), exactLog2(height), exactLog2(depth)}) + level;
  if (base < 0 || base < level || max < base || last < max) return GLU_INVALID_VALUE;
  return buildLevels(target, internalFormat, width, height, depth, width, height, depth, format, type, level, base,
                     max, data);
}

}  // extern "C"
