#include "pixels/color_matrix.h"

#include <cstddef>

namespace glass::gl {

bool colorMatrixIsIdentity(const Matrix4& m, const float scale[4], const float bias[4]) {
  for (int r = 0; r < 4; ++r) {
    if (scale[r] != 1.0f || bias[r] != 0.0f) return false;
    for (int c = 0; c < 4; ++c) {
      if (m.at(r, c) != (r == c ? 1.0f : 0.0f)) return false;
    }
  }
  return true;
}

void transformByColorMatrix(const Matrix4& m, const float scale[4], const float bias[4],
                            float* rgba, int count) {
  for (int i = 0; i < count; ++i) {
    float* c = rgba + static_cast<size_t>(i) * 4;
    const float in[4] = {c[0], c[1], c[2], c[3]};
    for (int r = 0; r < 4; ++r) {
      float sum = m.at(r, 0) * in[0];
      sum += m.at(r, 1) * in[1];
      sum += m.at(r, 2) * in[2];
      sum += m.at(r, 3) * in[3];
      c[r] = sum * scale[r] + bias[r];
    }
  }
}

}  // namespace glass::gl
