#include "texture/depth_texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glass::gl {

bool isDepthInternalFormat(GLint internalFormat) {
  return internalFormat == GL_DEPTH_COMPONENT || internalFormat == GL_DEPTH_COMPONENT16 ||
         internalFormat == GL_DEPTH_COMPONENT24 || internalFormat == GL_DEPTH_COMPONENT32;
}

int depthBitsOfInternalFormat(GLint internalFormat) {
  // The specification lets the GL choose the resolution (3.8.1); 24 bits is the depth buffer's,
  // so a copy of the depth buffer is exact, and no 32-bit request is answered with more bits
  // than the values it can be given carry.
  return internalFormat == GL_DEPTH_COMPONENT16 ? 16 : 24;
}

bool takesDepthImages(GLenum target) {
  return target == GL_TEXTURE_1D || target == GL_TEXTURE_2D || target == GL_PROXY_TEXTURE_1D ||
         target == GL_PROXY_TEXTURE_2D;
}

void unpackDepthTexels(const void* pixels, int width, int height, GLenum type,
                       const PixelLayout& layout, float depthScale, float depthBias,
                       std::vector<uint8_t>& out) {
  out.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 0);
  std::vector<float> row(static_cast<size_t>(width));
  for (int j = 0; j < height; ++j) {
    unpackDepthRow(pixels, width, j, type, layout, row.data());
    for (int i = 0; i < width; ++i) {
      const float d = std::clamp(row[static_cast<size_t>(i)] * depthScale + depthBias, 0.0f, 1.0f);
      std::memcpy(&out[(static_cast<size_t>(j) * static_cast<size_t>(width) +
                        static_cast<size_t>(i)) * 4],
                  &d, 4);
    }
  }
}

float depthFromTexelBits(const uint8_t bits[4]) {
  float d;
  std::memcpy(&d, bits, 4);
  return d == d ? std::clamp(d, 0.0f, 1.0f) : 0.0f;
}

void setDepthTexel(TextureImage& image, int i, int j, float depth) {
  const double levels = std::ldexp(1.0, image.depthBits) - 1.0;
  const float quantized = static_cast<float>(std::nearbyint(std::clamp(depth, 0.0f, 1.0f) * levels) / levels);
  image.depths[image.texelIndex(i, j, 0)] = quantized;
  uint8_t* texel = image.texel(i, j);
  texel[0] = texel[1] = texel[2] = texel[3] = unitFloatToByte(quantized);
}

void finishDepthImage(TextureImage& image, int bits) {
  image.depthBits = bits;
  image.base = BaseFormat::Luminance;
  image.depths.assign(static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 0.0f);
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) setDepthTexel(image, i, j, depthFromTexelBits(image.texel(i, j)));
}

void allocateDepthImage(TextureImage& image, int bits) {
  image.depthBits = bits;
  image.base = BaseFormat::Luminance;
  image.depths.assign(static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 0.0f);
  image.texels.assign(static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4, 0);
}

}  // namespace glass::gl
