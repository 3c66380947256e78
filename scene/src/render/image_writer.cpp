// Writing pictures: PNG, JPEG, BMP and TGA through stb_image_write, atomically.
#include "glass/scene/render.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

// stb_image_write is private to this file (STB_IMAGE_WRITE_STATIC).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace glass::scene {

namespace {

enum class Format { None, Png, Jpeg, Bmp, Tga };

Format formatOf(const std::string &path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return Format::Png;
  if (extension == ".jpg" || extension == ".jpeg") return Format::Jpeg;
  if (extension == ".bmp") return Format::Bmp;
  if (extension == ".tga") return Format::Tga;
  return Format::None;
}

void writeToFile(void *file, void *data, int size) {
  std::fwrite(data, 1, static_cast<std::size_t>(size), static_cast<std::FILE *>(file));
}

} // namespace

bool isSupportedImagePath(const std::string &path) { return formatOf(path) != Format::None; }

bool writeImage(const std::string &path, const Image &image, std::string &reason) {
  Format format = formatOf(path);
  if (format == Format::None) {
    reason = "unknown picture format: the name must end in .png, .jpg, .jpeg, .bmp or .tga";
    return false;
  }
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i) {
    std::memcpy(&rgb[3 * i], &image.rgba[4 * i], 3);
  }
  // The temporary file sits next to the target so that rename() replaces it in one step.
  std::string temporary = path + ".XXXXXX";
  int fd = mkstemp(temporary.data());
  if (fd < 0) {
    reason = std::strerror(errno);
    return false;
  }
  std::FILE *file = fdopen(fd, "wb");
  if (file == nullptr) {
    reason = std::strerror(errno);
    close(fd);
    unlink(temporary.c_str());
    return false;
  }
  int w = image.width, h = image.height;
  int ok = 0;
  switch (format) {
  case Format::Png: ok = stbi_write_png_to_func(writeToFile, file, w, h, 3, rgb.data(), w * 3); break;
  case Format::Jpeg: ok = stbi_write_jpg_to_func(writeToFile, file, w, h, 3, rgb.data(), 95); break;
  case Format::Bmp: ok = stbi_write_bmp_to_func(writeToFile, file, w, h, 3, rgb.data()); break;
  case Format::Tga: ok = stbi_write_tga_to_func(writeToFile, file, w, h, 3, rgb.data()); break;
  case Format::None: break;
  }
  bool good = ok != 0 && std::ferror(file) == 0;
  if (!good) reason = "cannot encode the picture";
  if (std::fclose(file) != 0 && good) {
    good = false;
    reason = std::strerror(errno);
  }
  // mkstemp makes the file readable by its owner only; give it the usual permissions.
  mode_t mask = umask(0);
  umask(mask);
  if (good && chmod(temporary.c_str(), 0666 & ~mask) != 0) {
    good = false;
    reason = std::strerror(errno);
  }
  if (good && std::rename(temporary.c_str(), path.c_str()) != 0) {
    good = false;
    reason = std::strerror(errno);
  }
  if (!good) unlink(temporary.c_str());
  return good;
}

} // namespace glass::scene
