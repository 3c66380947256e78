// Screen-space derivatives of a perspective-correct attribute (for texture level of detail, spec
// 3.8.8): with P = a/w and Q = 1/w affine in window x, y, a = P / Q and by the quotient rule
//   da/dx = (P_x Q - P Q_x) / Q^2,  da/dy = (P_y Q - P Q_y) / Q^2.
#include "glass/raster/fragment.h"

namespace glass::raster {

void AttributePlanes::derivatives(int varying, int px, int py, double& ddx, double& ddy) const {
  const double x = px + 0.5, y = py + 0.5;  // the pixel centre
  const double p = a0[varying] + dx[varying] * x + dy[varying] * y;
  const double q = invW0 + invWdx * x + invWdy * y;
  const double q2 = q * q;
  ddx = (dx[varying] * q - p * invWdx) / q2;
  ddy = (dy[varying] * q - p * invWdy) / q2;
}

}  // namespace glass::raster
