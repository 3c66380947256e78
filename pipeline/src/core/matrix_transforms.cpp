#include "core/matrix_transforms.h"

#include <cmath>
#include <numbers>

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
  // Sine and cosine in double, rounded to float: the float matrix then holds the correctly
  // rounded values for angles such as 90 degrees.
  const double radians = static_cast<double>(angleDegrees) * (std::numbers::pi / 180.0);
  const float s = static_cast<float>(std::sin(radians));
  const float c = static_cast<float>(std::cos(radians));
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

  const float length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0.0f)) return false;
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

Matrix4 orthoMatrix(double l, double r, double b, double t, double n, double f) {
  Matrix4 o = Matrix4::identity();
  o.at(0, 0) = static_cast<float>(2.0 / (r - l));
  o.at(1, 1) = static_cast<float>(2.0 / (t - b));
  o.at(2, 2) = static_cast<float>(-2.0 / (f - n));
  o.at(0, 3) = static_cast<float>(-(r + l) / (r - l));
  o.at(1, 3) = static_cast<float>(-(t + b) / (t - b));
  o.at(2, 3) = static_cast<float>(-(f + n) / (f - n));
  return o;
}

Matrix4 frustumMatrix(double l, double r, double b, double t, double n, double f) {
  Matrix4 p{};
  p.at(0, 0) = static_cast<float>(2.0 * n / (r - l));
  p.at(0, 2) = static_cast<float>((r + l) / (r - l));
  p.at(1, 1) = static_cast<float>(2.0 * n / (t - b));
  p.at(1, 2) = static_cast<float>((t + b) / (t - b));
  p.at(2, 2) = static_cast<float>(-(f + n) / (f - n));
  p.at(2, 3) = static_cast<float>(-2.0 * f * n / (f - n));
  p.at(3, 2) = -1.0f;
  return p;
}

}  // namespace glass::gl
