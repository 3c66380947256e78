// Image files as texture data: PNG, JPEG, BMP and TGA (read with stb_image) decoded to 8-bit RGBA
// rows, bottom row first, ready for
//   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA,
//                GL_UNSIGNED_BYTE, image.rgba.data());
// (rows are tightly packed: 4 * width bytes, so any GL_UNPACK_ALIGNMENT works). The file's top
// row becomes the texture's top row (t = 1), so the picture appears upright on a quad whose
// texture coordinates grow upwards.
#pragma once

#include <string>
#include <vector>

#if defined(__GNUC__)
#define GLASS_IMAGE_API __attribute__((visibility("default")))
#else
#define GLASS_IMAGE_API
#endif

namespace glass {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba;  // width * height * 4 bytes, bottom row first
};

// Reads an image file. On success fills `image` and returns true. On failure returns false,
// leaves `image` empty and sets `error` to a message that names the path and the reason, such
// as "textures/wall.png: cannot open the file (No such file or directory)" or
// "textures/wall.png: not an image in a supported format (PNG, JPEG, BMP, TGA): unknown image type".
GLASS_IMAGE_API bool loadImageFile(const std::string& path, Image& image, std::string& error);

}  // namespace glass
