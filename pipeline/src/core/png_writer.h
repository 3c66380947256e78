// Writing the colour buffer to a PNG file, whole or not at all.
#pragma once

#include "glass/raster/framebuffer.h"

namespace glass::gl {

// Writes an RGB PNG, top row first (the framebuffer's last row), alpha left out, whole or not at
// all (glass/image_io/write_image_file.h). Returns false on failure.
bool writeColorBufferPNG(const raster::Framebuffer& framebuffer, const char* path);

// The same for width * height RGBA8 pixels, bottom row first, rows packed (a copy of a colour
// buffer).
bool writeRGBAPixelsPNG(const unsigned char* rgba, int width, int height, const char* path);

}  // namespace glass::gl
