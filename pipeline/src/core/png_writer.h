// Writing the colour buffer to a PNG file, whole or not at all.
#pragma once

#include "glass/raster/framebuffer.h"

namespace glass::gl {

// Writes an RGB PNG, top row first (the framebuffer's last row), alpha left out. The PNG goes to
// a temporary file in the directory of path, renamed over path once complete; on any failure the
// temporary file is removed and path is untouched. Returns false on failure.
bool writeColorBufferPNG(const raster::Framebuffer& framebuffer, const char* path);

// The same for width * height RGBA8 pixels, bottom row first, rows packed (a copy of a colour
// buffer).
bool writeRGBAPixelsPNG(const unsigned char* rgba, int width, int height, const char* path);

}  // namespace glass::gl
