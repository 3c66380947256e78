// Writing pictures: PNG, JPEG, BMP and TGA, whole or not at all (glass/image_io).
#include "glass/scene/render.h"

#include <cstring>

#include "glass/image_io/write_image_file.h"

namespace glass::scene {

bool isSupportedImagePath(const std::string &path) {
  return image_io::imageFormatOf(path) != image_io::ImageFormat::None;
}

bool writeImage(const std::string &path, const Image &image, std::string &reason) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i) {
    std::memcpy(&rgb[3 * i], &image.rgba[4 * i], 3);
  }
  return image_io::writeImageFile(path, image_io::imageFormatOf(path), image.width, image.height,
                                  rgb.data(), reason);
}

} // namespace glass::scene
