#include "image_file.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

// stb_image is private to this file (STB_IMAGE_STATIC), so it cannot clash with another copy in
// the GL library or a program.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace glass::scene {

bool loadImageFile(const std::string &path, Image &image, std::string &reason) {
  std::FILE *file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    reason = std::strerror(errno);
    return false;
  }
  int width = 0, height = 0, channels = 0;
  unsigned char *pixels = stbi_load_from_file(file, &width, &height, &channels, 4);
  std::fclose(file);
  if (pixels == nullptr) {
    const char *why = stbi_failure_reason();
    reason = std::string("not a picture stb_image can read (") + (why ? why : "unknown format") + ")";
    return false;
  }
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  stbi_image_free(pixels);
  return true;
}

Image makeCheckerImage(int size, int squares, const double first[4], const double second[4]) {
  Image image;
  image.width = size;
  image.height = size;
  image.rgba.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      int cell = (x * squares / size + y * squares / size) % 2;
      const double *colour = cell == 0 ? first : second;
      std::uint8_t *p = &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(size) +
                                     static_cast<std::size_t>(x)) * 4];
      for (int c = 0; c < 4; ++c) {
        double v = colour[c] < 0.0 ? 0.0 : colour[c] > 1.0 ? 1.0 : colour[c];
        p[c] = static_cast<std::uint8_t>(std::lround(v * 255.0));
      }
    }
  }
  return image;
}

} // namespace glass::scene
