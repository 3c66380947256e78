// A block of RGBA groups on its way through the pixel transfer operations: 4 floats per group,
// row 0 first. Convolution in GL_REDUCE mode makes it smaller (spec 3.6.5).
#pragma once

#include <cstddef>
#include <vector>

namespace glass::gl {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<float> rgba;

  int count() const { return width * height; }
  float* at(int column, int row) {
    return rgba.data() + (static_cast<size_t>(row) * static_cast<size_t>(width) + static_cast<size_t>(column)) * 4;
  }
  const float* at(int column, int row) const {
    return rgba.data() + (static_cast<size_t>(row) * static_cast<size_t>(width) + static_cast<size_t>(column)) * 4;
  }
};

}  // namespace glass::gl
