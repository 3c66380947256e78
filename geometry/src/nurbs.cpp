#include "glass/geometry/nurbs.h"

#include <algorithm>

namespace glass::geometry {

KnotVectorError checkKnotVector(int order, std::span<const float> knots) {
  if (order < 2 || order > kMaxNurbsOrder) return KnotVectorError::UnsupportedOrder;
  const int count = static_cast<int>(knots.size());
  if (count < 2 * order) return KnotVectorError::TooFewKnots;
  if (!(knots[order - 1] < knots[count - order])) {
    for (int i = 0; i + 1 < count; ++i) {
      if (knots[i + 1] < knots[i]) return KnotVectorError::Decreasing;
    }
    return KnotVectorError::EmptyRange;
  }
  int multiplicity = 1;
  for (int i = 0; i + 1 < count; ++i) {
    if (knots[i + 1] < knots[i]) return KnotVectorError::Decreasing;
    multiplicity = knots[i + 1] == knots[i] ? multiplicity + 1 : 1;
    if (multiplicity > order) return KnotVectorError::MultiplicityTooHigh;
  }
  return KnotVectorError::None;
}

namespace {

// A B-spline whose "points" are blocks of `width` numbers: a curve's points, or for a surface
// whole rows or columns of the net, which split the same way.
class KnotInserter {
 public:
  KnotInserter(int order, std::span<const float> knots, int width, std::span<const double> points)
      : order_(order), width_(width), knots_(knots.begin(), knots.end()),
        points_(points.begin(), points.end()) {}

  // Raises every distinct knot of the valid range, and every extra breakpoint inside it, to
  // multiplicity `order`.
  void splitAtEveryKnot(std::span<const double> extra) {
    const int count = static_cast<int>(knots_.size());
    const double first = knots_[order_ - 1], last = knots_[count - order_];
    std::vector<double> breakpoints;
    for (int i = order_ - 1; i <= count - order_; ++i) {
      if (breakpoints.empty() || knots_[i] != breakpoints.back()) breakpoints.push_back(knots_[i]);
    }
    breakpoints.insert(breakpoints.end(), extra.begin(), extra.end());
    std::sort(breakpoints.begin(), breakpoints.end());
    breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());
    for (double u : breakpoints) {
      if (u < first || u > last) continue;
      int multiplicity = static_cast<int>(std::count(knots_.begin(), knots_.end(), u));
      for (; multiplicity < order_; ++multiplicity) insert(u, u == last);
    }
  }

  // The spans of the valid range: (span index s, knots[s], knots[s + 1]); the piece's points
  // are blocks s - order + 1 .. s.
  template <class Visit>
  void forEachPiece(Visit&& visit) const {
    const int count = static_cast<int>(knots_.size());
    const double first = knots_[order_ - 1], last = knots_[count - order_];
    for (int s = order_ - 1; s + 1 < count; ++s) {
      if (!(knots_[s] < knots_[s + 1]) || knots_[s] < first || knots_[s + 1] > last) continue;
      const auto begin = points_.begin() + static_cast<long>(s - order_ + 1) * width_;
      visit(knots_[s], knots_[s + 1],
            std::vector<double>(begin, begin + static_cast<long>(order_) * width_));
    }
  }

 private:
  // Boehm's insertion of u into span s (knots[s] <= u <= knots[s + 1]): with degree p,
  //   Q_i = P_i                              for i <= s - p
  //   Q_i = (1 - a_i) P_{i-1} + a_i P_i,     a_i = (u - t_i) / (t_{i+p} - t_i), s - p < i <= s
  //   Q_i = P_{i-1}                          for i > s
  // At the end of the range the span is the last non-empty one, whose right end is u.
  void insert(double u, bool atEnd) {
    const int p = order_ - 1;
    int s = 0;
    const int count = static_cast<int>(knots_.size());
    for (int i = 0; i + 1 < count; ++i) {
      if (atEnd ? (knots_[i] < u) : (knots_[i] <= u && u < knots_[i + 1])) s = i;
    }
    const int pointCount = static_cast<int>(points_.size()) / width_;
    std::vector<double> q(static_cast<size_t>(pointCount + 1) * width_);
    for (int i = 0; i <= pointCount; ++i) {
      double* out = &q[static_cast<size_t>(i) * width_];
      if (i <= s - p) {
        std::copy_n(&points_[static_cast<size_t>(i) * width_], width_, out);
      } else if (i > s) {
        std::copy_n(&points_[static_cast<size_t>(i - 1) * width_], width_, out);
      } else {
        const double a = (u - knots_[i]) / (knots_[i + p] - knots_[i]);
        const double* before = &points_[static_cast<size_t>(i - 1) * width_];
        const double* at = &points_[static_cast<size_t>(i) * width_];
        for (int c = 0; c < width_; ++c) out[c] = (1.0 - a) * before[c] + a * at[c];
      }
    }
    points_ = std::move(q);
    knots_.insert(knots_.begin() + s + 1, u);
  }

  int order_;
  int width_;
  std::vector<double> knots_;
  std::vector<double> points_;
};

}  // namespace

std::vector<double> breakpointsOf(int order, std::span<const float> knots) {
  std::vector<double> breakpoints;
  const int count = static_cast<int>(knots.size());
  for (int i = order - 1; i <= count - order; ++i) {
    if (breakpoints.empty() || knots[i] != breakpoints.back()) breakpoints.push_back(knots[i]);
  }
  return breakpoints;
}

std::vector<BezierCurvePiece> bezierPiecesOfCurve(int order, std::span<const float> knots,
                                                  int dimension, std::span<const double> points,
                                                  std::span<const double> extraBreakpoints) {
  KnotInserter curve(order, knots, dimension, points);
  curve.splitAtEveryKnot(extraBreakpoints);
  std::vector<BezierCurvePiece> pieces;
  curve.forEachPiece([&](double u0, double u1, std::vector<double> piece) {
    pieces.push_back({u0, u1, std::move(piece)});
  });
  return pieces;
}

std::vector<BezierSurfacePiece> bezierPiecesOfSurface(
    int uOrder, std::span<const float> uKnots, int vOrder, std::span<const float> vKnots,
    int dimension, std::span<const double> points, std::span<const double> extraUBreakpoints,
    std::span<const double> extraVBreakpoints) {
  const int vCount = static_cast<int>(vKnots.size()) - vOrder;
  // Along u the "points" are whole rows of vCount points.
  KnotInserter rows(uOrder, uKnots, vCount * dimension, points);
  rows.splitAtEveryKnot(extraUBreakpoints);
  std::vector<BezierSurfacePiece> pieces;
  rows.forEachPiece([&](double u0, double u1, std::vector<double> band) {
    // band: uOrder rows of vCount points. Along v the "points" are columns of uOrder points.
    std::vector<double> columns(band.size());
    for (int i = 0; i < uOrder; ++i) {
      for (int j = 0; j < vCount; ++j) {
        for (int c = 0; c < dimension; ++c) {
          columns[(static_cast<size_t>(j) * uOrder + i) * dimension + c] =
              band[(static_cast<size_t>(i) * vCount + j) * dimension + c];
        }
      }
    }
    KnotInserter cols(vOrder, vKnots, uOrder * dimension, columns);
    cols.splitAtEveryKnot(extraVBreakpoints);
    cols.forEachPiece([&](double v0, double v1, std::vector<double> piece) {
      // piece: vOrder columns of uOrder points; back to (i, j) with i outer.
      BezierSurfacePiece out{u0, u1, v0, v1, std::vector<double>(piece.size())};
      for (int j = 0; j < vOrder; ++j) {
        for (int i = 0; i < uOrder; ++i) {
          for (int c = 0; c < dimension; ++c) {
            out.points[(static_cast<size_t>(i) * vOrder + j) * dimension + c] =
                piece[(static_cast<size_t>(j) * uOrder + i) * dimension + c];
          }
        }
      }
      pieces.push_back(std::move(out));
    });
  });
  return pieces;
}

}  // namespace glass::geometry
