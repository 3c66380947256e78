// The pixel transfer operations on texture images. OpenGL 1.4, section 3.8.1: the groups of
// glTexImage are "processed exactly as for DrawPixels" up to the final clamp; section 3.8.2: those
// of glCopyTexImage and glCopyTexSubImage as for CopyPixels. That is scale and bias
// (glPixelTransfer), the GL_MAP_COLOR lookups (glPixelMap) and, with the imaging subset
// (pixels/imaging_pipeline.h), colour tables, convolution, the colour matrix, histogram and
// minmax. Convolution filters apply to one- and two-dimensional images only (section 3.6.5:
// the 1D filter to glTexImage1D, the 2D and separable ones to two-dimensional images), so a
// three-dimensional image is never convolved.
//
// Texture images take this path only when some operation would change a group or count it
// (textureTransferActive); otherwise they are unpacked straight to texels as before, at no cost.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "pixels/rgba_image.h"
#include "texture/client_pixels.h"
#include "texture/texture_image.h"

namespace glass::gl {

struct Context;

// Whether a colour texture image specified now would go through any pixel transfer operation.
bool textureTransferActive(const Context& ctx);

// Unpacks the client colour groups of a width x height x depth block (depth 1 unless
// dimensions is 3) to RGBA floats, slice after slice: a width x (height * depth) image.
RgbaImage unpackColorGroups(const void* pixels, int dimensions, int width, int height, int depth,
                            GLenum format, GLenum type, const PixelLayout& layout);

// The colour buffer's RGBA at window (x, y) as floats; pixels outside the window read as zero
// (the specification leaves them undefined).
void readFramebufferColor(const Context& ctx, int x, int y, float rgba[4]);

// The colour buffer's groups of the width x height rectangle at window (x, y).
RgbaImage readFramebufferGroups(const Context& ctx, int x, int y, int width, int height);

// Applies the pixel transfer operations to the groups of a `dimensions`-dimensional image (3: a
// stack of slices, never convolved). A GL_REDUCE convolution makes a 1D or 2D image smaller.
// Returns false when a histogram or minmax sink took the groups: no texel is to be written.
bool transferTextureGroups(Context& ctx, int dimensions, RgbaImage& groups);

// The texels of base format `base` (texture_image.h) of every group, row after row.
void storeTexelGroups(const RgbaImage& groups, BaseFormat base, std::vector<uint8_t>& texels);

}  // namespace glass::gl
