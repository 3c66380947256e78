#include "core/matrix.h"

#include <cmath>
#include <utility>

namespace glass::gl {

Matrix4 Matrix4::identity() {
  return Matrix4{{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  // P(r, c) = sum_k A(r, k) B(k, c), summed left to right in float, as Mesa's matmul4 does, so
  // that matrices match Mesa's to the last bit where the inputs do.
  Matrix4 p;
  for (int r = 0; r < 4; ++r) {
    const float a0 = a.at(r, 0), a1 = a.at(r, 1), a2 = a.at(r, 2), a3 = a.at(r, 3);
    for (int c = 0; c < 4; ++c) {
      p.at(r, c) = a0 * b.at(0, c) + a1 * b.at(1, c) + a2 * b.at(2, c) + a3 * b.at(3, c);
    }
  }
  return p;
}

void transformVector4(const Matrix4& matrix, const float in[4], float out[4]) {
  const float* m = matrix.m;
  for (int r = 0; r < 4; ++r) {
    out[r] = m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2] + m[12 + r] * in[3];
  }
}

bool invert(const Matrix4& matrix, Matrix4& inverse) {
  // Gauss-Jordan elimination with partial pivoting on [M | I], in double.
  double a[4][8];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      a[r][c] = matrix.at(r, c);
      a[r][c + 4] = (r == c) ? 1.0 : 0.0;
    }
  }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r) {
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    }
    if (a[pivot][col] == 0.0) {
      inverse = Matrix4::identity();
      return false;
    }
    if (pivot != col) {
      for (int c = 0; c < 8; ++c) std::swap(a[pivot][c], a[col][c]);
    }
    const double scale = 1.0 / a[col][col];
    for (int c = 0; c < 8; ++c) a[col][c] *= scale;
    for (int r = 0; r < 4; ++r) {
      if (r == col || a[r][col] == 0.0) continue;
      const double factor = a[r][col];
      for (int c = 0; c < 8; ++c) a[r][c] -= factor * a[col][c];
    }
  }
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) inverse.at(r, c) = static_cast<float>(a[r][c + 4]);
  }
  return true;
}

}  // namespace glass::gl
