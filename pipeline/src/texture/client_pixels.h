// Reading texel data from client memory (glTexImage, glTexSubImage: "unpacking", OpenGL 1.5
// specification, section 3.6.4) and writing it back (glGetTexImage: "packing", section 4.3.2),
// with the format/type combinations of tables 3.5 to 3.8 and the glPixelStore layout parameters.
//
// Pixel transfer operations (glPixelTransfer scale and bias, glPixelMap) are not applied: glass
// keeps them at their defaults, where they change nothing.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "texture/texture_image.h"

namespace glass::gl {

// The glPixelStore parameters of one direction (GL_UNPACK_* or GL_PACK_*).
struct PixelLayout {
  int alignment = 4;   // 1, 2, 4 or 8
  int rowLength = 0;   // 0: rows are as long as the image
  int skipRows = 0;
  int skipPixels = 0;
  bool swapBytes = false;
};

// Checks a format/type pair for texture images. Returns GL_NO_ERROR, GL_INVALID_ENUM (a format or
// type that is not one of the GL's, or one textures do not take: COLOR_INDEX, STENCIL_INDEX,
// DEPTH_COMPONENT, BITMAP) or GL_INVALID_OPERATION (a packed type whose component count does not
// match the format, table 3.8).
GLenum checkTexelFormatAndType(GLenum format, GLenum type);

// Converts a width x height block of client pixels to texels of the given base format, row 0
// first, 4 bytes per texel in the layout of texture_image.h (spec 3.6.4: unpack, convert to
// floating point by table 2.9, expand luminance to RGB, fill the missing components with
// R = G = B = 0, A = 1; then section 3.8.1: keep the components of the base internal format).
// format and type must have passed checkTexelFormatAndType.
void unpackTexels(const void* pixels, int width, int height, GLenum format, GLenum type,
                  const PixelLayout& layout, BaseFormat base, std::vector<uint8_t>& texels);

// Writes row `row` of a block `width` pixels wide to client memory in format/type, from `width`
// RGBA floats (spec 4.3.2: clamp to [0, 1], keep the components the format names, luminance is
// R).
void packPixelRow(const float* rgba, int width, int row, GLenum format, GLenum type,
                  const PixelLayout& layout, void* pixels);

}  // namespace glass::gl
