// Depth textures (OpenGL 1.4 specification, sections 3.8.1 and 3.8.4; GL_ARB_depth_texture):
// images of base internal format DEPTH_COMPONENT, one depth value per texel, specified from
// client memory with format GL_DEPTH_COMPONENT or copied from the depth buffer. How they are
// sampled and compared is texture/depth_comparison.h.
//
// An image keeps its depths as floats in [0, 1] at the resolution of its internal format
// (DEPTH_COMPONENT16: 16 bits; DEPTH_COMPONENT, DEPTH_COMPONENT24 and DEPTH_COMPONENT32: 24 bits,
// the depth buffer's), see TextureImage::depths. Until then, unpacked client depths travel in
// the 4-byte texel slots as the bits of a float, so that the border stripping and display list
// code written for colour texels carries them unchanged.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "texture/client_pixels.h"
#include "texture/texture_image.h"

namespace glass::gl {

// GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32.
bool isDepthInternalFormat(GLint internalFormat);
// The bits glass keeps per depth texel of a depth internal format (GL_TEXTURE_DEPTH_SIZE).
int depthBitsOfInternalFormat(GLint internalFormat);

// The texture targets that take depth images (spec 3.8.1: TEXTURE_1D, TEXTURE_2D and their
// proxies; any other target with a depth format is an INVALID_OPERATION error).
bool takesDepthImages(GLenum target);

// Unpacks a width x height block of GL_DEPTH_COMPONENT client pixels: each value converted by
// table 2.9, then scaled and biased by GL_DEPTH_SCALE/GL_DEPTH_BIAS and clamped to [0, 1]
// (spec 3.6.4 and 3.8.1), stored as float bits in 4 bytes per texel, row 0 first.
void unpackDepthTexels(const void* pixels, int width, int height, GLenum type,
                       const PixelLayout& layout, float depthScale, float depthBias,
                       std::vector<uint8_t>& out);

// The float whose bits a texel slot of unpackDepthTexels holds.
float depthFromTexelBits(const uint8_t bits[4]);

// Sets texel (i, j) of a depth image: the depth quantized to the image's resolution in
// `depths`, and at 8 bits in all four components of `texels`.
void setDepthTexel(TextureImage& image, int i, int j, float depth);

// Turns an image whose `texels` hold float bits (unpackDepthTexels) into a depth image with
// `bits` bits per texel.
void finishDepthImage(TextureImage& image, int bits);

// A depth image of width x height texels, all zero (glTexImage without data).
void allocateDepthImage(TextureImage& image, int bits);

}  // namespace glass::gl
