// Turning what the GL read back into pictures: the colour buffer, the depth buffer as grey, the
// overdraw count as a heat map, and the box filter of supersampling.
#pragma once

#include "glass/scene/program.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glass::scene {

// glReadPixels rows (bottom row first, 4 bytes a pixel) to a top-first image, turned over in
// place: a frame as large as 16384 x 16384 is a gigabyte, and a copy would be a second one.
Image imageFromGlRows(std::vector<std::uint8_t> rgba, int width, int height);

// Depth values (bottom row first) as grey: the nearest depth drawn is black, the farthest drawn
// white; pixels nothing was drawn on (depth = the clear value 1) are white too. `notes` gets
// the range.
Image depthImage(const std::vector<float> &depth, int width, int height, std::string &notes);

// Stencil counts (bottom row first) as a heat map; `notes` gets the largest and the mean count.
Image overdrawImage(const std::vector<std::uint8_t> &counts, int width, int height, std::string &notes);

// The colour of a fragment count in the heat map (docs/cli.md shows the scale).
std::array<std::uint8_t, 3> overdrawColor(int count);

// Averages factor x factor blocks (rounding to nearest): a box filter. Factor 1 hands the image
// over as it is, without a copy.
Image boxDownsample(Image image, int factor);

} // namespace glass::scene
