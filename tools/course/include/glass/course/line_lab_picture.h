// The line lab's picture (homework 1): a square grid of big pixels, the squares an algorithm
// chooses filled, the true segment in red between the centres of its end squares. Several
// algorithms side by side, one panel each, left to right. Drawn with GL calls into the current
// context, as the homework asks for an OpenGL program.
#pragma once

#include <vector>

#include "glass/course/line_lab.h"

namespace glass::course {

struct LineLabPicture {
  int gridSize = 32;    // squares per side
  int cellPixels = 16;  // pixels per square, grid line included
  GridSegment segment{3, 5, 27, 14};
  std::vector<LineAlgorithm> algorithms{LineAlgorithm::Bresenham};
};

struct PictureSize {
  int width = 0, height = 0;
};

// The context size the picture needs.
PictureSize lineLabPictureSize(const LineLabPicture& picture);

// Clears and draws the whole picture; the context must have lineLabPictureSize's size.
void drawLineLabPicture(const LineLabPicture& picture);

}  // namespace glass::course
