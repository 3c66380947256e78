#include "core/png_writer.h"

#include <cstring>
#include <string>
#include <vector>

#include "glass/image_io/write_image_file.h"

namespace glass::gl {

bool writeRGBAPixelsPNG(const unsigned char* rgba, int width, int height, const char* path) {
  if (!path || !*path || !rgba || width <= 0 || height <= 0) return false;
  const size_t rowBytes = static_cast<size_t>(width) * 3;
  std::vector<unsigned char> rgb(rowBytes * static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) {
    // GL's row 0 is the bottom row; a PNG starts with the top row.
    unsigned char* out = rgb.data() + static_cast<size_t>(height - 1 - y) * rowBytes;
    const unsigned char* in = rgba + static_cast<size_t>(y) * width * 4;
    for (int x = 0; x < width; ++x) std::memcpy(out + 3 * x, in + 4 * x, 3);
  }
  std::string reason;
  return image_io::writeImageFile(path, image_io::ImageFormat::Png, width, height, rgb.data(),
                                  reason);
}

}  // namespace glass::gl
