// Quaternions q = w + x i + y j + z k, as in section 2.3 of the study guide: the algebra
// (sum, Hamilton product, conjugate, norm, inverse), reflections n v n and rotations q v q^-1 of
// vectors (vectors are the imaginary quaternions), the rotation matrix of a unit quaternion
// (the guide's equation 8) and back, and spherical linear interpolation.
//
// Axis-angle descriptions of rotations (equations 7 and 9) are in rotation.h.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace glass::geometry {

struct Quaternion {
  double w = 1.0;  // real (scalar) part
  double x = 0.0;  // coefficients of i, j, k: the imaginary (vector) part
  double y = 0.0;
  double z = 0.0;

  constexpr Quaternion() = default;
  constexpr Quaternion(double w_, double x_, double y_, double z_) : w(w_), x(x_), y(y_), z(z_) {}
  // q = r + v, the guide's "scalar part plus vector part" notation.
  constexpr Quaternion(double real, const glm::dvec3& imaginary)
      : w(real), x(imaginary.x), y(imaginary.y), z(imaginary.z) {}

  // A vector of R^3 as the imaginary quaternion v1 i + v2 j + v3 k (section 2.3.2).
  static constexpr Quaternion pure(const glm::dvec3& v) { return {0.0, v}; }

  constexpr double real() const { return w; }
  constexpr glm::dvec3 imaginary() const { return {x, y, z}; }

  bool operator==(const Quaternion&) const = default;
};

constexpr Quaternion operator+(const Quaternion& a, const Quaternion& b) {
  return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr Quaternion operator-(const Quaternion& a, const Quaternion& b) {
  return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr Quaternion operator-(const Quaternion& q) { return {-q.w, -q.x, -q.y, -q.z}; }
constexpr Quaternion operator*(double s, const Quaternion& q) {
  return {s * q.w, s * q.x, s * q.y, s * q.z};
}

// The Hamilton product, from i^2 = j^2 = k^2 = -1, ij = k, jk = i, ki = j (section 2.3.1):
//   q q' = (r r' - v.v') + (r v' + r' v + v x v').
// Not commutative: q1 q2 != q2 q1 in general.
Quaternion operator*(const Quaternion& a, const Quaternion& b);

// Conjugate r - v, so that q conj(q) = |q|^2.
constexpr Quaternion conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }
constexpr double normSquared(const Quaternion& q) {
  return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
}
double norm(const Quaternion& q);
// q^-1 = conj(q) / |q|^2. The zero quaternion has no inverse: its result is all NaN.
Quaternion inverse(const Quaternion& q);
// q / |q|; the zero quaternion stays zero.
Quaternion normalized(const Quaternion& q);
// The 4D dot product w w' + x x' + y y' + z z' (the cosine of the angle between unit quaternions).
constexpr double dot(const Quaternion& a, const Quaternion& b) {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

// The rotation of v by q as the imaginary part of q v q^-1 (section 2.3.3). q need not be a unit
// quaternion: q and any non-zero multiple of it give the same rotation.
glm::dvec3 rotate(const Quaternion& q, const glm::dvec3& v);

// The reflection of v in the plane through the origin perpendicular to the unit vector n, computed
// as the quaternion product n v n = v - 2 (n.v) n (section 2.3.2). n is normalised first; a zero
// n gives NaN.
glm::dvec3 reflect(const glm::dvec3& n, const glm::dvec3& v);

// The rotation matrix of q (equation 8), for q normalised first:
//   [ w^2+x^2-y^2-z^2   2(xy - wz)        2(xz + wy)      ]
//   [ 2(xy + wz)        w^2-x^2+y^2-z^2   2(yz - wx)      ]
//   [ 2(xz - wy)        2(yz + wx)        w^2-x^2-y^2+z^2 ]
// (the factor 2 of the off-diagonal terms comes from 2 q q^T + 2 q0 [q]x, the line above
// equation 8). glm matrices are column-major: entry (row r, column c) is m[c][r].
glm::dmat3 rotationMatrix(const Quaternion& q);

// The unit quaternion of a rotation matrix, the inverse of equation 8. Of the two answers q and -q
// the one with w >= 0 is returned. Uses the largest of w^2, x^2, y^2, z^2 (read off the diagonal
// of equation 8) as the pivot, so the result is accurate for every rotation, angle pi included.
// The matrix is assumed to be a rotation (orthogonal, determinant +1).
Quaternion quaternionFromRotationMatrix(const glm::dmat3& m);

// Spherical linear interpolation between the rotations a (t = 0) and b (t = 1) along the shorter
// arc: slerp = a (a^-1 b)^t for unit quaternions, computed as
//   (sin((1-t) phi) a + sin(t phi) b) / sin(phi),  cos(phi) = a.b,
// with b replaced by -b when a.b < 0 (the same rotation, the shorter way round). Inputs are
// normalised first; when the two are almost equal the formula becomes 0/0 and normalised linear
// interpolation, its limit, is used instead.
Quaternion slerp(const Quaternion& a, const Quaternion& b, double t);

}  // namespace glass::geometry
