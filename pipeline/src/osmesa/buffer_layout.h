// The caller's buffer of an OSMesa context: which format and type pairs it may have, and the
// copies between it and glass's RGBA8 colour buffer.
//
// OSMesa's buffer formats (include/GL/osmesa.h) name the order of the components in memory:
// OSMESA_RGBA, _BGRA, _ARGB with 4 components, OSMESA_RGB and _BGR with 3, each with components of
// GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_FLOAT; OSMESA_RGB_565 packs a pixel into one
// GL_UNSIGNED_SHORT_5_6_5 (red in the high 5 bits). glass's colour buffer keeps 8 bits per
// component, so a 16-bit component receives c * 257 and a float c / 255, exactly c / 255 of the
// full scale (spec 2.14.9's conversion of unsigned normalized values).
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "glass/raster/framebuffer.h"

namespace glass::osmesa {

// True for the OSMesa formats a context may be created with.
bool isBufferFormat(GLenum format);
// True when a buffer of this format may have components of this type (OSMesaMakeCurrent).
bool acceptsType(GLenum format, GLenum type);
// True for the formats with an alpha component (OSMESA_RGBA, _BGRA, _ARGB): a context of
// another format has no alpha bitplanes (GL_ALPHA_BITS 0), as in Mesa.
bool formatHasAlpha(GLenum format);

struct BufferLayout {
  GLenum format = 0;
  GLenum type = 0;
  int width = 0, height = 0;
  int rowLength = 0;  // pixels from one row to the next: OSMESA_ROW_LENGTH, or the width
  bool yUp = true;    // OSMESA_Y_UP: the buffer's first row is the bottom one
};

// Bytes of one pixel of the layout's format and type.
std::size_t bytesPerPixel(GLenum format, GLenum type);

// RGBA8 pixels of the layout's size, bottom row first (the framebuffer's colour buffer, or a
// teaching view's picture) -> buffer, every pixel.
void storeColorBuffer(const uint8_t* rgba, const BufferLayout& layout, void* buffer);
// buffer -> framebuffer, every pixel, rounding to 8 bits; a format without alpha gives alpha 1.
void loadColorBuffer(const void* buffer, const BufferLayout& layout,
                     raster::Framebuffer& framebuffer);

}  // namespace glass::osmesa
