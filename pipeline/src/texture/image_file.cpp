// glass/image.h: image files decoded by stb_image (Debian's libstb-dev). The decoder is compiled
// into this file only, with internal linkage (STB_IMAGE_STATIC), so it cannot clash with another
// copy of stb_image in a program that links libglass.
#include "glass/image.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace glass {

bool loadImageFile(const std::string& path, Image& image, std::string& error) {
  image = Image();
  error.clear();
  struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    error = path + ": cannot open the file (" + std::strerror(errno) + ")";
    return false;
  }
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_file(file.get(), &width, &height, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    error = path + ": not an image in a supported format (PNG, JPEG, BMP, TGA)" +
            (reason != nullptr ? std::string(": ") + reason : std::string());
    return false;
  }
  image.width = width;
  image.height = height;
  const size_t rowBytes = static_cast<size_t>(width) * 4;
  image.rgba.resize(rowBytes * static_cast<size_t>(height));
  // Files store the top row first; GL texture rows start at the bottom (t = 0).
  for (int row = 0; row < height; ++row)
    std::memcpy(&image.rgba[static_cast<size_t>(height - 1 - row) * rowBytes],
                pixels + static_cast<size_t>(row) * rowBytes, rowBytes);
  stbi_image_free(pixels);
  return true;
}

}  // namespace glass
