// What the texturing entry points share: finding the texture object a target names, the glPixelStore
// layouts, and the specification of texture images (glTexImage, glTexSubImage, glCopyTexImage),
// written once for one and two dimensions.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "pixels/rgba_image.h"
#include "texture/client_pixels.h"
#include "texture/texture_object.h"

namespace glass::gl {

struct Context;

// The texture object of the active unit bound to GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D or
// GL_TEXTURE_CUBE_MAP; null for any other target.
TextureObject* boundTexture(Context& ctx, GLenum target);
const TextureObject* boundTexture(const Context& ctx, GLenum target);

// The texture and face whose images an image target names: GL_TEXTURE_1D, GL_TEXTURE_2D and
// GL_TEXTURE_3D (face 0), GL_TEXTURE_CUBE_MAP_POSITIVE_X .. NEGATIVE_Z (the cube map's faces
// 0..5); the texture is null for any other target.
struct ImageTarget {
  TextureObject* texture = nullptr;
  int face = 0;
};
ImageTarget imageTarget(Context& ctx, GLenum target);

PixelLayout unpackLayout(const Context& ctx);
PixelLayout packLayout(const Context& ctx);

// The arguments of glTexImage1D/2D (height = 1 and dimensions = 1 for 1D).
struct TexImageArguments {
  int dimensions = 2;
  GLenum target = GL_TEXTURE_2D;
  GLint level = 0;
  GLint internalFormat = GL_RGBA;
  GLsizei width = 0, height = 1, depth = 1;
  GLint border = 0;
  GLenum format = GL_RGBA;
  GLenum type = GL_UNSIGNED_BYTE;
};

// Client data unpacked ahead of time, for a glTexImage or glTexSubImage compiled into a display
// list (spec 5.4: the pixel data is unpacked when the list is compiled, with the glPixelStore
// state of that time). The pixel transfer operations apply when the list is executed, so colour
// data is kept as RGBA groups (texture/texture_pixel_transfer.h); depth data as unpackDepthTexels
// gives it (the depth scale and bias of compile time). Null when the arguments were invalid or no
// data was given; the command then reports its error or defines an image without contents when
// the list is executed.
struct UnpackedImage {
  RgbaImage groups;                  // colour data: width x (height * depth) groups
  std::vector<uint8_t> depthTexels;  // GL_DEPTH_COMPONENT data
  std::vector<int32_t> indices;      // GL_COLOR_INDEX data: width x (height * depth) indices
};
using UnpackedTexels = std::shared_ptr<const UnpackedImage>;
UnpackedTexels unpackForDisplayList(const Context& ctx, const TexImageArguments& args, const void* pixels);

// glTexImage1D/2D: checks the arguments (setting the GL error of the specification), then defines
// the image from client memory (`pixels`) or from `unpacked`.
void texImage(Context& ctx, const TexImageArguments& args, const void* pixels, const UnpackedTexels& unpacked);

// glTexSubImage1D/2D: replaces a rectangle of an existing image.
struct TexSubImageArguments {
  int dimensions = 2;
  GLenum target = GL_TEXTURE_2D;
  GLint level = 0;
  GLint xoffset = 0, yoffset = 0, zoffset = 0;
  GLsizei width = 0, height = 1, depth = 1;
  GLenum format = GL_RGBA;
  GLenum type = GL_UNSIGNED_BYTE;
};
UnpackedTexels unpackForDisplayList(const Context& ctx, const TexSubImageArguments& args, const void* pixels);
void texSubImage(Context& ctx, const TexSubImageArguments& args, const void* pixels, const UnpackedTexels& unpacked);

// glCopyTexImage1D/2D and glCopyTexSubImage1D/2D: the texels come from the colour buffer.
void copyTexImage(Context& ctx, int dimensions, GLenum target, GLint level, GLenum internalFormat,
                  GLint x, GLint y, GLsizei width, GLsizei height, GLint border);
// glCopyTexSubImage3D copies into slice zoffset of a 3D image.
void copyTexSubImage(Context& ctx, int dimensions, GLenum target, GLint level, GLint xoffset,
                     GLint yoffset, GLint x, GLint y, GLsizei width, GLsizei height,
                     GLint zoffset = 0);

}  // namespace glass::gl
