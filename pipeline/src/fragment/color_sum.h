// Colour sum (spec 3.9): the secondary colour (the separate specular term) is added to the
// textured primary colour's R, G and B, and the sum clamped to [0, 1]. Alpha is the primary's.
#pragma once

#include <algorithm>

namespace glass::gl {

inline void applyColorSum(const float secondary[4], float color[4]) {
  for (int i = 0; i < 3; ++i) color[i] = std::min(color[i] + secondary[i], 1.0f);
}

}  // namespace glass::gl
