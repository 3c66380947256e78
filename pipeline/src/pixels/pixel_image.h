// A pixel rectangle unpacked from client memory (OpenGL 1.5 specification, section 3.6.4), before
// the pixel transfer operations: what glDrawPixels draws, and what a display list keeps of it
// (spec 5.4: client data is unpacked when the command is compiled, with the pixel store state of
// that moment; the transfer state applies when the list is executed).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "core/pixel_store.h"

namespace glass::gl {

struct Context;

enum class PixelKind { Color, ColorIndex, Depth, Stencil };

struct UnpackedImage {
  PixelKind kind = PixelKind::Color;
  int width = 0, height = 0;
  std::vector<float> values;     // Color: RGBA, 4 per pixel; Depth: 1 per pixel; row 0 first
  std::vector<int32_t> indices;  // ColorIndex and Stencil: 1 per pixel
};

// Unpacks a width x height image (format and type passed checkPixelFormatAndType). Throws
// std::bad_alloc when memory runs out.
UnpackedImage unpackImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                          const PixelPacking& unpack);

// glDrawPixels's work at execution (spec 3.6.4-3.6.5, 4.3.1): with a valid raster position, the
// transfer operations and then fragments (or stencil writes) in GL_RENDER mode, a
// GL_DRAW_PIXEL_TOKEN in GL_FEEDBACK mode, nothing in GL_SELECT mode.
void drawPixels(Context& ctx, const UnpackedImage& image);

// glCopyPixels's work (spec 4.3.3) once its errors are checked: type GL_COLOR, GL_DEPTH or
// GL_STENCIL. Source pixels outside the framebuffer (undefined by the specification) read as 0.
void copyPixels(Context& ctx, int x, int y, int width, int height, GLenum type);

// glBitmap's work (spec 3.7) once its errors are checked: bits holds width * height values 0 or
// 1, row 0 first (may be empty when width or height is 0).
void drawBitmap(Context& ctx, int width, int height, float xorig, float yorig, float xmove,
                float ymove, const std::vector<uint8_t>& bits);

}  // namespace glass::gl
