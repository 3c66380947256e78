#include "fragment/read_pixels.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/context.h"
#include "core/pixel_store.h"
#include "glass/raster/fragment.h"
#include "pixels/imaging_client_data.h"
#include "pixels/imaging_pipeline.h"
#include "pixels/pixel_transfer.h"
#include "texture/client_pixels.h"

namespace glass::gl {

GLenum checkReadPixelsFormatAndType(GLenum format, GLenum type) {
  const GLenum error = checkPixelFormatAndType(format, type);
  if (error != GL_NO_ERROR) return error;
  return format == GL_COLOR_INDEX ? GL_INVALID_OPERATION : GL_NO_ERROR;
}

namespace {

// Whether the depth transfer operations leave values as they are.
bool depthTransferIsIdentity(const PixelTransferState& t) {
  return t.depthScale == 1.0f && t.depthBias == 0.0f;
}

// GL_UNSIGNED_INT depth without transfer operations: the 24-bit value scaled to 32 bits exactly,
// d * (2^32 - 1) / (2^24 - 1) by bit replication, as Mesa reads a 24-bit depth buffer.
void packDepthBits(const uint32_t* depth, int count, int width, int column, int row,
                   const PixelPacking& pack, void* pixels) {
  std::vector<uint32_t> bits(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) bits[i] = (depth[i] << 8) | (depth[i] >> 16);
  packIndexSpan(bits.data(), count, width, column, row, GL_UNSIGNED_INT, pack, pixels);
}

// Colours with the imaging operations (pixels/imaging_pipeline.h): the whole block is read first,
// since convolution needs the neighbours of each group (groups outside the framebuffer read as
// 0), and the image the operations leave, smaller after a GL_REDUCE convolution, is packed as a
// block of its own size. A sink leaves client memory as it is.
void readColorImage(Context& ctx, int x, int y, int width, int height, GLenum format, GLenum type,
                    void* pixels) {
  RgbaImage image{width, height, readColorBlock(ctx, x, y, width, height)};
  if (!transferColorImage(ctx.pixelTransfer, ctx.imaging, image, 2)) return;
  for (int row = 0; row < image.height; ++row) {
    // Spec 4.3.2: luminance is the sum R + G + B, clamped.
    packColorSpan(image.at(0, row), image.width, image.width, 0, row, format, type,
                  ctx.pixelStore.pack, LuminancePacking::Sum, pixels);
  }
}

}  // namespace

void readPixels(Context& ctx, int x, int y, int width, int height, GLenum format,
                GLenum type, void* pixels) {
  const raster::Framebuffer& fb = ctx.framebuffer;
  const PixelPacking& pack = ctx.pixelStore.pack;
  const PixelTransferState& transfer = ctx.pixelTransfer;
  if (format != GL_STENCIL_INDEX && format != GL_DEPTH_COMPONENT && imagingActive(ctx.imaging)) {
    readColorImage(ctx, x, y, width, height, format, type, pixels);
    return;
  }

  // The part of each row inside the framebuffer: columns [first, end) of the block.
  const int first = static_cast<int>(std::clamp<long long>(-static_cast<long long>(x), 0, width));
  const int end = static_cast<int>(std::clamp<long long>(static_cast<long long>(fb.width()) - x, first, width));
  const int count = end - first;
  if (count <= 0) return;

  // Colour bytes as they are stored, when the transfer operations would give them back unchanged.
  const bool copiesStoredBytes = colorTransferChangesNothing(transfer);
  std::vector<float> values(static_cast<size_t>(count) * 4);
  std::vector<uint32_t> raw(static_cast<size_t>(count));
  std::vector<int32_t> indices(static_cast<size_t>(count));
  for (int row = 0; row < height; ++row) {
    const long long fy = static_cast<long long>(y) + row;
    if (fy < 0 || fy >= fb.height()) continue;
    const int py = static_cast<int>(fy);
    const int px = x + first;
    if (format == GL_STENCIL_INDEX) {
      for (int i = 0; i < count; ++i) indices[i] = *fb.stencilAt(px + i, py);
      transferStencilIndices(transfer, indices.data(), count);
      for (int i = 0; i < count; ++i) raw[i] = static_cast<uint32_t>(indices[i]);
      packIndexSpan(raw.data(), count, width, first, row, type, pack, pixels);
    } else if (format == GL_DEPTH_COMPONENT) {
      for (int i = 0; i < count; ++i) raw[i] = *fb.depthAt(px + i, py);
      if (type == GL_UNSIGNED_INT && depthTransferIsIdentity(transfer)) {
        packDepthBits(raw.data(), count, width, first, row, pack, pixels);
        continue;
      }
      for (int i = 0; i < count; ++i) {
        values[i] = static_cast<float>(static_cast<double>(raw[i]) / raster::kDepthMax);
      }
      transferDepths(transfer, values.data(), count);
      packDepthSpan(values.data(), count, width, first, row, type, pack, pixels);
    } else {
      // packByteColorSpan takes the formats whose bytes are copied as they are.
      if (copiesStoredBytes &&
          packByteColorSpan(fb.colorAt(px, py), count, width, first, row, format, type, pack, pixels))
        continue;
      for (int i = 0; i < count; ++i) {
        const uint8_t* c = fb.colorAt(px + i, py);
        for (int k = 0; k < 4; ++k) values[static_cast<size_t>(i) * 4 + k] = static_cast<float>(c[k]) / 255.0f;
      }
      transferColors(transfer, values.data(), count);
      // Spec 4.3.2: luminance is the sum R + G + B, clamped.
      packColorSpan(values.data(), count, width, first, row, format, type, pack,
                    LuminancePacking::Sum, pixels);
    }
  }
}

}  // namespace glass::gl
