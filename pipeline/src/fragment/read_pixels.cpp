#include "fragment/read_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/context.h"
#include "core/pixel_store.h"
#include "fragment/color_conversion.h"
#include "glass/raster/fragment.h"

namespace glass::gl {

bool isReadPixelsFormat(GLenum format) {
  switch (format) {
    case GL_RGBA: case GL_RGB: case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA:
    case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_BGR: case GL_BGRA:
    case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX:
      return true;
    default:
      return false;
  }
}

bool isReadPixelsType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
      return true;
    default:
      return false;
  }
}

namespace {

int componentCount(GLenum format) {
  switch (format) {
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 1;
  }
}

int typeBytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    default: return 4;
  }
}

// The components of one colour pixel in the order the format lists them (spec 4.3.2: luminance
// is R + G + B, clamped).
void colorComponents(const uint8_t* rgba, GLenum format, double* out) {
  double c[4];
  for (int i = 0; i < 4; ++i) c[i] = rgba[i] / 255.0;
  switch (format) {
    case GL_RGBA: std::copy(c, c + 4, out); break;
    case GL_RGB: std::copy(c, c + 3, out); break;
    case GL_BGRA: out[0] = c[2]; out[1] = c[1]; out[2] = c[0]; out[3] = c[3]; break;
    case GL_BGR: out[0] = c[2]; out[1] = c[1]; out[2] = c[0]; break;
    case GL_RED: out[0] = c[0]; break;
    case GL_GREEN: out[0] = c[1]; break;
    case GL_BLUE: out[0] = c[2]; break;
    case GL_ALPHA: out[0] = c[3]; break;
    case GL_LUMINANCE: out[0] = std::min(1.0, c[0] + c[1] + c[2]); break;
    case GL_LUMINANCE_ALPHA: out[0] = std::min(1.0, c[0] + c[1] + c[2]); out[1] = c[3]; break;
    default: break;
  }
}

// Writes a component in [0, 1] as `type` (spec 4.3.2, table 4.7): unsigned b-bit types hold
// (2^b - 1) c, signed ones ((2^b - 1) c - 1) / 2, GL_FLOAT c itself.
void packNormalized(double c, GLenum type, unsigned char* out) {
  switch (type) {
    case GL_UNSIGNED_BYTE: { const GLubyte v = static_cast<GLubyte>(std::lround(c * 255.0)); std::memcpy(out, &v, 1); break; }
    case GL_BYTE: { const GLbyte v = static_cast<GLbyte>(std::lround((c * 255.0 - 1.0) / 2.0)); std::memcpy(out, &v, 1); break; }
    case GL_UNSIGNED_SHORT: { const GLushort v = static_cast<GLushort>(std::lround(c * 65535.0)); std::memcpy(out, &v, 2); break; }
    case GL_SHORT: { const GLshort v = static_cast<GLshort>(std::lround((c * 65535.0 - 1.0) / 2.0)); std::memcpy(out, &v, 2); break; }
    case GL_UNSIGNED_INT: { const GLuint v = static_cast<GLuint>(std::llround(c * 4294967295.0)); std::memcpy(out, &v, 4); break; }
    case GL_INT: { const GLint v = static_cast<GLint>(std::llround((c * 4294967295.0 - 1.0) / 2.0)); std::memcpy(out, &v, 4); break; }
    default: { const GLfloat v = static_cast<GLfloat>(c); std::memcpy(out, &v, 4); break; }
  }
}

// Stencil indices are integers: they are written as numbers, masked to the type's width.
void packIndex(unsigned index, GLenum type, unsigned char* out) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: { const uint8_t v = static_cast<uint8_t>(index); std::memcpy(out, &v, 1); break; }
    case GL_UNSIGNED_SHORT: case GL_SHORT: { const uint16_t v = static_cast<uint16_t>(index); std::memcpy(out, &v, 2); break; }
    case GL_FLOAT: { const GLfloat v = static_cast<GLfloat>(index); std::memcpy(out, &v, 4); break; }
    default: { const uint32_t v = index; std::memcpy(out, &v, 4); break; }
  }
}

void swapBytes(unsigned char* p, int size) { std::reverse(p, p + size); }

}  // namespace

void readPixels(const Context& ctx, int x, int y, int width, int height, GLenum format,
                GLenum type, void* pixels) {
  const raster::Framebuffer& fb = ctx.framebuffer;
  const PixelPacking& pack = ctx.pixelStore.pack;
  const int components = componentCount(format);
  const int size = typeBytes(type);
  const int pixelBytes = components * size;
  const long long rowStride = rowStrideBytes(pack, width, pixelBytes, size);
  auto* base = static_cast<unsigned char*>(pixels) + pack.skipRows * rowStride +
               static_cast<long long>(pack.skipPixels) * pixelBytes;

  for (int row = 0; row < height; ++row) {
    const int fy = y + row;
    if (fy < 0 || fy >= fb.height()) continue;
    unsigned char* out = base + row * rowStride;
    for (int column = 0; column < width; ++column) {
      const int fx = x + column;
      if (fx < 0 || fx >= fb.width()) continue;
      unsigned char* pixel = out + static_cast<long long>(column) * pixelBytes;
      if (format == GL_STENCIL_INDEX) {
        packIndex(*fb.stencilAt(fx, fy), type, pixel);
      } else if (format == GL_DEPTH_COMPONENT) {
        const uint32_t d = *fb.depthAt(fx, fy);
        if (type == GL_UNSIGNED_INT) {
          // The 24-bit value scaled to 32 bits exactly: d * (2^32 - 1) / (2^24 - 1).
          const uint32_t v = (d << 8) | (d >> 16);
          std::memcpy(pixel, &v, 4);
        } else {
          packNormalized(static_cast<double>(d) / raster::kDepthMax, type, pixel);
        }
      } else {
        double c[4];
        colorComponents(fb.colorAt(fx, fy), format, c);
        for (int i = 0; i < components; ++i) packNormalized(c[i], type, pixel + i * size);
      }
      if (pack.swapBytes && size > 1) {
        for (int i = 0; i < components; ++i) swapBytes(pixel + i * size, size);
      }
    }
  }
}

}  // namespace glass::gl
