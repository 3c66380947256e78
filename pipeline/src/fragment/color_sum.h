// Colour sum (spec 3.9): the secondary colour (the separate specular term) is added to the
// textured primary colour's R, G and B, and the sum clamped to [0, 1]. Alpha is the primary's.
// Fog (3.10) then works on the clamped sum. Mesa's llvmpipe fogs the unclamped sum and clamps
// only the final colour, so the two differ where a sum exceeds 1 (tests/image/programs/fog_color_sum.c).
#pragma once

#include <algorithm>

namespace glass::gl {

inline void applyColorSum(const float secondary[4], float color[4]) {
  for (int i = 0; i < 3; ++i) color[i] = std::min(color[i] + secondary[i], 1.0f);
}

}  // namespace glass::gl
