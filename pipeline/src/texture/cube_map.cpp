#include "texture/cube_map.h"

#include <cmath>

namespace glass::gl {

void cubeFaceProjection(int face, float rx, float ry, float rz, float* s, float* t) {
  float sc = 0.0f, tc = 0.0f, ma = 0.0f;
  switch (face) {
    case 0: sc = -rz; tc = -ry; ma = rx; break;
    case 1: sc = rz; tc = -ry; ma = rx; break;
    case 2: sc = rx; tc = rz; ma = ry; break;
    case 3: sc = rx; tc = -rz; ma = ry; break;
    case 4: sc = rx; tc = -ry; ma = rz; break;
    default: sc = -rx; tc = -ry; ma = rz; break;
  }
  const float m = std::fabs(ma);
  if (m == 0.0f) {
    *s = 0.5f;
    *t = 0.5f;
    return;
  }
  *s = 0.5f * (sc / m + 1.0f);
  *t = 0.5f * (tc / m + 1.0f);
}

CubeFaceCoordinates cubeFaceCoordinates(float rx, float ry, float rz) {
  const float ax = std::fabs(rx), ay = std::fabs(ry), az = std::fabs(rz);
  CubeFaceCoordinates c;
  if (ax >= ay && ax >= az) {
    c.face = rx >= 0.0f ? 0 : 1;
  } else if (ay >= az) {
    c.face = ry >= 0.0f ? 2 : 3;
  } else {
    c.face = rz >= 0.0f ? 4 : 5;
  }
  cubeFaceProjection(c.face, rx, ry, rz, &c.s, &c.t);
  return c;
}

}  // namespace glass::gl
