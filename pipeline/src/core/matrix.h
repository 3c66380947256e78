// 4x4 matrices as GL stores them: column-major floats, element (row r, column c) at m[c * 4 + r]
// (OpenGL 1.5 spec, section 2.11.2). Products are computed in float with a fixed order of
// operations, so results are the same on every machine (no fused multiply-add: the build sets
// -ffp-contract=off).
#pragma once

namespace glass::gl {

struct Matrix4 {
  float m[16];

  static Matrix4 identity();
  float at(int row, int column) const { return m[column * 4 + row]; }
  float& at(int row, int column) { return m[column * 4 + row]; }
  bool operator==(const Matrix4&) const = default;
};

// a * b: the matrix that applies b first, then a (glMultMatrix(b) on a stack whose top is a).
Matrix4 multiply(const Matrix4& a, const Matrix4& b);

// out = M * in for a column vector in (in and out may not alias).
void transformVector4(const Matrix4& matrix, const float in[4], float out[4]);

// The inverse, computed in double precision and rounded to float. Returns false (and leaves
// inverse as the identity) when the matrix is singular.
bool invert(const Matrix4& matrix, Matrix4& inverse);

}  // namespace glass::gl
