#include "glass/image_io/write_image_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

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

namespace glass::image_io {

namespace {

// stb's writer reports nothing; a short write sets the stream's error flag, checked after.
void writeToFile(void* file, void* data, int size) {
  std::fwrite(data, 1, static_cast<std::size_t>(size), static_cast<std::FILE*>(file));
}

// A new file next to path, opened for writing: path.tmp-PID-N with the first N (counting across
// threads) that names no file yet. O_EXCL makes the creation fail rather than reuse a file, and
// the mode 0666 is reduced by the umask in the kernel, as for any new file. -1 on failure.
int createTemporaryFile(const std::string& path, std::string& temporary) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
    const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

}  // namespace

ImageFormat imageFormatOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::Png;
  if (extension == ".jpg" || extension == ".jpeg") return ImageFormat::Jpeg;
  if (extension == ".bmp") return ImageFormat::Bmp;
  if (extension == ".tga") return ImageFormat::Tga;
  return ImageFormat::None;
}

bool writeImageFile(const std::string& path, ImageFormat format, int width, int height,
                    const std::uint8_t* rgb, std::string& reason) {
  if (format == ImageFormat::None) {
    reason = "unknown picture format: the name must end in .png, .jpg, .jpeg, .bmp or .tga";
    return false;
  }
  if (path.empty()) {
    reason = "no file name";
    return false;
  }
  std::string temporary;
  const int fd = createTemporaryFile(path, temporary);
  if (fd < 0) {
    reason = std::strerror(errno);
    return false;
  }
  std::FILE* file = fdopen(fd, "wb");
  if (file == nullptr) {
    reason = std::strerror(errno);
    close(fd);
    unlink(temporary.c_str());
    return false;
  }
  int ok = 0;
  switch (format) {
    case ImageFormat::Png:
      ok = stbi_write_png_to_func(writeToFile, file, width, height, 3, rgb, width * 3);
      break;
    case ImageFormat::Jpeg: ok = stbi_write_jpg_to_func(writeToFile, file, width, height, 3, rgb, 95); break;
    case ImageFormat::Bmp: ok = stbi_write_bmp_to_func(writeToFile, file, width, height, 3, rgb); break;
    case ImageFormat::Tga: ok = stbi_write_tga_to_func(writeToFile, file, width, height, 3, rgb); break;
    case ImageFormat::None: break;
  }
  bool good = ok != 0 && std::ferror(file) == 0;
  if (!good) reason = std::ferror(file) ? std::strerror(errno) : "cannot encode the picture";
  if (std::fclose(file) != 0 && good) {
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

}  // namespace glass::image_io
