#include "core/png_writer.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <vector>

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

namespace glass::gl {

namespace {

// stb's writer reports nothing; a short write sets the stream's error flag, checked below.
void writeToFile(void* file, void* data, int size) {
  fwrite(data, 1, static_cast<size_t>(size), static_cast<FILE*>(file));
}

}  // namespace

bool writeColorBufferPNG(const raster::Framebuffer& fb, const char* path) {
  return writeRGBAPixelsPNG(fb.colorAt(0, 0), fb.width(), fb.height(), path);
}

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

  // The temporary file sits next to the target so that rename() replaces it atomically.
  std::string temporary = std::string(path) + ".XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) return false;
  FILE* file = fdopen(fd, "wb");
  if (!file) {
    close(fd);
    unlink(temporary.c_str());
    return false;
  }
  bool ok = stbi_write_png_to_func(writeToFile, file, width, height, 3, rgb.data(),
                                   static_cast<int>(rowBytes)) != 0;
  ok = !ferror(file) && ok;
  ok = fclose(file) == 0 && ok;
  // mkstemp creates the file readable by its owner only; give it the usual permissions.
  const mode_t mask = umask(0);
  umask(mask);
  ok = ok && chmod(temporary.c_str(), 0666 & ~mask) == 0;
  ok = ok && rename(temporary.c_str(), path) == 0;
  if (!ok) unlink(temporary.c_str());
  return ok;
}

}  // namespace glass::gl
