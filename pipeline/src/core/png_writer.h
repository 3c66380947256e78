// Writing the colour buffer to a PNG file, whole or not at all.
#pragma once

namespace glass::gl {

// Writes width * height RGBA8 pixels, bottom row first, rows packed (a colour buffer or a copy
// of one), as an RGB PNG, top row first, alpha left out, whole or not at all
// (glass/image_io/write_image_file.h). Returns false on failure.
bool writeRGBAPixelsPNG(const unsigned char* rgba, int width, int height, const char* path);

}  // namespace glass::gl
