#include "glass/geometry/bezier_surface.h"

#include "glass/geometry/de_casteljau.h"
#include "rational_derivatives.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace glass::geometry {
namespace {

using Row = std::vector<glm::dvec4>;

// The piece of one row of control points on [t0, t1], parametrised by [0, 1].
Row segmentOfRow(const Row& row, double t0, double t1) {
  Row left = t1 < 1.0 ? deCasteljauSplit(std::span<const glm::dvec4>(row), t1).first : row;
  if (t0 <= 0.0) return left;
  const double local = t1 > 0.0 ? t0 / t1 : 0.0;
  return deCasteljauSplit(std::span<const glm::dvec4>(left), local).second;
}

}  // namespace

BezierSurface::BezierSurface(int degreeU, int degreeV, std::span<const glm::dvec3> points)
    : degreeU_(degreeU), degreeV_(degreeV) {
  assert(points.size() == static_cast<std::size_t>((degreeU + 1) * (degreeV + 1)));
  net_.reserve(points.size());
  for (const glm::dvec3& p : points) net_.emplace_back(p, 1.0);
}

BezierSurface::BezierSurface(int degreeU, int degreeV, std::span<const glm::dvec3> points,
                             std::span<const double> weights)
    : degreeU_(degreeU), degreeV_(degreeV) {
  assert(points.size() == static_cast<std::size_t>((degreeU + 1) * (degreeV + 1)));
  assert(weights.size() == points.size());
  net_.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) net_.emplace_back(weights[k] * points[k], weights[k]);
}

BezierSurface BezierSurface::fromHomogeneous(int degreeU, int degreeV, std::vector<glm::dvec4> homogeneous) {
  assert(homogeneous.size() == static_cast<std::size_t>((degreeU + 1) * (degreeV + 1)));
  BezierSurface surface;
  surface.degreeU_ = degreeU;
  surface.degreeV_ = degreeV;
  surface.net_ = std::move(homogeneous);
  return surface;
}

bool BezierSurface::isRational() const {
  return std::any_of(net_.begin(), net_.end(), [](const glm::dvec4& h) { return h.w != 1.0; });
}

bool BezierSurface::hasPositiveWeights() const {
  return std::all_of(net_.begin(), net_.end(), [](const glm::dvec4& h) { return h.w > 0.0; });
}

glm::dvec3 BezierSurface::controlPoint(int i, int j) const {
  const glm::dvec4& h = net_[index(i, j)];
  return h.w == 0.0 ? glm::dvec3(h) : glm::dvec3(h) / h.w;
}

// Rows first (each row i is a curve in v), then the column of row values along u. At u = 0 this
// returns the row-0 curve's value at v bit for bit, and at v = 0 the column-0 curve's value at u,
// so a patch and the boundary curve it shares with a neighbour agree exactly.
glm::dvec4 BezierSurface::evaluateHomogeneous(double u, double v) const {
  if (net_.empty()) return glm::dvec4(0.0);
  const std::size_t columns = static_cast<std::size_t>(degreeV_ + 1);
  WorkingRow<glm::dvec4> column(static_cast<std::size_t>(degreeU_ + 1));
  for (int i = 0; i <= degreeU_; ++i)
    column[i] = deCasteljau(std::span<const glm::dvec4>(net_.data() + i * columns, columns), v);
  return deCasteljau(column.points(), u);
}

glm::dvec3 BezierSurface::evaluate(double u, double v) const {
  const glm::dvec4 h = evaluateHomogeneous(u, v);
  return glm::dvec3(h) / h.w;
}

std::vector<glm::dvec4> BezierSurface::homogeneousDerivatives(double u, double v, int orderU, int orderV) const {
  const std::size_t columns = static_cast<std::size_t>(degreeV_ + 1);
  const int tableColumns = orderV + 1;
  std::vector<glm::dvec4> table(static_cast<std::size_t>((orderU + 1) * tableColumns));
  WorkingRow<glm::dvec4> column(static_cast<std::size_t>(degreeU_ + 1));
  for (int b = 0; b <= orderV; ++b) {
    for (int i = 0; i <= degreeU_; ++i)
      column[i] = deCasteljauDerivative(std::span<const glm::dvec4>(net_.data() + i * columns, columns), v, b);
    for (int a = 0; a <= orderU; ++a)
      table[a * tableColumns + b] = deCasteljauDerivative(column.points(), u, a);
  }
  return table;
}

glm::dvec3 BezierSurface::derivative(double u, double v, int orderU, int orderV) const {
  if (net_.empty()) return glm::dvec3(0.0);
  const std::vector<glm::dvec3> table =
      detail::projectMixedDerivatives(homogeneousDerivatives(u, v, orderU, orderV), orderU, orderV);
  return table.back();
}

bool BezierSurface::normalAt(double u, double v, glm::dvec3& normal) const {
  const std::vector<glm::dvec3> table = detail::projectMixedDerivatives(homogeneousDerivatives(u, v, 1, 1), 1, 1);
  const glm::dvec3& su = table[2];   // (a, b) = (1, 0)
  const glm::dvec3& sv = table[1];   // (0, 1)
  const glm::dvec3& suv = table[3];  // (1, 1)

  // "Vanishes" is measured against the size of the net: a collapsed row gives a derivative of
  // exactly zero for integral patches and of rounding noise (~1e-16 of the size) for rational ones.
  const double scale = netSize();
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  const double tiny = 1e-9 * scale;
  const double lengthU = glm::length(su);
  const double lengthV = glm::length(sv);

  glm::dvec3 n = glm::cross(su, sv);
  if (lengthU > tiny && lengthV > tiny && glm::length(n) > 1e-10 * lengthU * lengthV) {
    normal = glm::normalize(n);
    return true;
  }
  // A collapsed row: the limit of du x dv from the inside of the patch (see the header).
  const double lengthUV = glm::length(suv);
  if (lengthU > tiny && lengthV <= tiny && lengthUV > tiny) {
    n = glm::cross(su, suv) * (u <= 0.5 ? 1.0 : -1.0);
    if (glm::length(n) > 1e-10 * lengthU * lengthUV) {
      normal = glm::normalize(n);
      return true;
    }
  } else if (lengthV > tiny && lengthU <= tiny && lengthUV > tiny) {
    n = glm::cross(suv, sv) * (v <= 0.5 ? 1.0 : -1.0);
    if (glm::length(n) > 1e-10 * lengthV * lengthUV) {
      normal = glm::normalize(n);
      return true;
    }
  }
  return false;
}

glm::dvec3 BezierSurface::normal(double u, double v) const {
  if (net_.empty()) return glm::dvec3(0.0);
  glm::dvec3 n(0.0);
  if (normalAt(u, v, n)) return n;
  // Step towards the middle of the patch: the normal of a nearby regular point.
  for (double step : {1e-7, 1e-5, 1e-3}) {
    if (normalAt(u + (0.5 - u) * step, v + (0.5 - v) * step, n)) return n;
  }
  return glm::dvec3(0.0);
}

SurfaceFrame BezierSurface::frame(double u, double v) const {
  SurfaceFrame result;
  if (net_.empty()) return result;
  const std::vector<glm::dvec3> table = detail::projectMixedDerivatives(homogeneousDerivatives(u, v, 1, 1), 1, 1);
  result.point = table[0];
  result.dv = table[1];
  result.du = table[2];
  result.normal = normal(u, v);
  return result;
}

std::pair<BezierSurface, BezierSurface> BezierSurface::subdivideU(double u) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  std::vector<glm::dvec4> low(net_.size()), high(net_.size());
  Row column(static_cast<std::size_t>(rows));
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < rows; ++i) column[i] = net_[index(i, j)];
    auto [left, right] = deCasteljauSplit(std::span<const glm::dvec4>(column), u);
    for (int i = 0; i < rows; ++i) {
      low[index(i, j)] = left[i];
      high[index(i, j)] = right[i];
    }
  }
  return {fromHomogeneous(degreeU_, degreeV_, std::move(low)), fromHomogeneous(degreeU_, degreeV_, std::move(high))};
}

std::pair<BezierSurface, BezierSurface> BezierSurface::subdivideV(double v) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  std::vector<glm::dvec4> low(net_.size()), high(net_.size());
  for (int i = 0; i < rows; ++i) {
    auto [left, right] = deCasteljauSplit(std::span<const glm::dvec4>(net_.data() + index(i, 0), columns), v);
    std::copy(left.begin(), left.end(), low.begin() + static_cast<std::ptrdiff_t>(index(i, 0)));
    std::copy(right.begin(), right.end(), high.begin() + static_cast<std::ptrdiff_t>(index(i, 0)));
  }
  return {fromHomogeneous(degreeU_, degreeV_, std::move(low)), fromHomogeneous(degreeU_, degreeV_, std::move(high))};
}

BezierSurface BezierSurface::piece(double u0, double u1, double v0, double v1) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  std::vector<glm::dvec4> result(net_.size());
  for (int i = 0; i < rows; ++i) {
    const Row row(net_.begin() + static_cast<std::ptrdiff_t>(index(i, 0)),
                  net_.begin() + static_cast<std::ptrdiff_t>(index(i, 0)) + columns);
    const Row cut = segmentOfRow(row, v0, v1);
    std::copy(cut.begin(), cut.end(), result.begin() + static_cast<std::ptrdiff_t>(index(i, 0)));
  }
  Row column(static_cast<std::size_t>(rows));
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < rows; ++i) column[i] = result[index(i, j)];
    const Row cut = segmentOfRow(column, u0, u1);
    for (int i = 0; i < rows; ++i) result[index(i, j)] = cut[i];
  }
  return fromHomogeneous(degreeU_, degreeV_, std::move(result));
}

BezierSurface BezierSurface::elevatedU() const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  std::vector<glm::dvec4> result(static_cast<std::size_t>((rows + 1) * columns));
  Row column(static_cast<std::size_t>(rows));
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < rows; ++i) column[i] = net_[index(i, j)];
    const Row raised = elevateDegree(std::span<const glm::dvec4>(column));
    for (int i = 0; i <= rows; ++i) result[static_cast<std::size_t>(i * columns + j)] = raised[i];
  }
  return fromHomogeneous(degreeU_ + 1, degreeV_, std::move(result));
}

BezierSurface BezierSurface::elevatedV() const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  std::vector<glm::dvec4> result;
  result.reserve(static_cast<std::size_t>(rows * (columns + 1)));
  for (int i = 0; i < rows; ++i) {
    const Row raised = elevateDegree(std::span<const glm::dvec4>(net_.data() + index(i, 0), columns));
    result.insert(result.end(), raised.begin(), raised.end());
  }
  return fromHomogeneous(degreeU_, degreeV_ + 1, std::move(result));
}

BezierCurve BezierSurface::curveAtU(double u) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  Row curve(static_cast<std::size_t>(columns)), column(static_cast<std::size_t>(rows));
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < rows; ++i) column[i] = net_[index(i, j)];
    curve[j] = deCasteljau(std::span<const glm::dvec4>(column), u);
  }
  return BezierCurve::fromHomogeneous(std::move(curve));
}

BezierCurve BezierSurface::curveAtV(double v) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  Row curve(static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i)
    curve[i] = deCasteljau(std::span<const glm::dvec4>(net_.data() + index(i, 0), columns), v);
  return BezierCurve::fromHomogeneous(std::move(curve));
}

BezierCurve BezierSurface::boundary(PatchSide side) const {
  const int rows = degreeU_ + 1, columns = degreeV_ + 1;
  Row curve;
  switch (side) {
    case PatchSide::UMin:
    case PatchSide::UMax: {
      const int i = side == PatchSide::UMin ? 0 : degreeU_;
      curve.assign(net_.begin() + static_cast<std::ptrdiff_t>(index(i, 0)),
                   net_.begin() + static_cast<std::ptrdiff_t>(index(i, 0)) + columns);
      break;
    }
    case PatchSide::VMin:
    case PatchSide::VMax: {
      const int j = side == PatchSide::VMin ? 0 : degreeV_;
      for (int i = 0; i < rows; ++i) curve.push_back(net_[index(i, j)]);
      break;
    }
  }
  return BezierCurve::fromHomogeneous(std::move(curve));
}

double BezierSurface::netSize() const {
  AxisAlignedBox box;
  for (const glm::dvec4& h : net_)
    if (h.w != 0.0) box.include(glm::dvec3(h) / h.w);
  return glm::length(box.size());
}

AxisAlignedBox BezierSurface::bounds() const {
  AxisAlignedBox box;
  if (!hasPositiveWeights()) {
    const double inf = std::numeric_limits<double>::infinity();
    box.min = glm::dvec3(-inf);
    box.max = glm::dvec3(inf);
    return box;
  }
  for (int i = 0; i <= degreeU_; ++i)
    for (int j = 0; j <= degreeV_; ++j) box.include(controlPoint(i, j));
  return box;
}

}  // namespace glass::geometry
