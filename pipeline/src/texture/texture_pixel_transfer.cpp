#include "texture/texture_pixel_transfer.h"

#include "core/context.h"
#include "pixels/imaging_pipeline.h"
#include "pixels/pixel_transfer.h"

namespace glass::gl {

bool textureTransferActive(const Context& ctx) {
  return !colorTransferChangesNothing(ctx.pixelTransfer) || imagingActive(ctx.imaging);
}

RgbaImage unpackColorGroups(const void* pixels, int dimensions, int width, int height, int depth,
                            GLenum format, GLenum type, const PixelLayout& layout) {
  RgbaImage groups;
  groups.width = width;
  groups.height = height * depth;
  groups.rgba.resize(static_cast<size_t>(groups.count()) * 4);
  for (int k = 0; k < depth; ++k) {
    const PixelLayout slice = dimensions == 3 ? sliceLayout(layout, height, k) : layout;
    for (int j = 0; j < height; ++j) {
      unpackColorRow(pixels, width, j, format, type, slice, groups.at(0, k * height + j));
    }
  }
  return groups;
}

void readFramebufferColor(const Context& ctx, int x, int y, float rgba[4]) {
  const raster::Framebuffer& fb = ctx.framebuffer;
  if (x < 0 || y < 0 || x >= fb.width() || y >= fb.height()) {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0f;
    return;
  }
  const uint8_t* c = fb.colorAt(x, y);
  for (int k = 0; k < 4; ++k) rgba[k] = static_cast<float>(c[k]) / 255.0f;
}

RgbaImage readFramebufferGroups(const Context& ctx, int x, int y, int width, int height) {
  RgbaImage groups;
  groups.width = width;
  groups.height = height;
  groups.rgba.resize(static_cast<size_t>(groups.count()) * 4);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) readFramebufferColor(ctx, x + i, y + j, groups.at(i, j));
  }
  return groups;
}

bool transferTextureGroups(Context& ctx, int dimensions, RgbaImage& groups) {
  return transferColorImage(ctx.pixelTransfer, ctx.imaging, groups, dimensions);
}

void storeTexelGroups(const RgbaImage& groups, BaseFormat base, std::vector<uint8_t>& texels) {
  texels.resize(static_cast<size_t>(groups.count()) * 4);
  for (int g = 0; g < groups.count(); ++g) {
    storeTexel(base, &groups.rgba[static_cast<size_t>(g) * 4], &texels[static_cast<size_t>(g) * 4]);
  }
}

}  // namespace glass::gl
