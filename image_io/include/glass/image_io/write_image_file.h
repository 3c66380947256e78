// Picture files written whole or not at all: PNG, JPEG, BMP and TGA through stb_image_write.
#pragma once

#include <cstdint>
#include <string>

namespace glass::image_io {

enum class ImageFormat { None, Png, Jpeg, Bmp, Tga };

// The format a file name asks for by its extension (.png, .jpg or .jpeg, .bmp, .tga, in any
// case); None for anything else.
ImageFormat imageFormatOf(const std::string& path);

// Writes width x height RGB pixels (3 bytes each, rows top first, no padding) to path. The
// picture goes to a new temporary file next to path, created with the permissions of any new file
// (0666 less the umask, applied by the system, so no process-wide state is touched), and is
// renamed over path once complete: a reader sees the old file or the whole new one. On failure
// the temporary file is removed, path is untouched, and reason says why.
bool writeImageFile(const std::string& path, ImageFormat format, int width, int height,
                    const std::uint8_t* rgb, std::string& reason);

}  // namespace glass::image_io
