#include "pixels/imaging_client_data.h"

#include "core/context.h"
#include "pixels/imaging_formats.h"
#include "texture/client_pixels.h"

namespace glass::gl {

GLenum checkImagingFormatAndType(GLenum format, GLenum type) {
  const GLenum error = checkPixelFormatAndType(format, type);
  if (error != GL_NO_ERROR) return error;
  return isColorFormat(format) ? GL_NO_ERROR : GL_INVALID_ENUM;
}

GLenum checkImagingQuery(bool targetTaken, GLenum format, GLenum type) {
  return targetTaken ? checkImagingFormatAndType(format, type) : GL_INVALID_ENUM;
}

std::vector<float> unpackRgbaBlock(const void* pixels, int width, int height, GLenum format,
                                   GLenum type, const PixelPacking& unpack) {
  std::vector<float> rgba(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  for (int j = 0; j < height; ++j) {
    unpackColorRow(pixels, width, j, format, type, unpack, rgba.data() + static_cast<size_t>(j) * width * 4);
  }
  return rgba;
}

std::vector<float> readColorBlock(const Context& ctx, int x, int y, int width, int height) {
  const raster::Framebuffer& fb = ctx.framebuffer;
  std::vector<float> rgba(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 0.0f);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const long long fx = static_cast<long long>(x) + i, fy = static_cast<long long>(y) + j;
      if (fx < 0 || fy < 0 || fx >= fb.width() || fy >= fb.height()) continue;
      const uint8_t* c = fb.colorAt(static_cast<int>(fx), static_cast<int>(fy));
      float* out = &rgba[(static_cast<size_t>(j) * width + i) * 4];
      for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(c[k]) / 255.0f;
    }
  }
  return rgba;
}

void packRgbaBlock(const float* rgba, int width, int height, GLenum format, GLenum type,
                   const PixelPacking& pack, void* pixels) {
  for (int j = 0; j < height; ++j) {
    packColorSpan(rgba + static_cast<size_t>(j) * width * 4, width, width, 0, j, format, type, pack,
                  LuminancePacking::Red, pixels);
  }
}

bool readsClientDataNow(const Context& ctx) { return !ctx.assembly.active || ctx.lists.isCompiling(); }

bool isColorTableFormat(GLenum internalFormat) {
  BaseFormat base;
  return imagingBaseFormat(internalFormat, &base);
}

bool isHistogramFormat(GLenum internalFormat) {
  BaseFormat base;
  return imagingBaseFormat(internalFormat, &base) && base != BaseFormat::Intensity;
}

}  // namespace glass::gl
