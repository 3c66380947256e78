#include "texture/texture_commands.h"

#include <algorithm>
#include <cstring>
#include <new>

#include "core/context.h"
#include "core/errors.h"
#include "fragment/buffer_selection.h"
#include "pixels/imaging_pipeline.h"
#include "pixels/pixel_transfer.h"
#include "texture/depth_texture.h"
#include "texture/mipmap_generation.h"
#include "texture/texture_pixel_transfer.h"

namespace glass::gl {
namespace {

PixelLayout layoutFrom(const PixelPacking& p) {
  PixelLayout l;
  l.alignment = p.alignment;
  l.rowLength = p.rowLength;
  l.skipRows = p.skipRows;
  l.skipPixels = p.skipPixels;
  l.swapBytes = p.swapBytes;
  l.imageHeight = p.imageHeight;  // 3D images (spec 3.8.1)
  l.skipImages = p.skipImages;
  return l;
}

// The images targets of the given dimensionality name: GL_TEXTURE_1D; GL_TEXTURE_2D and the six
// cube map faces (OpenGL 1.3, section 3.8.1).
bool isImageTarget(int dimensions, GLenum target) {
  if (dimensions == 3) return target == GL_TEXTURE_3D;
  return dimensions == 1 ? target == GL_TEXTURE_1D
                         : target == GL_TEXTURE_2D || cubeFaceOf(target) >= 0;
}

// The targets glTexImage of the given dimensionality accepts: the images and the proxies.
bool isTexImageTarget(int dimensions, GLenum target) {
  if (isImageTarget(dimensions, target)) return true;
  if (dimensions == 3) return target == GL_PROXY_TEXTURE_3D;
  return dimensions == 1 ? target == GL_PROXY_TEXTURE_1D
                         : target == GL_PROXY_TEXTURE_2D || target == GL_PROXY_TEXTURE_CUBE_MAP;
}

// The proxy images of each level of a proxy target.
TextureImage* proxyLevels(Context& ctx, GLenum target) {
  switch (target) {
    case GL_PROXY_TEXTURE_1D: return ctx.texture.proxy1D;
    case GL_PROXY_TEXTURE_2D: return ctx.texture.proxy2D;
    case GL_PROXY_TEXTURE_3D: return ctx.texture.proxy3D;
    default: return ctx.texture.proxyCube;
  }
}

// Cube map faces are square (spec 3.8.1: otherwise GL_INVALID_VALUE).
bool isCubeMapTarget(GLenum target) {
  return cubeFaceOf(target) >= 0 || target == GL_PROXY_TEXTURE_CUBE_MAP;
}

// The image size checks common to glTexImage and glCopyTexImage (spec 3.8.1): border 0 or 1,
// width, height and depth at least twice the border. The size of the image without its border
// is written to innerWidth/innerHeight/innerDepth (height 1 for 1D images, depth 1 for 1D and 2D
// images, which have no border there).
GLenum checkImageSize(int dimensions, GLsizei width, GLsizei height, GLsizei depth, GLint border,
                      int* innerWidth, int* innerHeight, int* innerDepth) {
  if (border != 0 && border != 1) return GL_INVALID_VALUE;
  if (width < 2 * border) return GL_INVALID_VALUE;
  if (dimensions >= 2 && height < 2 * border) return GL_INVALID_VALUE;
  if (dimensions == 3 && depth < 2 * border) return GL_INVALID_VALUE;
  *innerWidth = width - 2 * border;
  *innerHeight = dimensions >= 2 ? height - 2 * border : 1;
  *innerDepth = dimensions == 3 ? depth - 2 * border : 1;
  return GL_NO_ERROR;
}

// Whether glass can hold a level-`level` image of this size (GL_MAX_TEXTURE_SIZE >> level, or
// GL_MAX_3D_TEXTURE_SIZE >> level for a 3D image).
bool fitsLevel(int level, int innerWidth, int innerHeight, int innerDepth = 1,
               int dimensions = 2) {
  const int max = (dimensions == 3 ? kMax3DTextureSize : kMaxTextureSize) >> level;
  return innerWidth <= max && innerHeight <= max && innerDepth <= max;
}

// Unpacks a width x height x depth block of client texels (spec 3.8.1: a 3D image is `depth`
// 2D images, each GL_UNPACK_IMAGE_HEIGHT rows apart, or `height` when that is 0, after
// GL_UNPACK_SKIP_IMAGES images). 1D and 2D images are one slice, without the image skip.
void unpackBlock(const void* pixels, int dimensions, int width, int height, int depth,
                 GLenum format, GLenum type, const PixelLayout& layout, BaseFormat base,
                 std::vector<uint8_t>& out) {
  if (dimensions < 3) {
    unpackTexels(pixels, width, height, format, type, layout, base, out);
    return;
  }
  out.clear();
  std::vector<uint8_t> slice;
  for (int k = 0; k < depth; ++k) {
    unpackTexels(pixels, width, height, format, type, sliceLayout(layout, height, k), base, slice);
    out.insert(out.end(), slice.begin(), slice.end());
  }
}

// The format checks of glTexImage and glTexSubImage for an image of the given internal format:
// those of the colour formats, or for GL_DEPTH_COMPONENT those of glDrawPixels; then (OpenGL 1.4,
// 3.8.1) a depth format with a colour internal format or the other way round, or a depth image on
// a target other than 1D and 2D, is GL_INVALID_OPERATION.
GLenum checkImageFormat(GLenum target, GLint internalFormat, GLenum format, GLenum type) {
  const bool depthData = format == GL_DEPTH_COMPONENT;
  const GLenum e =
      depthData ? checkPixelFormatAndType(format, type) : checkTexImageFormatAndType(format, type);
  if (e != GL_NO_ERROR) return e;
  if (depthData != isDepthInternalFormat(internalFormat)) return GL_INVALID_OPERATION;
  if (depthData && !takesDepthImages(target)) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

// unpackBlock, or for GL_DEPTH_COMPONENT data the depths as float bits (depth_texture.h), with
// the depth scale and bias of the pixel transfer state.
void unpackImageBlock(const Context& ctx, const void* pixels, int dimensions, int width, int height,
                      int depth, GLenum format, GLenum type, BaseFormat base,
                      std::vector<uint8_t>& out) {
  if (format == GL_DEPTH_COMPONENT) {
    unpackDepthTexels(pixels, width, height, type, unpackLayout(ctx), ctx.pixelTransfer.depthScale,
                      ctx.pixelTransfer.depthBias, out);
    return;
  }
  unpackBlock(pixels, dimensions, width, height, depth, format, type, unpackLayout(ctx), base, out);
}

// The client data of a texture image command as the pixel transfer path takes it: colour groups
// as RGBA floats, depth data as unpackDepthTexels gives it.
UnpackedImage readClientImage(const Context& ctx, const void* pixels, int dimensions, int width,
                              int height, int depth, GLenum format, GLenum type) {
  UnpackedImage image;
  if (format == GL_DEPTH_COMPONENT) {
    unpackDepthTexels(pixels, width, height, type, unpackLayout(ctx), ctx.pixelTransfer.depthScale,
                      ctx.pixelTransfer.depthBias, image.depthTexels);
  } else if (format == GL_COLOR_INDEX) {
    const PixelLayout layout = unpackLayout(ctx);
    image.indices.resize(static_cast<size_t>(width) * static_cast<size_t>(height) *
                         static_cast<size_t>(depth));
    for (int k = 0; k < depth; ++k) {
      const PixelLayout slice = dimensions == 3 ? sliceLayout(layout, height, k) : layout;
      for (int j = 0; j < height; ++j) {
        unpackIndexRow(pixels, width, j, type, slice,
                       &image.indices[(static_cast<size_t>(k) * static_cast<size_t>(height) +
                                       static_cast<size_t>(j)) * static_cast<size_t>(width)]);
      }
    }
  } else {
    image.groups = unpackColorGroups(pixels, dimensions, width, height, depth, format, type,
                                     unpackLayout(ctx));
  }
  return image;
}

// Whether colour data of this format goes through transferredTexels: always for colour indices,
// which only the transfer operations turn into RGBA; for RGBA data when an operation is active.
bool takesTransferPath(const Context& ctx, GLenum format) {
  return format == GL_COLOR_INDEX || textureTransferActive(ctx);
}

// The texels of a texture image command's data through the pixel transfer operations, border
// included: from `unpacked` (a display list) or read from `pixels` now. *width and *height come in
// as the client block's size and go out as the texels' (a GL_REDUCE convolution shrinks a colour
// image). False when a histogram or minmax sink took the groups: nothing is to be written.
bool transferredTexels(Context& ctx, int dimensions, const void* pixels,
                       const UnpackedTexels& unpacked, GLenum format, GLenum type, BaseFormat base,
                       int* width, int* height, int depth, std::vector<uint8_t>& texels) {
  UnpackedImage read;
  if (!unpacked) read = readClientImage(ctx, pixels, dimensions, *width, *height, depth, format, type);
  const UnpackedImage& client = unpacked ? *unpacked : read;
  if (format == GL_DEPTH_COMPONENT) {
    texels = client.depthTexels;
    return true;
  }
  if (format == GL_COLOR_INDEX) {
    // Spec 3.6.5: indices are shifted and offset, then become RGBA through the
    // GL_PIXEL_MAP_I_TO_* maps (clamped); the imaging operations, if any, follow.
    RgbaImage groups;
    groups.width = *width;
    groups.height = *height * depth;
    groups.rgba.resize(static_cast<size_t>(groups.count()) * 4);
    colorIndicesToRGBA(ctx.pixelTransfer, client.indices.data(), groups.count(), groups.rgba.data());
    if (imagingActive(ctx.imaging) && !transferConvertedColorImage(ctx.imaging, groups, dimensions))
      return false;
    *width = groups.width;
    *height = groups.height / depth;
    storeTexelGroups(groups, base, texels);
    return true;
  }
  if (!textureTransferActive(ctx)) {
    storeTexelGroups(client.groups, base, texels);
    return true;
  }
  RgbaImage groups = unpacked ? client.groups : std::move(read.groups);
  if (!transferTextureGroups(ctx, dimensions, groups)) return false;
  *width = groups.width;
  *height = groups.height / depth;
  storeTexelGroups(groups, base, texels);
  return true;
}

// Gives `image` the size of fullWidth x fullHeight texels less the border, after the pixel
// transfer changed it (a GL_REDUCE convolution; spec 3.8.1: the image is the convolved one).
// GL_INVALID_VALUE when the level cannot take that size.
GLenum resizeToTransferred(TextureImage& image, int dimensions, GLenum target, GLint level,
                           int fullWidth, int fullHeight) {
  const int b = image.border;
  const int w = fullWidth - 2 * b;
  const int h = dimensions >= 2 ? fullHeight - 2 * b : 1;
  if (w < 0 || h < 0 || !fitsLevel(level, w, h, image.depth, dimensions)) return GL_INVALID_VALUE;
  if (isCubeMapTarget(target) && w != h) return GL_INVALID_VALUE;
  image.width = w;
  image.height = h;
  image.texels.assign(static_cast<size_t>(w) * static_cast<size_t>(h) *
                          static_cast<size_t>(image.depth) * 4, 0);
  return GL_NO_ERROR;
}

// Copies the texels inside the border of a full image (fullWidth x fullHeight x depth texels,
// border included) into `image`, whose width/height/depth are the inner size.
void copyInsideBorder(const std::vector<uint8_t>& full, int fullWidth, int fullHeight, int border,
                      int dimensions, TextureImage& image) {
  const int rowBorder = dimensions >= 2 ? border : 0;
  const int sliceBorder = dimensions == 3 ? border : 0;
  const size_t rowBytes = static_cast<size_t>(image.width) * 4;
  for (int k = 0; k < image.depth; ++k) {
    for (int j = 0; j < image.height; ++j) {
      const size_t row = static_cast<size_t>(k + sliceBorder) * static_cast<size_t>(fullHeight) +
                         static_cast<size_t>(j + rowBorder);
      const size_t from = (row * static_cast<size_t>(fullWidth) + static_cast<size_t>(border)) * 4;
      std::memcpy(image.texel(0, j, k), &full[from], rowBytes);
    }
  }
}

void afterBaseLevelChange(TextureObject& texture, int face, GLint level) {
  if (level == texture.params.baseLevel && texture.params.generateMipmap)
    generateMipmaps(texture, face);
  texture.updateCompleteness();
}

// The depth buffer's value at window (x, y) in [0, 1]; outside the window zero, as for colours.
float readFramebufferDepth(const Context& ctx, int x, int y) {
  const raster::Framebuffer& fb = ctx.framebuffer;
  if (x < 0 || y < 0 || x >= fb.width() || y >= fb.height()) return 0.0f;
  return static_cast<float>(static_cast<double>(*fb.depthAt(x, y)) / raster::kDepthMax);
}

// glCopyTexSubImage through the pixel transfer operations (spec 3.8.2): the rectangle's groups as
// glCopyPixels would draw them, stored from (xoffset, yoffset) in slice zoffset, border texels
// left out. A copy into a 3D image is a two-dimensional rectangle, convolved as one.
void copyTransferredGroups(Context& ctx, int dimensions, int x, int y, int width, int height,
                           int xoffset, int yoffset, int zoffset, TextureImage& image) {
  RgbaImage groups = readFramebufferGroups(ctx, x, y, width, height);
  if (!transferTextureGroups(ctx, dimensions == 1 ? 1 : 2, groups)) return;  // a sink took them
  std::vector<uint8_t> texels;
  storeTexelGroups(groups, image.base, texels);
  for (int j = 0; j < groups.height; ++j) {
    const int ty = yoffset + j;
    if (ty < 0 || ty >= image.height) continue;
    for (int i = 0; i < groups.width; ++i) {
      const int tx = xoffset + i;
      if (tx < 0 || tx >= image.width) continue;
      const size_t from = static_cast<size_t>(j) * static_cast<size_t>(groups.width) + static_cast<size_t>(i);
      std::memcpy(image.texel(tx, ty, zoffset), &texels[from * 4], 4);
    }
  }
}

}  // namespace

TextureObject* boundTexture(Context& ctx, GLenum target) {
  if (target == GL_TEXTURE_1D) return ctx.texture.unit().bound1D;
  if (target == GL_TEXTURE_2D) return ctx.texture.unit().bound2D;
  if (target == GL_TEXTURE_3D) return ctx.texture.unit().bound3D;
  if (target == GL_TEXTURE_CUBE_MAP) return ctx.texture.unit().boundCube;
  return nullptr;
}

const TextureObject* boundTexture(const Context& ctx, GLenum target) {
  return boundTexture(const_cast<Context&>(ctx), target);
}

ImageTarget imageTarget(Context& ctx, GLenum target) {
  const int face = cubeFaceOf(target);
  if (face >= 0) return {ctx.texture.unit().boundCube, face};
  return {boundTexture(ctx, target), 0};
}

PixelLayout unpackLayout(const Context& ctx) { return layoutFrom(ctx.pixelStore.unpack); }
PixelLayout packLayout(const Context& ctx) { return layoutFrom(ctx.pixelStore.pack); }

UnpackedTexels unpackForDisplayList(const Context& ctx, const TexImageArguments& a, const void* pixels) {
  BaseFormat base;
  int w, h, d;
  if (pixels == nullptr || !isImageTarget(a.dimensions, a.target) ||
      !baseFormatOfInternalFormat(a.internalFormat, &base) ||
      checkImageSize(a.dimensions, a.width, a.height, a.depth, a.border, &w, &h, &d) !=
          GL_NO_ERROR ||
      a.level < 0 || a.level >= kMaxTextureLevels || !fitsLevel(a.level, w, h, d, a.dimensions) ||
      checkImageFormat(a.target, a.internalFormat, a.format, a.type) != GL_NO_ERROR)
    return nullptr;
  try {
    return std::make_shared<UnpackedImage>(
        readClientImage(ctx, pixels, a.dimensions, a.width, a.dimensions >= 2 ? a.height : 1,
                        a.dimensions == 3 ? a.depth : 1, a.format, a.type));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

void texImage(Context& ctx, const TexImageArguments& a, const void* pixels, const UnpackedTexels& unpacked) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (!isTexImageTarget(a.dimensions, a.target)) return recordError(ctx, GL_INVALID_ENUM);
  if (a.level < 0 || a.level >= kMaxTextureLevels) return recordError(ctx, GL_INVALID_VALUE);
  BaseFormat base;
  if (!baseFormatOfInternalFormat(a.internalFormat, &base)) return recordError(ctx, GL_INVALID_VALUE);
  int w = 0, h = 0, d = 0;
  if (GLenum e = checkImageSize(a.dimensions, a.width, a.height, a.depth, a.border, &w, &h, &d);
      e != GL_NO_ERROR)
    return recordError(ctx, e);
  if (GLenum e = checkImageFormat(a.target, a.internalFormat, a.format, a.type); e != GL_NO_ERROR)
    return recordError(ctx, e);
  if (isCubeMapTarget(a.target) && w != h) return recordError(ctx, GL_INVALID_VALUE);
  const bool depthImage = isDepthInternalFormat(a.internalFormat);

  if (!isImageTarget(a.dimensions, a.target)) {
    // Spec 3.8.11: a proxy query succeeds (the level state is set) when the image would fit, and
    // leaves every level parameter zero otherwise; no error either way.
    TextureImage& proxy = proxyLevels(ctx, a.target)[a.level];
    proxy.clear();
    if (fitsLevel(a.level, w, h, d, a.dimensions)) {
      proxy.width = w;
      proxy.height = h;
      proxy.depth = d;
      proxy.border = a.border;
      proxy.internalFormat = a.internalFormat;
      proxy.base = base;
      proxy.depthBits = depthImage ? depthBitsOfInternalFormat(a.internalFormat) : 0;
    } else {
      proxy.internalFormat = 0;
    }
    return;
  }
  if (!fitsLevel(a.level, w, h, d, a.dimensions)) return recordError(ctx, GL_INVALID_VALUE);

  const ImageTarget target = imageTarget(ctx, a.target);
  TextureObject& texture = *target.texture;
  TextureImage& slot = texture.image(target.face, a.level);
  try {
    TextureImage image;
    image.internalFormat = a.internalFormat;
    image.base = base;
    image.border = a.border;
    if (w > 0 && h > 0 && d > 0) {
      image.width = w;
      image.height = h;
      image.depth = d;
      image.texels.assign(
          static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(d) * 4, 0);
      const int fullHeight = a.dimensions >= 2 ? a.height : 1;
      const int fullDepth = a.dimensions == 3 ? a.depth : 1;
      if (unpacked || (pixels != nullptr && !depthImage && takesTransferPath(ctx, a.format))) {
        int fullWidth = a.width, transferredHeight = fullHeight;
        std::vector<uint8_t> full;
        if (!transferredTexels(ctx, a.dimensions, pixels, unpacked, a.format, a.type, base,
                               &fullWidth, &transferredHeight, fullDepth, full))
          return;  // a histogram or minmax sink took the groups
        if (fullWidth != a.width || transferredHeight != fullHeight) {
          if (GLenum e = resizeToTransferred(image, a.dimensions, a.target, a.level, fullWidth,
                                             transferredHeight);
              e != GL_NO_ERROR)
            return recordError(ctx, e);
        }
        copyInsideBorder(full, fullWidth, transferredHeight, a.border, a.dimensions, image);
      } else if (pixels != nullptr) {
        if (a.border == 0) {
          unpackImageBlock(ctx, pixels, a.dimensions, w, h, d, a.format, a.type, base,
                           image.texels);
        } else {
          std::vector<uint8_t> full;
          unpackImageBlock(ctx, pixels, a.dimensions, a.width, fullHeight, fullDepth, a.format,
                           a.type, base, full);
          copyInsideBorder(full, a.width, fullHeight, a.border, a.dimensions, image);
        }
      }
      if (depthImage) finishDepthImage(image, depthBitsOfInternalFormat(a.internalFormat));
    } else if (depthImage) {
      image.depthBits = depthBitsOfInternalFormat(a.internalFormat);
    }
    slot = std::move(image);
    afterBaseLevelChange(texture, target.face, a.level);
  } catch (const std::bad_alloc&) {
    slot.clear();
    texture.updateCompleteness();
    recordError(ctx, GL_OUT_OF_MEMORY);
  }
}

UnpackedTexels unpackForDisplayList(const Context& ctx, const TexSubImageArguments& a, const void* pixels) {
  if (pixels == nullptr || !isImageTarget(a.dimensions, a.target) || a.level < 0 ||
      a.level >= kMaxTextureLevels || a.width < 0 || a.height < 0)
    return nullptr;
  const ImageTarget target = imageTarget(const_cast<Context&>(ctx), a.target);
  // The format check is the one of the image when the list is compiled; the texels are made
  // for the image of execution time.
  const TextureImage& image = target.texture->image(target.face, a.level);
  if (checkImageFormat(a.target, image.internalFormat, a.format, a.type) != GL_NO_ERROR)
    return nullptr;
  try {
    return std::make_shared<UnpackedImage>(
        readClientImage(ctx, pixels, a.dimensions, a.width, a.dimensions >= 2 ? a.height : 1,
                        a.dimensions == 3 ? a.depth : 1, a.format, a.type));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

void texSubImage(Context& ctx, const TexSubImageArguments& a, const void* pixels, const UnpackedTexels& unpacked) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (!isImageTarget(a.dimensions, a.target)) return recordError(ctx, GL_INVALID_ENUM);
  if (a.level < 0 || a.level >= kMaxTextureLevels) return recordError(ctx, GL_INVALID_VALUE);
  const ImageTarget target = imageTarget(ctx, a.target);
  TextureObject& texture = *target.texture;
  TextureImage& image = texture.image(target.face, a.level);
  if (GLenum e = a.format == GL_DEPTH_COMPONENT ? checkPixelFormatAndType(a.format, a.type)
                                                 : checkTexImageFormatAndType(a.format, a.type);
      e != GL_NO_ERROR)
    return recordError(ctx, e);
  if (!image.defined()) return recordError(ctx, GL_INVALID_OPERATION);
  // OpenGL 1.4, 3.8.2: depth data for a depth image, colour data for a colour image.
  if ((a.format == GL_DEPTH_COMPONENT) != image.isDepth()) return recordError(ctx, GL_INVALID_OPERATION);
  const int height = a.dimensions >= 2 ? a.height : 1;
  const int yoffset = a.dimensions >= 2 ? a.yoffset : 0;
  const int depth = a.dimensions == 3 ? a.depth : 1;
  const int zoffset = a.dimensions == 3 ? a.zoffset : 0;
  const int b = image.border;
  const int rowBorder = a.dimensions >= 2 ? b : 0;
  const int sliceBorder = a.dimensions == 3 ? b : 0;
  // Spec 3.8.2: the box must lie inside the image, border included.
  if (a.width < 0 || height < 0 || depth < 0 || a.xoffset < -b ||
      a.xoffset + a.width > image.width + b || yoffset < -rowBorder ||
      yoffset + height > image.height + rowBorder || zoffset < -sliceBorder ||
      zoffset + depth > image.depth + sliceBorder)
    return recordError(ctx, GL_INVALID_VALUE);
  if (a.width == 0 || height == 0 || depth == 0) return;
  if (!unpacked && pixels == nullptr) return;
  try {
    // The block's size after the pixel transfer (a GL_REDUCE convolution makes it smaller).
    int width = a.width, rows = height;
    std::vector<uint8_t> texels;
    if (unpacked || (!image.isDepth() && takesTransferPath(ctx, a.format))) {
      if (!transferredTexels(ctx, a.dimensions, pixels, unpacked, a.format, a.type, image.base,
                             &width, &rows, depth, texels))
        return;  // a histogram or minmax sink took the groups
    } else {
      unpackImageBlock(ctx, pixels, a.dimensions, a.width, height, depth, a.format, a.type,
                       image.base, texels);
    }
    for (int k = 0; k < depth; ++k) {
      const int z = zoffset + k;
      if (z < 0 || z >= image.depth) continue;  // a border slice: not stored
      for (int j = 0; j < rows; ++j) {
        const int y = yoffset + j;
        if (y < 0 || y >= image.height) continue;  // a border row: not stored
        for (int i = 0; i < width; ++i) {
          const int x = a.xoffset + i;
          if (x < 0 || x >= image.width) continue;
          const size_t from = (static_cast<size_t>(k) * static_cast<size_t>(rows) +
                               static_cast<size_t>(j)) * static_cast<size_t>(width) +
                              static_cast<size_t>(i);
          if (image.isDepth()) {
            setDepthTexel(image, x, y, depthFromTexelBits(&texels[from * 4]));
          } else {
            std::memcpy(image.texel(x, y, z), &texels[from * 4], 4);
          }
        }
      }
    }
    afterBaseLevelChange(texture, target.face, a.level);
  } catch (const std::bad_alloc&) {
    recordError(ctx, GL_OUT_OF_MEMORY);
  }
}

void copyTexImage(Context& ctx, int dimensions, GLenum target, GLint level, GLenum internalFormat,
                  GLint x, GLint y, GLsizei width, GLsizei height, GLint border) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (!isImageTarget(dimensions, target)) return recordError(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return recordError(ctx, GL_INVALID_VALUE);
  BaseFormat base;
  // Spec 3.8.2: the component counts 1 to 4 are not internal formats of glCopyTexImage.
  const GLint format = static_cast<GLint>(internalFormat);
  if (format >= 1 && format <= 4) return recordError(ctx, GL_INVALID_VALUE);
  if (!baseFormatOfInternalFormat(format, &base)) return recordError(ctx, GL_INVALID_VALUE);
  if (dimensions == 1) height = 1;
  int w = 0, h = 0, d = 0;
  if (GLenum e = checkImageSize(dimensions, width, height, 1, border, &w, &h, &d); e != GL_NO_ERROR)
    return recordError(ctx, e);
  if (!fitsLevel(level, w, h)) return recordError(ctx, GL_INVALID_VALUE);
  if (isCubeMapTarget(target) && w != h) return recordError(ctx, GL_INVALID_VALUE);
  // A depth internal format copies the depth buffer (OpenGL 1.4, 3.8.2), into 1D and 2D
  // textures only (3.8.1).
  const bool depthImage = isDepthInternalFormat(format);
  if (depthImage && !takesDepthImages(target)) return recordError(ctx, GL_INVALID_OPERATION);
  if (depthImage && !ctx.buffers.depth) return recordError(ctx, GL_INVALID_OPERATION);
  // No colour buffer to read from after glReadBuffer(GL_NONE), as for glReadPixels (Mesa too).
  if (!depthImage && !readsColor(ctx.pixelTransfer.readBuffer))
    return recordError(ctx, GL_INVALID_OPERATION);
  const ReadBufferSelection read(ctx);

  const ImageTarget named = imageTarget(ctx, target);
  TextureObject& texture = *named.texture;
  TextureImage& slot = texture.image(named.face, level);
  try {
    TextureImage image;
    image.internalFormat = format;
    image.base = base;
    image.border = border;
    if (w > 0 && h > 0) {
      image.width = w;
      image.height = h;
      image.texels.resize(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
      const int rowBorder = dimensions == 2 ? border : 0;
      if (depthImage) allocateDepthImage(image, depthBitsOfInternalFormat(format));
      if (!depthImage && textureTransferActive(ctx)) {
        // The rectangle's groups, border included, as glCopyPixels would draw them (3.8.2).
        RgbaImage groups = readFramebufferGroups(ctx, x, y, width, height);
        if (!transferTextureGroups(ctx, dimensions, groups)) return;  // a sink took them
        if (groups.width != width || groups.height != height) {
          if (GLenum e = resizeToTransferred(image, dimensions, target, level, groups.width,
                                             groups.height);
              e != GL_NO_ERROR)
            return recordError(ctx, e);
        }
        std::vector<uint8_t> full;
        storeTexelGroups(groups, base, full);
        copyInsideBorder(full, groups.width, groups.height, border, dimensions, image);
      } else {
        for (int j = 0; j < h; ++j) {
          for (int i = 0; i < w; ++i) {
            if (depthImage) {
              setDepthTexel(image, i, j, readFramebufferDepth(ctx, x + border + i, y + rowBorder + j));
              continue;
            }
            float rgba[4];
            readFramebufferColor(ctx, x + border + i, y + rowBorder + j, rgba);
            storeTexel(base, rgba, image.texel(i, j));
          }
        }
      }
    } else if (depthImage) {
      image.depthBits = depthBitsOfInternalFormat(format);
    }
    slot = std::move(image);
    afterBaseLevelChange(texture, named.face, level);
  } catch (const std::bad_alloc&) {
    slot.clear();
    texture.updateCompleteness();
    recordError(ctx, GL_OUT_OF_MEMORY);
  }
}

void copyTexSubImage(Context& ctx, int dimensions, GLenum target, GLint level, GLint xoffset,
                     GLint yoffset, GLint x, GLint y, GLsizei width, GLsizei height,
                     GLint zoffset) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (!isImageTarget(dimensions, target)) return recordError(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return recordError(ctx, GL_INVALID_VALUE);
  const ImageTarget named = imageTarget(ctx, target);
  TextureObject& texture = *named.texture;
  TextureImage& image = texture.image(named.face, level);
  if (!image.defined()) return recordError(ctx, GL_INVALID_OPERATION);
  if (dimensions == 1) {
    height = 1;
    yoffset = 0;
  }
  const int b = image.border;
  const int rowBorder = dimensions >= 2 ? b : 0;
  const int sliceBorder = dimensions == 3 ? b : 0;
  if (dimensions < 3) zoffset = 0;
  if (width < 0 || height < 0 || xoffset < -b || xoffset + width > image.width + b ||
      yoffset < -rowBorder || yoffset + height > image.height + rowBorder ||
      zoffset < -sliceBorder || zoffset >= image.depth + sliceBorder)
    return recordError(ctx, GL_INVALID_VALUE);
  if (!image.isDepth() && !readsColor(ctx.pixelTransfer.readBuffer))
    return recordError(ctx, GL_INVALID_OPERATION);
  const ReadBufferSelection read(ctx);
  if (image.isDepth() && !ctx.buffers.depth) return recordError(ctx, GL_INVALID_OPERATION);
  // A border slice of a 3D image is not stored.
  if (zoffset < 0 || zoffset >= image.depth) return;
  if (!image.isDepth() && textureTransferActive(ctx)) {
    try {
      copyTransferredGroups(ctx, dimensions, x, y, width, height, xoffset, yoffset, zoffset, image);
    } catch (const std::bad_alloc&) {
      return recordError(ctx, GL_OUT_OF_MEMORY);
    }
    afterBaseLevelChange(texture, named.face, level);
    return;
  }
  for (int j = 0; j < height; ++j) {
    const int ty = yoffset + j;
    if (ty < 0 || ty >= image.height) continue;
    for (int i = 0; i < width; ++i) {
      const int tx = xoffset + i;
      if (tx < 0 || tx >= image.width) continue;
      if (image.isDepth()) {  // the depth buffer (OpenGL 1.4, 3.8.2)
        setDepthTexel(image, tx, ty, readFramebufferDepth(ctx, x + i, y + j));
        continue;
      }
      float rgba[4];
      readFramebufferColor(ctx, x + i, y + j, rgba);
      storeTexel(image.base, rgba, image.texel(tx, ty, zoffset));
    }
  }
  afterBaseLevelChange(texture, named.face, level);
}

}  // namespace glass::gl
