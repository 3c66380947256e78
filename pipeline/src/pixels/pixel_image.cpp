#include "pixels/pixel_image.h"

#include <algorithm>
#include <cmath>

#include "core/context.h"
#include "core/float_to_int.h"
#include "fragment/buffer_selection.h"
#include "pixels/imaging_pipeline.h"
#include "pixels/pixel_fragments.h"
#include "pixels/pixel_transfer.h"
#include "select/render_mode.h"
#include "texture/client_pixels.h"

namespace glass::gl {

namespace {

size_t pixelCount(int width, int height) {
  return static_cast<size_t>(width) * static_cast<size_t>(height);
}

// Pixel commands act only with a valid raster position (spec 2.13), and rasterize only in
// GL_RENDER mode; in feedback mode they leave their token (spec 5.3).
bool shouldRasterize(Context& ctx, GLenum feedbackToken) {
  if (!ctx.rasterPosition.valid) return false;
  if (ctx.renderMode.mode == GL_RENDER) return true;
  recordPixelCommand(ctx, feedbackToken);
  return false;
}

// A block of pixels to draw at the raster position: its size and, for glCopyPixels clipped to
// the framebuffer, its place in the rectangle the command names.
struct PixelBlock {
  int width = 0, height = 0;
  int column0 = 0, row0 = 0;
};

FragmentImage fragmentImageOf(const PixelBlock& block) {
  FragmentImage image;
  image.width = block.width;
  image.height = block.height;
  image.column0 = block.column0;
  image.row0 = block.row0;
  return image;
}

// Colours, depths or stencil indices after the transfer operations, drawn at the raster position.
// The imaging operations may discard the colours (a histogram or minmax sink) or shrink the
// block (convolution in GL_REDUCE mode): the smaller block is drawn at the raster position.
void drawColorImage(Context& ctx, PixelBlock block, RgbaImage image) {
  block.width = image.width;
  block.height = image.height;
  if (block.width == 0 || block.height == 0) return;
  FragmentImage fragments = fragmentImageOf(block);
  fragments.colors = image.rgba.data();
  drawImageFragments(ctx, fragments);
}

void drawColors(Context& ctx, const PixelBlock& block, std::vector<float> rgba) {
  RgbaImage image{block.width, block.height, std::move(rgba)};
  if (!transferColorImage(ctx.pixelTransfer, ctx.imaging, image, 2)) return;
  drawColorImage(ctx, block, std::move(image));
}

void drawDepths(Context& ctx, const PixelBlock& block, std::vector<float> depth) {
  transferDepths(ctx.pixelTransfer, depth.data(), static_cast<int>(pixelCount(block.width, block.height)));
  FragmentImage image = fragmentImageOf(block);
  image.depths = depth.data();
  drawImageFragments(ctx, image);
}

void drawStencil(Context& ctx, const PixelBlock& block, std::vector<int32_t> indices) {
  transferStencilIndices(ctx.pixelTransfer, indices.data(), static_cast<int>(pixelCount(block.width, block.height)));
  FragmentImage image = fragmentImageOf(block);
  image.stencil = indices.data();
  drawStencilImage(ctx, image);
}

}  // namespace

UnpackedImage unpackImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                          const PixelPacking& unpack) {
  UnpackedImage image;
  image.width = width;
  image.height = height;
  const size_t count = pixelCount(width, height);
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
      image.kind = format == GL_STENCIL_INDEX ? PixelKind::Stencil : PixelKind::ColorIndex;
      image.indices.resize(count);
      for (int j = 0; j < height; ++j) {
        unpackIndexRow(pixels, width, j, type, unpack, image.indices.data() + static_cast<size_t>(j) * width);
      }
      break;
    case GL_DEPTH_COMPONENT:
      image.kind = PixelKind::Depth;
      image.values.resize(count);
      for (int j = 0; j < height; ++j) {
        unpackDepthRow(pixels, width, j, type, unpack, image.values.data() + static_cast<size_t>(j) * width);
      }
      break;
    default:
      image.kind = PixelKind::Color;
      image.values.resize(count * 4);
      for (int j = 0; j < height; ++j) {
        unpackColorRow(pixels, width, j, format, type, unpack,
                       image.values.data() + static_cast<size_t>(j) * width * 4);
      }
      break;
  }
  return image;
}

void drawPixels(Context& ctx, const UnpackedImage& image) {
  if (!shouldRasterize(ctx, GL_DRAW_PIXEL_TOKEN)) return;
  if (image.width == 0 || image.height == 0) return;
  switch (image.kind) {
    case PixelKind::Color:
      drawColors(ctx, PixelBlock{image.width, image.height}, image.values);
      break;
    case PixelKind::ColorIndex: {
      RgbaImage rgba{image.width, image.height,
                     std::vector<float>(pixelCount(image.width, image.height) * 4)};
      colorIndicesToRGBA(ctx.pixelTransfer, image.indices.data(), rgba.count(), rgba.rgba.data());
      if (!transferConvertedColorImage(ctx.imaging, rgba, 2)) return;
      drawColorImage(ctx, PixelBlock{image.width, image.height}, std::move(rgba));
      break;
    }
    case PixelKind::Depth:
      drawDepths(ctx, PixelBlock{image.width, image.height}, image.values);
      break;
    case PixelKind::Stencil:
      drawStencil(ctx, PixelBlock{image.width, image.height}, image.indices);
      break;
  }
}

void copyPixels(Context& ctx, int x, int y, int width, int height, GLenum type) {
  if (!shouldRasterize(ctx, GL_COPY_PIXEL_TOKEN)) return;
  if (width == 0 || height == 0) return;
  // Only the part of the rectangle inside the framebuffer is read and drawn: the specification
  // leaves copies from outside the window undefined, and so a huge rectangle costs no more than
  // the framebuffer. The whole part is read before anything is drawn, so that overlapping source
  // and destination rectangles copy the original pixels (spec 4.3.3: as if read, then drawn).
  const raster::Framebuffer& fb = ctx.framebuffer;
  const long long left = std::max<long long>(x, 0), bottom = std::max<long long>(y, 0);
  const long long right = std::min<long long>(static_cast<long long>(x) + width, fb.width());
  const long long top = std::min<long long>(static_cast<long long>(y) + height, fb.height());
  if (left >= right || bottom >= top) return;
  PixelBlock block;
  block.width = static_cast<int>(right - left);
  block.height = static_cast<int>(top - bottom);
  block.column0 = static_cast<int>(left - x);
  block.row0 = static_cast<int>(bottom - y);
  const int x0 = static_cast<int>(left), y0 = static_cast<int>(bottom);
  const size_t count = pixelCount(block.width, block.height);
  if (type == GL_COLOR) {
    std::vector<float> rgba(count * 4);
    {
      const ReadBufferSelection read(ctx);  // the read buffer's pixels; drawn into the draw buffer
      for (int j = 0; j < block.height; ++j) {
        for (int i = 0; i < block.width; ++i) {
          const uint8_t* c = fb.colorAt(x0 + i, y0 + j);
          float* out = &rgba[(static_cast<size_t>(j) * block.width + i) * 4];
          for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(c[k]) / 255.0f;
        }
      }
    }
    drawColors(ctx, block, std::move(rgba));
  } else if (type == GL_DEPTH) {
    std::vector<float> depth(count);
    for (int j = 0; j < block.height; ++j) {
      for (int i = 0; i < block.width; ++i) {
        depth[static_cast<size_t>(j) * block.width + i] =
            static_cast<float>(static_cast<double>(*fb.depthAt(x0 + i, y0 + j)) / raster::kDepthMax);
      }
    }
    drawDepths(ctx, block, std::move(depth));
  } else {
    std::vector<int32_t> indices(count);
    for (int j = 0; j < block.height; ++j) {
      for (int i = 0; i < block.width; ++i) {
        indices[static_cast<size_t>(j) * block.width + i] = *fb.stencilAt(x0 + i, y0 + j);
      }
    }
    drawStencil(ctx, block, std::move(indices));
  }
}

void drawBitmap(Context& ctx, int width, int height, float xorig, float yorig, float xmove,
                float ymove, const std::vector<uint8_t>& bits) {
  RasterPositionState& r = ctx.rasterPosition;
  if (!r.valid) return;  // an invalid raster position is not moved either (spec 3.7)
  if (ctx.renderMode.mode == GL_RENDER) {
    if (width > 0 && height > 0 && !bits.empty()) {
      // Spec 3.7: the bitmap's lower left corner is at (floor(x_rp - x_o), floor(y_rp - y_o)).
      // Like Mesa (and SGI's implementation), a raster position 1e-4 below an integer counts as
      // that integer, so that positions computed as whole pixels with a rounding error stay put.
      const float epsilon = 0.0001f;
      const int xll = floorToPixel(double(r.window[0] + epsilon - xorig));
      const int yll = floorToPixel(double(r.window[1] + epsilon - yorig));
      drawBitmapFragments(ctx, xll, yll, width, height, bits.data());
    }
  } else {
    recordPixelCommand(ctx, GL_BITMAP_TOKEN);
  }
  r.window[0] += xmove;
  r.window[1] += ymove;
}

}  // namespace glass::gl
