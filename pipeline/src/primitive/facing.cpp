#include "primitive/facing.h"

namespace glass::gl {

bool isCounterClockwise(const raster::ClipVertex& a, const raster::ClipVertex& b,
                        const raster::ClipVertex& c) {
  // det | xa ya wa |
  //     | xb yb wb |
  //     | xc yc wc |   in double, so that the sign is right for all but near-degenerate cases.
  const double xa = a.clip[0], ya = a.clip[1], wa = a.clip[3];
  const double xb = b.clip[0], yb = b.clip[1], wb = b.clip[3];
  const double xc = c.clip[0], yc = c.clip[1], wc = c.clip[3];
  const double det = xa * (yb * wc - wb * yc) - ya * (xb * wc - wb * xc) + wa * (xb * yc - yb * xc);
  return det > 0.0;
}

}  // namespace glass::gl
