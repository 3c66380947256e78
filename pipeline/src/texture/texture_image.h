// One texture image (one mipmap level of a texture object) and the internal formats a texture can
// have (OpenGL 1.5 specification, section 3.8.1, tables 3.15 and 3.16).
//
// glass stores every image as 8-bit RGBA, whatever internal format the program asked for; the
// specification lets an implementation pick the resolution of each component (3.8.1: "the GL
// may choose an internal representation ... that does not exactly match"). Components are
// stored as the texture environment sees them (table 3.21), so filtering is the same code for
// every format:
//   ALPHA            (0, 0, 0, A)      LUMINANCE        (L, L, L, 1)
//   LUMINANCE_ALPHA  (L, L, L, A)      INTENSITY        (I, I, I, I)
//   RGB              (R, G, B, 1)      RGBA             (R, G, B, A)
// The base format travels with the image, because the environment functions (tables 3.22 and
// 3.23) differ by base format, not by value.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glass::gl {

enum class BaseFormat : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, RGB, RGBA };

// GL_MAX_TEXTURE_SIZE. Levels 0 .. kMaxTextureLevels - 1 exist, enough for a 4096-texel side.
inline constexpr int kMaxTextureSize = 4096;
inline constexpr int kMaxTextureLevels = 13;
// GL_MAX_3D_TEXTURE_SIZE, as Mesa's llvmpipe reports it.
inline constexpr int kMax3DTextureSize = 2048;

// The base internal format of an internal format given to glTexImage (table 3.15 and 3.16, plus
// the legacy component counts 1 to 4 and the GL 1.3 generic compressed formats, which glass
// stores uncompressed). Returns false for a value that is not an internal format.
bool baseFormatOfInternalFormat(GLint internalFormat, BaseFormat* base);

// The GL enum of a base format (GL_ALPHA, GL_LUMINANCE, ...).
GLenum baseFormatEnum(BaseFormat base);

// Bits per component as glGetTexLevelParameter reports them (GL_TEXTURE_RED_SIZE, ...):
// 8 for each component the base format has, 0 for the others.
int componentBits(BaseFormat base, GLenum sizeQuery);

struct TextureImage {
  int width = 0;               // 0: the level has no image
  int height = 0;              // 1 for a one-dimensional texture
  int depth = 1;               // the number of slices of a three-dimensional texture, else 1
  int border = 0;              // as specified; the border texels themselves are not kept (below)
  GLint internalFormat = 1;    // as specified, returned by GL_TEXTURE_INTERNAL_FORMAT
  BaseFormat base = BaseFormat::Luminance;
  // width * height * depth texels, 4 bytes each, row 0 (t = 0) of slice 0 (r = 0) first, each
  // slice after the previous. A border given with border = 1 is
  // stripped when the image is specified, as Mesa does; texels outside the image take the
  // border colour instead (docs/texturing.md).
  std::vector<uint8_t> texels;
  // A DEPTH_COMPONENT image (OpenGL 1.4, 3.8.1; texture/depth_texture.h): the resolution of its
  // depth values (16 or 24 bits), 0 for the colour formats. Its values, width * height of them
  // in [0, 1] in the order of `texels`, are in `depths`; `texels` holds each at 8 bits in all
  // four components, for the code that reads any image (mipmaps, glGetTexImage of colours).
  int depthBits = 0;
  std::vector<float> depths;

  bool isDepth() const { return depthBits > 0; }
  bool defined() const { return width > 0 && height > 0 && depth > 0; }
  std::size_t texelIndex(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(height) +
            static_cast<std::size_t>(j)) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(i);
  }
  const uint8_t* texel(int i, int j, int k = 0) const { return &texels[texelIndex(i, j, k) * 4]; }
  uint8_t* texel(int i, int j, int k = 0) { return &texels[texelIndex(i, j, k) * 4]; }
  void clear() { *this = TextureImage(); }
};

// Stores one texel given as RGBA in [0, 1] (the result of unpacking, spec 3.6.4) in the layout
// above: the base format picks the components it keeps (table 3.15: LUMINANCE takes R, ...).
void storeTexel(BaseFormat base, const float rgba[4], uint8_t out[4]);

// An 8-bit component from a value in [0, 1]: clamp, then round(c * 255) (spec 2.14.9, the
// conversion of floating-point colour components to fixed point).
uint8_t unitFloatToByte(float c);

}  // namespace glass::gl
