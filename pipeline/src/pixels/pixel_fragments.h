// Conversion of pixel rectangles and bitmaps to fragments (OpenGL 1.5 specification, sections
// 3.6.5 "Conversion to fragments" and 3.7), and the stencil writes of glDrawPixels and
// glCopyPixels (section 4.3.1), at the current raster position.
//
// Zoom (glPixelZoom): image pixel (n, m) becomes the fragments whose centres lie in the rectangle
// from (x + Z_x n, y + Z_y m) to (x + Z_x (n + 1), y + Z_y (m + 1)). Like Mesa (and SGI's
// implementation before it), glass first rounds the raster position to the nearest pixel corner
// (x, y), so that a raster position a rounding error away from an integer still puts the image
// on the intended pixels; a fragment at window pixel (i, j) then shows image pixel
// (floor((i + 1/2 - x) / Z_x), floor((j + 1/2 - y) / Z_y)), which covers each rectangle's
// lower-left edge and not its upper-right one.
//
// The fragments take the raster position's depth (unless the image gives depths), colour (unless
// the image gives colours), texture coordinates and distance (as the fog coordinate), and go
// through the whole fragment stage: texturing, fog, the scissor, alpha, stencil and depth tests,
// blending, logic op and the masks.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/pixel_store.h"

namespace glass::gl {

struct Context;

// An image of width x height pixels, row 0 at the bottom. colors: 4 floats per pixel in [0, 1],
// or null to use the raster colour; depths: one value per pixel in [0, 1], or null to use the
// raster depth.
struct FragmentImage {
  int width = 0, height = 0;
  // Where pixel (0, 0) of these pixels lies in the rectangle the command drew, in image pixels:
  // glCopyPixels reads only the part of its rectangle inside the framebuffer (the specification
  // leaves the rest undefined) and draws that part where it belongs.
  int column0 = 0, row0 = 0;
  const float* colors = nullptr;
  const float* depths = nullptr;
  const int32_t* stencil = nullptr;  // for drawStencilImage
};

// Draws the image at the current raster position with the current zoom. The caller checked
// that the raster position is valid and that the render mode is GL_RENDER.
void drawImageFragments(Context& ctx, const FragmentImage& image);

// glDrawPixels's fast path (docs/pipeline.md, "Fast paths"): colours of unsigned bytes, without
// zoom, pixel transfer or imaging operations that would change them, drawn by a fragment stage
// that stores colours as they come (FragmentProcessor::storesColorsAsGiven), in GL_RENDER mode at
// a valid raster position. Each visible row's bytes go into the colour buffer directly: the bytes
// the reference path (floats, fragments, conversion back to bytes) writes. Returns false, having
// done nothing, in any other case. Queued drawing must be finished.
bool drawPixelBytes(Context& ctx, const void* pixels, int width, int height, GLenum format, GLenum type,
                    const PixelPacking& unpack);

// Writes stencil indices at the raster position with the zoom: only the scissor test, the
// pixel ownership test and the stencil write mask apply (spec 4.3.1).
void drawStencilImage(Context& ctx, const FragmentImage& image);

// glBitmap's fragments (spec 3.7): one for each set bit (bits: width * height values, 0 or 1,
// row 0 at the bottom), at (x_ll + i, y_ll + j), with the raster colour, depth and texture
// coordinates.
void drawBitmapFragments(Context& ctx, int xll, int yll, int width, int height, const uint8_t* bits);

}  // namespace glass::gl
