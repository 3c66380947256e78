// The normals view's colour of one fragment.
#include <cmath>

#include "teaching/teaching_hooks.h"

namespace glass::gl {

// Each component of the unit normal, -1 to 1, is mapped to 0 to 255, the usual normal-map
// encoding: a face turned to the eye (0, 0, 1) is (128, 128, 255). The normal is the one the
// lighting equation would use (spec 2.11.3: n_e = n_o M^-1), normalized here whatever
// GL_NORMALIZE says, so that the colour shows the direction alone.
void paintNormal(const float eyeNormal[3], std::uint8_t* rgba) {
  const double x = eyeNormal[0], y = eyeNormal[1], z = eyeNormal[2];
  const double length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0.0) || !std::isfinite(length)) {
    rgba[0] = rgba[1] = rgba[2] = 0;
  } else {
    const double n[3] = {x / length, y / length, z / length};
    for (int c = 0; c < 3; ++c) rgba[c] = static_cast<std::uint8_t>(std::lround(127.5 * (n[c] + 1.0)));
  }
  rgba[3] = 255;
}

}  // namespace glass::gl
