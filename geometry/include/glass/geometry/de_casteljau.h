// The algorithms on one row of Bezier control points that everything else is built from: de
// Casteljau evaluation and subdivision, the hodograph (derivative control points) and degree
// elevation. They are templates over the point type P, which needs only P + P and double * P, so
// the same code serves 3D points, homogeneous 4D points (rational curves: weights in w and the
// other coordinates premultiplied by it) and the colours, normals and texture coordinates of the
// GL evaluators.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace glass::geometry {

// (1 - t) a + t b, written so that t = 0 gives a and t = 1 gives b bit for bit (1 * a + 0 * b == a).
// Equal end points give that point for every t, so a boundary row collapsed to one point (a sphere
// pole, the top of the teapot lid) evaluates to exactly that point. Both facts keep the vertices of
// neighbouring tessellated patches identical along shared edges.
template <class P>
P interpolate(const P& a, const P& b, double t) {
  if (a == b) return a;
  return (1.0 - t) * a + t * b;
}

// A row of points to work on in place: on the stack up to 16 points (every GL evaluator, the
// teapot, the conics, the rounding's patches), on the heap beyond. Evaluating a surface point or a
// derivative then allocates nothing, which matters where a tessellation evaluates thousands.
template <class P>
class WorkingRow {
 public:
  explicit WorkingRow(std::size_t size) : size_(size) {
    if (size > kStackPoints) heap_.resize(size);
    data_ = size > kStackPoints ? heap_.data() : stack_.data();
  }
  explicit WorkingRow(std::span<const P> points) : WorkingRow(points.size()) {
    for (std::size_t i = 0; i < size_; ++i) data_[i] = points[i];
  }
  WorkingRow(const WorkingRow&) = delete;
  WorkingRow& operator=(const WorkingRow&) = delete;

  P& operator[](std::size_t i) { return data_[i]; }
  std::size_t size() const { return size_; }
  std::span<const P> points() const { return {data_, size_}; }

 private:
  static constexpr std::size_t kStackPoints = 16;
  std::array<P, kStackPoints> stack_;
  std::vector<P> heap_;
  P* data_;
  std::size_t size_;
};

namespace detail {
// The hodograph of the first n >= 2 points of `row`, in place: its n - 1 points
// (n - 1) (p(i+1) - p(i)) replace the first n - 1 (point i is read before it is overwritten,
// point i + 1 after).
template <class Row>
void hodographInPlace(Row& row, std::size_t n) {
  const double degree = static_cast<double>(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) row[i] = degree * (row[i + 1] + (-1.0) * row[i]);
}

// de Casteljau on the first n points of `level`, overwriting them.
template <class P>
P deCasteljauInPlace(WorkingRow<P>& level, std::size_t n, double t) {
  if (n == 0) return P{};
  for (; n > 1; --n)
    for (std::size_t i = 0; i + 1 < n; ++i) level[i] = interpolate(level[i], level[i + 1], t);
  return level[0];
}
}  // namespace detail

// de Casteljau's algorithm (study guide, section 2.4, equations (10) and (12)): repeated linear
// interpolation of neighbouring control points until one point is left. Numerically stable for
// t in [0, 1]; the empty row evaluates to P{}.
template <class P>
P deCasteljau(std::span<const P> control, double t) {
  WorkingRow<P> level(control);
  return detail::deCasteljauInPlace(level, level.size(), t);
}

// Subdivision at t: the left edge of de Casteljau's triangle (p00, p10, p20, ...) controls the
// curve on [0, t], the right edge (..., p1(n-1), p0n) the curve on [t, 1], each reparametrised
// to [0, 1].
template <class P>
std::pair<std::vector<P>, std::vector<P>> deCasteljauSplit(std::span<const P> control, double t) {
  std::vector<P> level(control.begin(), control.end());
  const std::size_t count = level.size();
  std::vector<P> left(count), right(count);
  for (std::size_t step = 0; step < count; ++step) {
    const std::size_t n = count - step;  // points left on this level
    left[step] = level[0];
    right[count - 1 - step] = level[n - 1];
    for (std::size_t i = 0; i + 1 < n; ++i) level[i] = interpolate(level[i], level[i + 1], t);
  }
  return {std::move(left), std::move(right)};
}

// The hodograph: the derivative of a degree-n Bezier curve is the degree n-1 Bezier curve with
// control points n (p(i+1) - p(i)).
template <class P>
std::vector<P> hodograph(std::span<const P> control) {
  if (control.size() < 2) return {};
  std::vector<P> result(control.begin(), control.end());
  detail::hodographInPlace(result, result.size());
  result.pop_back();
  return result;
}

// The k-th derivative at t: k hodographs, then de Casteljau. Beyond the degree it is zero.
template <class P>
P deCasteljauDerivative(std::span<const P> control, double t, int order) {
  WorkingRow<P> row(control);
  std::size_t n = row.size();
  for (int k = 0; k < order; ++k, --n) {
    if (n < 2) return P{};
    detail::hodographInPlace(row, n);
  }
  return detail::deCasteljauInPlace(row, n, t);
}

// Degree elevation: the same curve with one more control point,
//   q(i) = i/(n+1) p(i-1) + (1 - i/(n+1)) p(i),   i = 0..n+1.
// Applied to homogeneous points it elevates rational curves too.
template <class P>
std::vector<P> elevateDegree(std::span<const P> control) {
  if (control.empty()) return {};
  const std::size_t n = control.size() - 1;
  std::vector<P> result(control.size() + 1);
  result[0] = control[0];
  result[n + 1] = control[n];
  for (std::size_t i = 1; i <= n; ++i) {
    const double a = static_cast<double>(i) / static_cast<double>(n + 1);
    result[i] = a * control[i - 1] + (1.0 - a) * control[i];
  }
  return result;
}

// Binomial coefficient C(n, k) as a double (exact for the small n used by Leibniz's rule).
inline double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double result = 1.0;
  for (int i = 1; i <= k; ++i) result = result * static_cast<double>(n - k + i) / static_cast<double>(i);
  return result;
}

}  // namespace glass::geometry
