// Reading pictures for textures: PNG, JPEG, BMP, TGA (and the other formats stb_image reads).
#pragma once

#include "glass/scene/program.h"

#include <string>

namespace glass::scene {

// Reads `path` into RGBA8, top row first. On failure returns false and says why in `reason`.
bool loadImageFile(const std::string &path, Image &image, std::string &reason);

// A checkerboard of `squares` x `squares` squares, `size` pixels a side.
Image makeCheckerImage(int size, int squares, const double first[4], const double second[4]);

} // namespace glass::scene
