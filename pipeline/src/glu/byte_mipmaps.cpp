#include "glu/byte_mipmaps.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "glu/client_image.h"

namespace glass::glu {
namespace {

// A tightly packed image of bytes: component c of texel (i, j) at (j width + i) components + c.
struct ByteImage {
  int width = 0, height = 0, components = 0;
  std::vector<unsigned char> bytes;
  const unsigned char* texel(int i, int j) const {
    return bytes.data() + (static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i)) *
                              static_cast<std::size_t>(components);
  }
};

// halveImage for GL_UNSIGNED_BYTE, into `out` (its buffer reused).
void halveBytes(const ByteImage& in, ByteImage& out) {
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.components = in.components;
  out.bytes.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) *
                   static_cast<std::size_t>(out.components));
  const int n = in.components;
  unsigned char* to = out.bytes.data();
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i)
      for (int c = 0; c < n; ++c) {
        if (in.width != 1 && in.height != 1) {
          const unsigned char* upper = in.texel(2 * i, 2 * j);
          const unsigned char* lower = in.texel(2 * i, 2 * j + 1);
          *to++ = static_cast<unsigned char>((upper[c] + upper[n + c] + lower[c] + lower[n + c] + 2) / 4);
        } else if (in.height == 1) {
          *to++ = static_cast<unsigned char>((in.texel(2 * i, 0)[c] + in.texel(2 * i + 1, 0)[c]) / 2);
        } else {
          *to++ = static_cast<unsigned char>((in.texel(0, 2 * j)[c] + in.texel(0, 2 * j + 1)[c]) / 2);
        }
      }
}

}  // namespace

void loadByteLevels(GLenum target, GLint internalFormat, int width, int height, GLenum format, const void* data,
                    GLint level, GLint base, GLint max) {
  const ClientLayout layout = clientLayout(2, width, height, format, GL_UNSIGNED_BYTE, data);
  ByteImage image{width, height, componentsOfFormat(format), {}};
  const std::size_t rowBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(image.components);
  image.bytes.resize(rowBytes * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j)
    std::memcpy(image.bytes.data() + static_cast<std::size_t>(j) * rowBytes,
                layout.first + static_cast<std::size_t>(j) * layout.rowBytes, rowBytes);
  ByteImage next;
  for (GLint l = level; l <= max; ++l) {
    if (l > level) {
      halveBytes(image, next);
      std::swap(image, next);
    }
    if (l >= base)
      uploadPackedLevel(target, 2, l, internalFormat, image.width, image.height, 1, format, GL_UNSIGNED_BYTE,
                        image.bytes.data());
  }
}

}  // namespace glass::glu
