// Tensor-product Bezier patches of any bi-degree, integral or rational.
//
//   S(u, v) = sum_i sum_j B_i^m(u) B_j^n(v) w_ij p_ij / sum_i sum_j B_i^m(u) B_j^n(v) w_ij
//
// As for curves, the patch is stored by its homogeneous control points H_ij = (w_ij p_ij, w_ij);
// the index i runs along u (0..degreeU), j along v (0..degreeV), and H_ij sits at
// [i * (degreeV + 1) + j]. That is the layout of glMap2 with u as the outer index.
#pragma once

#include "glass/geometry/axis_aligned_box.h"
#include "glass/geometry/bezier_curve.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <utility>
#include <vector>

namespace glass::geometry {

// The four boundary curves of a patch.
enum class PatchSide {
  UMin,  // u = 0, the curve in v through H_0j
  UMax,  // u = 1, the curve in v through H_mj
  VMin,  // v = 0, the curve in u through H_i0
  VMax,  // v = 1, the curve in u through H_in
};

// A point of a patch with its first partial derivatives and unit normal.
struct SurfaceFrame {
  glm::dvec3 point{0.0};
  glm::dvec3 du{0.0};      // dS/du of the projected point
  glm::dvec3 dv{0.0};      // dS/dv of the projected point
  glm::dvec3 normal{0.0};  // unit, in the direction of du x dv (see BezierSurface::normal)
};

class BezierSurface {
 public:
  BezierSurface() = default;
  // An integral patch; points.size() must be (degreeU + 1) * (degreeV + 1).
  BezierSurface(int degreeU, int degreeV, std::span<const glm::dvec3> points);
  // A rational patch, point (i, j) with weight weights[i * (degreeV + 1) + j].
  BezierSurface(int degreeU, int degreeV, std::span<const glm::dvec3> points, std::span<const double> weights);
  static BezierSurface fromHomogeneous(int degreeU, int degreeV, std::vector<glm::dvec4> homogeneous);

  int degreeU() const { return degreeU_; }
  int degreeV() const { return degreeV_; }
  bool empty() const { return net_.empty(); }
  bool isRational() const;
  bool hasPositiveWeights() const;

  const glm::dvec4& homogeneousControlPoint(int i, int j) const { return net_[index(i, j)]; }
  // H.xyz / H.w, or the direction H.xyz for weight 0.
  glm::dvec3 controlPoint(int i, int j) const;
  double weight(int i, int j) const { return net_[index(i, j)].w; }
  std::span<const glm::dvec4> homogeneousControlPoints() const { return net_; }

  glm::dvec4 evaluateHomogeneous(double u, double v) const;
  glm::dvec3 evaluate(double u, double v) const;
  // d^(orderU + orderV) S / du^orderU dv^orderV of the projected point (the quotient rule for
  // rational patches, by Leibniz's rule on H = w S).
  glm::dvec3 derivative(double u, double v, int orderU, int orderV) const;
  // The unit normal: du x dv normalised, the normal GL_AUTO_NORMAL defines (OpenGL 1.x, section
  // 5.1). Where that cross product vanishes because a boundary row of the net collapses to one
  // point (sphere poles, cone apex, the top of the teapot lid), the normal is its limit from the
  // inside of the patch: at u = 0 with dv = 0, dv ~ u d2S/dudv, so the normal is along
  // du x d2S/dudv (and the reverse at u = 1; likewise d2S/dudv x dv at v = 0 or 1). Where no limit
  // is found, the normal of a point slightly inside the patch. The zero vector only when the patch
  // is degenerate everywhere near (u, v).
  glm::dvec3 normal(double u, double v) const;
  SurfaceFrame frame(double u, double v) const;

  std::pair<BezierSurface, BezierSurface> subdivideU(double u) const;
  std::pair<BezierSurface, BezierSurface> subdivideV(double v) const;
  // The sub-patch on [u0, u1] x [v0, v1], parametrised by [0, 1]^2.
  BezierSurface piece(double u0, double u1, double v0, double v1) const;
  BezierSurface elevatedU() const;
  BezierSurface elevatedV() const;
  // The curve v -> S(u, v) at fixed u, and u -> S(u, v) at fixed v.
  BezierCurve curveAtU(double u) const;
  BezierCurve curveAtV(double v) const;
  // A boundary curve, oriented by increasing u or v.
  BezierCurve boundary(PatchSide side) const;
  // The box around the control points; it holds the patch when all weights are positive (convex
  // hull property), and is unbounded otherwise.
  AxisAlignedBox bounds() const;

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i * (degreeV_ + 1) + j); }
  // H^(a, b) for a <= orderU, b <= orderV at [a * (orderV + 1) + b].
  std::vector<glm::dvec4> homogeneousDerivatives(double u, double v, int orderU, int orderV) const;
  // The normal without the fallback to a point inside the patch; false when it is undefined.
  bool normalAt(double u, double v, glm::dvec3& normal) const;
  // The diagonal of the box around the finite control points: the length scale of the patch.
  double netSize() const;

  int degreeU_ = -1;
  int degreeV_ = -1;
  std::vector<glm::dvec4> net_;
};

}  // namespace glass::geometry
