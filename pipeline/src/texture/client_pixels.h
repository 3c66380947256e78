// Reading pixel data from client memory ("unpacking", OpenGL 1.5 specification, section 3.6.4)
// and writing it back ("packing", section 4.3.2), with the format/type combinations of tables 3.5
// to 3.8 and the glPixelStore layout parameters. Texture images (glTexImage, glGetTexImage), pixel
// rectangles (glDrawPixels, glReadPixels), bitmaps (glBitmap, glPolygonStipple) all read and write
// client memory through these functions.
//
// Pixel transfer operations (glPixelTransfer, glPixelMap) are not applied here: they act on the
// unpacked values (pixels/pixel_transfer.h; for texture images texture/texture_pixel_transfer.h).
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/pixel_store.h"
#include "texture/texture_image.h"

namespace glass::gl {

// The glPixelStore parameters of one direction (GL_UNPACK_* or GL_PACK_*).
using PixelLayout = PixelPacking;

// Checks a format/type pair for texture images. Returns GL_NO_ERROR, GL_INVALID_ENUM (a format or
// type that is not one of the GL's, or one textures do not take: COLOR_INDEX, STENCIL_INDEX,
// DEPTH_COMPONENT, BITMAP) or GL_INVALID_OPERATION (a packed type whose component count does not
// match the format, table 3.8).
GLenum checkTexelFormatAndType(GLenum format, GLenum type);

// The same for the data of glTexImage and glTexSubImage, which may also be colour indices
// (OpenGL 1.4, section 3.8.1: the groups are processed as for DrawPixels, where an index becomes
// RGBA through the GL_PIXEL_MAP_I_TO_* maps), GL_BITMAP included (section 3.6.4).
GLenum checkTexImageFormatAndType(GLenum format, GLenum type);

// The layout of slice `slice` of a 3D image of `height` rows (spec 3.8.1: slices are
// GL_UNPACK_IMAGE_HEIGHT rows apart, or `height` when that is 0, after GL_UNPACK_SKIP_IMAGES
// slices).
PixelLayout sliceLayout(const PixelLayout& layout, int height, int slice);

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

// The format and type checks of glDrawPixels and glReadPixels (spec 3.6.4, 4.3.2; tables 3.5,
// 3.6 and 3.8). Returns GL_INVALID_ENUM for a format or type that is not the GL's, or GL_BITMAP
// with a format other than GL_COLOR_INDEX and GL_STENCIL_INDEX, and GL_INVALID_OPERATION for a
// packed type whose components do not match the format (table 3.8).
GLenum checkPixelFormatAndType(GLenum format, GLenum type);

// GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA, GL_LUMINANCE,
// GL_LUMINANCE_ALPHA.
bool isColorFormat(GLenum format);

// Unpacking, one row of a width-pixel block at a time (row 0 first; spec 3.6.4):
// Colour formats to RGBA floats, 4 per pixel: elements converted by table 2.9, luminance copied
// to R, G and B, missing components R, G, B = 0 and A = 1.
void unpackColorRow(const void* pixels, int width, int row, GLenum format, GLenum type,
                    const PixelLayout& layout, float* rgba);
// GL_DEPTH_COMPONENT: one value per pixel, converted like a colour component (table 2.9).
void unpackDepthRow(const void* pixels, int width, int row, GLenum type, const PixelLayout& layout,
                    float* depth);
// GL_COLOR_INDEX and GL_STENCIL_INDEX: integers as given (floats truncated), GL_BITMAP one bit
// each (spec 3.6.4, "Unpacking of bitmaps", honouring GL_UNPACK_LSB_FIRST).
void unpackIndexRow(const void* pixels, int width, int row, GLenum type, const PixelLayout& layout,
                    int32_t* indices);

// Packing. A span of count pixels starting at column `column` of row `row` of a block `width`
// pixels wide: the pixels outside the span are left as they are in client memory.
// How luminance is formed from RGBA: R alone (glGetTexImage, table 6.1), or R + G + B clamped to
// [0, 1] (glReadPixels, spec 4.3.2).
enum class LuminancePacking { Red, Sum };
// rgba: 4 floats per pixel, clamped to [0, 1] and converted by table 4.7.
void packColorSpan(const float* rgba, int count, int width, int column, int row, GLenum format,
                   GLenum type, const PixelLayout& layout, LuminancePacking luminance, void* pixels);
// packColorSpan for colours that are bytes b read as b / 255 (a colour buffer read without
// transfer operations), when the result is the bytes themselves: GL_UNSIGNED_BYTE and a format
// without luminance. Writes the span and returns true then; returns false (nothing written)
// otherwise. rgba8: 4 bytes per pixel. The unit test pack_byte_color_span_matches_floats shows it
// writes what packColorSpan writes for every byte value, format and layout it takes.
bool packByteColorSpan(const uint8_t* rgba8, int count, int width, int column, int row, GLenum format,
                       GLenum type, const PixelLayout& layout, void* pixels);
// The bytes of the colours unpackColorRow gives, each component converted to the colour buffer's
// 8 bits (floatToColorByte), for unsigned bytes (which are b / 255 and convert back to b): `count`
// groups from column `column` of row `row`, 4 bytes each in RGBA order into rgba8 (luminance into
// red, green and blue; a missing colour component 0, a missing alpha 255). Returns false, having
// written nothing, for other types. The unit test unpack_byte_color_span_matches_floats compares
// it with the conversion of unpackColorRow's floats for every byte value, format and layout.
bool unpackByteColorSpan(const void* pixels, int count, int width, int column, int row, GLenum format,
                         GLenum type, const PixelLayout& layout, uint8_t* rgba8);
// glGetHistogram's counts (OpenGL 1.4 specification, section 6.1.9, "Histogram Query"): a
// one-row block of `count` groups, 4 counts each in RGBA order (luminance from R), written as
// numbers, not normalized: each saturated to its type's range (its field's for packed types).
void packCountSpan(const uint32_t* counts, int count, GLenum format, GLenum type,
                   const PixelLayout& layout, void* pixels);
// GL_DEPTH_COMPONENT: values clamped to [0, 1] and converted by table 4.7.
void packDepthSpan(const float* depth, int count, int width, int column, int row, GLenum type,
                   const PixelLayout& layout, void* pixels);
// GL_STENCIL_INDEX and GL_COLOR_INDEX: integers masked to the type's width; GL_BITMAP writes bit
// 0 of each index.
void packIndexSpan(const uint32_t* indices, int count, int width, int column, int row, GLenum type,
                   const PixelLayout& layout, void* pixels);

}  // namespace glass::gl
