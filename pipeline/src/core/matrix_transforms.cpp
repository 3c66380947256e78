#include "core/matrix_transforms.h"

#include <cmath>
#include <numbers>
#include "glass/geometry/portable_math.h"

namespace glass::gl {

Matrix4 translationMatrix(float x, float y, float z) {
  Matrix4 t = Matrix4::identity();
  t.at(0, 3) = x;
  t.at(1, 3) = y;
  t.at(2, 3) = z;
  return t;
}

Matrix4 scaleMatrix(float x, float y, float z) {
  Matrix4 s = Matrix4::identity();
  s.at(0, 0) = x;
  s.at(1, 1) = y;
  s.at(2, 2) = z;
  return s;
}

bool rotationMatrix(float angleDegrees, float x, float y, float z, Matrix4& r) {
  // The rounding is not the specification's business; glass takes Mesa's (m_matrix.c), because
  // it decides where a vertex that lies exactly on a clip plane or a polygon edge falls: the
  // angle in radians is computed in double, rounded to float, and its sine and cosine taken in
  // float (glass::portable, the correctly rounded float, which is glibc's cosf at the angles the
  // tests compare). At 90 degrees the cosine is then cos(float(pi / 2)) = -4.37e-8, not 0, and a
  // glutWireSphere turned by glRotatef(90, 1, 0, 0) has its equator just below y = 0, so the
  // clip plane y >= 0 removes it, as in Mesa.
  const float radians =
      static_cast<float>(static_cast<double>(angleDegrees) * std::numbers::pi / 180.0);
  const float s = portable::sin(radians);
  const float c = portable::cos(radians);
  r = Matrix4::identity();

  // Rotations about a coordinate axis: the general formula below gives the same values
  // mathematically, but (1 - c) * 1 + c is not always exactly 1 in float. Writing the entries
  // directly keeps the unit entry exact, as Mesa does.
  const int axis = (y == 0.0f && z == 0.0f && x != 0.0f)   ? 0
                   : (x == 0.0f && z == 0.0f && y != 0.0f) ? 1
                   : (x == 0.0f && y == 0.0f && z != 0.0f) ? 2
                                                            : -1;
  if (axis >= 0) {
    const float direction = (axis == 0 ? x : axis == 1 ? y : z) < 0.0f ? -1.0f : 1.0f;
    const float sa = direction * s;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane rotated: i towards j
    r.at(i, i) = c;
    r.at(j, j) = c;
    r.at(j, i) = sa;
    r.at(i, j) = -sa;
    return true;
  }

  // Mesa leaves the matrix alone for an axis shorter than 1e-4.
  const float length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 1.0e-4f)) return false;
  x /= length;
  y /= length;
  z /= length;
  // R = u u^T (1 - c) + c I + s [u]x   (spec 2.11.2, with u the normalized axis)
  const float oneMinusC = 1.0f - c;
  r.at(0, 0) = oneMinusC * (x * x) + c;
  r.at(0, 1) = oneMinusC * (x * y) - z * s;
  r.at(0, 2) = oneMinusC * (x * z) + y * s;
  r.at(1, 0) = oneMinusC * (x * y) + z * s;
  r.at(1, 1) = oneMinusC * (y * y) + c;
  r.at(1, 2) = oneMinusC * (y * z) - x * s;
  r.at(2, 0) = oneMinusC * (x * z) - y * s;
  r.at(2, 1) = oneMinusC * (y * z) + x * s;
  r.at(2, 2) = oneMinusC * (z * z) + c;
  return true;
}

Matrix4 orthoMatrix(double left, double right, double bottom, double top, double zNear,
                    double zFar) {
  // In float from the arguments rounded to float, term by term as Mesa (_math_float_ortho).
  const float l = static_cast<float>(left), r = static_cast<float>(right);
  const float b = static_cast<float>(bottom), t = static_cast<float>(top);
  const float n = static_cast<float>(zNear), f = static_cast<float>(zFar);
  Matrix4 o = Matrix4::identity();
  o.at(0, 0) = 2.0f / (r - l);
  o.at(1, 1) = 2.0f / (t - b);
  o.at(2, 2) = -2.0f / (f - n);
  o.at(0, 3) = -(r + l) / (r - l);
  o.at(1, 3) = -(t + b) / (t - b);
  o.at(2, 3) = -(f + n) / (f - n);
  return o;
}

Matrix4 frustumMatrix(double left, double right, double bottom, double top, double zNear,
                      double zFar) {
  // In float from the arguments rounded to float, as Mesa (_math_matrix_frustum).
  const float l = static_cast<float>(left), r = static_cast<float>(right);
  const float b = static_cast<float>(bottom), t = static_cast<float>(top);
  const float n = static_cast<float>(zNear), f = static_cast<float>(zFar);
  Matrix4 p{};
  p.at(0, 0) = (2.0f * n) / (r - l);
  p.at(0, 2) = (r + l) / (r - l);
  p.at(1, 1) = (2.0f * n) / (t - b);
  p.at(1, 2) = (t + b) / (t - b);
  p.at(2, 2) = -(f + n) / (f - n);
  p.at(2, 3) = -(2.0f * f * n) / (f - n);
  p.at(3, 2) = -1.0f;
  return p;
}

}  // namespace glass::gl
