// What GLU's mipmap builders and gluScaleImage share (mipmaps.cpp, mipmaps_3d.cpp): client
// images read with the GL_UNPACK_* layout as raw element values, GLU's argument checks and size
// rounding, its 2 x 2 halving in each client type, its 16-bit working values and their box
// filter, and the upload of a level.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glass::glu {

int componentsOfFormat(GLenum format);  // 0 for a format GLU does not take
int bytesOfType(GLenum type);           // 0 for a packed type or GL_BITMAP
// The formats whose values GLU takes as they are, not as colours.
bool isIndexFormat(GLenum format);
bool isPackedOrBitmapType(GLenum type);
// GLU's argument check: 0 or a GLU error code.
GLint checkMipmapArguments(GLenum format, GLenum type);
// GLU's "nearest power of two": 3 * 2^k goes up to 4 * 2^k, everything else down.
int nearestPowerOfTwo(int value);
int log2OfPowerOfTwo(int value);
// log2 of a power of two, -1 for any other size (GLU's computeLog).
int exactLog2(int value);

// A client image as raw element values (not normalized), tightly packed: texel (i, j, k) is at
// ((k height + j) width + i) components, row 0 of image 0 first.
struct ClientImage {
  int width = 0, height = 0, depth = 1, components = 0;
  std::vector<double> values;
  std::size_t indexOf(int i, int j, int k, int c) const {
    return ((static_cast<std::size_t>(k) * static_cast<std::size_t>(height) + static_cast<std::size_t>(j)) *
                static_cast<std::size_t>(width) +
            static_cast<std::size_t>(i)) *
               static_cast<std::size_t>(components) +
           static_cast<std::size_t>(c);
  }
  double& at(int i, int j, int c) { return values[indexOf(i, j, 0, c)]; }
  double at(int i, int j, int c) const { return values[indexOf(i, j, 0, c)]; }
  double& at(int i, int j, int k, int c) { return values[indexOf(i, j, k, c)]; }
  double at(int i, int j, int k, int c) const { return values[indexOf(i, j, k, c)]; }
};

// Where the elements of a client image lie with the current GL_UNPACK_* layout (spec 3.6.4; for
// 3 dimensions also GL_UNPACK_IMAGE_HEIGHT and GL_UNPACK_SKIP_IMAGES, 3.8.1): component c of
// texel (i, j, k) starts at first + k imageBytes + j rowBytes + i groupBytes + c elementBytes.
struct ClientLayout {
  const unsigned char* first = nullptr;
  std::size_t elementBytes = 0, groupBytes = 0, rowBytes = 0, imageBytes = 0;
  bool swapBytes = false;  // GL_UNPACK_SWAP_BYTES, for elements of more than one byte
};
ClientLayout clientLayout(int dimensions, int width, int height, GLenum format, GLenum type, const void* data);

// Reads the client image with the current GL_UNPACK_* layout (spec 3.6.4; for 3 dimensions also
// GL_UNPACK_IMAGE_HEIGHT and GL_UNPACK_SKIP_IMAGES, 3.8.1).
ClientImage readClientImage(int dimensions, int width, int height, int depth, GLenum format, GLenum type,
                            const void* data);

// Writes a raw element value as `type` (C's conversion: integer types truncate).
void writeElement(double value, GLenum type, unsigned char* destination);

// GLU's halving of a 2D image (one of depth 1) in the arithmetic of each client type: 2 x 2
// averages, 2 x 1 once a side is 1 texel long.
ClientImage halveImage(const ClientImage& in, GLenum type);

// GLU's 16-bit working values (its fill_image and empty_image) and back.
uint16_t sixteenBitOf(double raw, GLenum type, bool index);
double fromSixteenBit(uint16_t u, GLenum type, bool index);

// GLU's box filter on 16-bit values (its scale_internal, and scaleInternal3D with a depth).
ClientImage scaleSixteenBit(const ClientImage& in, int widthOut, int heightOut, int depthOut);

// Loads one level, tightly packed, with glTexImage1D/2D/3D, restoring the caller's unpack state:
// from raw element values written as `type`, or from elements already so written.
void uploadLevel(GLenum target, int dimensions, GLint level, GLint internalFormat, const ClientImage& image,
                 GLenum format, GLenum type);
void uploadPackedLevel(GLenum target, int dimensions, GLint level, GLint internalFormat, int width, int height,
                       int depth, GLenum format, GLenum type, const void* data);

}  // namespace glass::glu
