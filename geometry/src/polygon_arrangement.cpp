#include "polygon_arrangement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace glass::geometry {

namespace {

// A contour edge between two (merged) vertices, in the contour's direction.
struct Segment {
  int from = 0;
  int to = 0;
};

// A vertex that lies inside a segment, at parameter t in (0, 1) from the segment's start.
struct SplitPoint {
  double t = 0.0;
  int vertex = 0;
};

double l1Distance(const PlanarPoint& a, const PlanarPoint& b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y);
}

// The parameter of p's projection onto the line through a and b (0 at a, 1 at b).
double parameterAlong(const PlanarPoint& a, const PlanarPoint& b, const PlanarPoint& p) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
}

class ArrangementBuilder {
 public:
  explicit ArrangementBuilder(const std::vector<std::vector<PlanarPoint>>& contours)
      : contours_(contours) {}

  PolygonArrangement build() {
    mergeCoincidentVertices();
    collectSegments();
    findSplitPoints();
    collectEdges();
    return std::move(result_);
  }

 private:
  int addCreated(const CreatedVertex& v) {
    const int id = static_cast<int>(result_.points.size());
    result_.points.push_back(v.position);
    result_.created.push_back(v);
    mergedInto_.push_back(-1);
    return id;
  }

  // The vertex that finally stands for v after every merge.
  int finalVertex(int v) const {
    while (mergedInto_[v] >= 0) v = mergedInto_[v];
    return v;
  }

  // Input vertices at the same position become one created vertex, merged pairwise in input
  // order, as GLU merges them (its combine callback sees two vertices of weight 1/2 each).
  void mergeCoincidentVertices() {
    for (const auto& contour : contours_) {
      for (const PlanarPoint& p : contour) {
        result_.points.push_back(p);
        mergedInto_.push_back(-1);
      }
    }
    const int inputCount = static_cast<int>(result_.points.size());
    for (int i = 0; i < inputCount; ++i) {
      const PlanarPoint p = result_.points[i];
      const auto key = std::make_pair(p.x, p.y);
      const auto found = byPosition_.find(key);
      if (found == byPosition_.end()) {
        byPosition_.emplace(key, i);
        continue;
      }
      CreatedVertex merged;
      merged.position = p;
      merged.sources = {found->second, i, -1, -1};
      merged.weights = {0.5, 0.5, 0.0, 0.0};
      const int id = addCreated(merged);
      mergedInto_[found->second] = id;
      mergedInto_[i] = id;
      found->second = id;
    }
  }

  // Each contour's edges between consecutive distinct vertices, closing edge included.
  void collectSegments() {
    int first = 0;
    for (const auto& contour : contours_) {
      std::vector<int> ring;
      for (size_t k = 0; k < contour.size(); ++k) {
        const int v = finalVertex(first + static_cast<int>(k));
        if (ring.empty() || ring.back() != v) ring.push_back(v);
      }
      while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      if (ring.size() >= 2) {
        for (size_t k = 0; k < ring.size(); ++k) {
          segments_.push_back({ring[k], ring[(k + 1) % ring.size()]});
        }
      }
      first += static_cast<int>(contour.size());
    }
    splits_.resize(segments_.size());
    double extent = 0.0;
    for (const PlanarPoint& p : result_.points) {
      extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    }
    // Crossings closer than this are one point: three edges through one point would otherwise
    // make three crossing vertices a rounding error apart.
    snapDistance_ = extent * 1e-12;
  }

  const PlanarPoint& point(int v) const { return result_.points[v]; }

  // Every pair of segments whose bounding boxes overlap, found by sorting on the left end.
  void findSplitPoints() {
    const size_t n = segments_.size();
    std::vector<size_t> order(n);
    std::vector<double> minX(n), maxX(n), minY(n), maxY(n);
    for (size_t i = 0; i < n; ++i) {
      const PlanarPoint& a = point(segments_[i].from);
      const PlanarPoint& b = point(segments_[i].to);
      minX[i] = std::min(a.x, b.x);
      maxX[i] = std::max(a.x, b.x);
      minY[i] = std::min(a.y, b.y);
      maxY[i] = std::max(a.y, b.y);
      order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return minX[a] < minX[b] || (minX[a] == minX[b] && a < b);
    });
    for (size_t oi = 0; oi < n; ++oi) {
      const size_t i = order[oi];
      for (size_t oj = oi + 1; oj < n && minX[order[oj]] <= maxX[i]; ++oj) {
        const size_t j = order[oj];
        if (minY[j] > maxY[i] || maxY[j] < minY[i]) continue;
        intersect(i < j ? i : j, i < j ? j : i);
      }
    }
  }

  // Adds p to segment s's split points when p lies strictly inside it.
  void splitIfInside(size_t s, int p) {
    const Segment& seg = segments_[s];
    if (p == seg.from || p == seg.to) return;
    const PlanarPoint& a = point(seg.from);
    const PlanarPoint& b = point(seg.to);
    const PlanarPoint& q = point(p);
    if (orientation(a, b, q) != 0.0) return;
    const double t = parameterAlong(a, b, q);
    if (t > 0.0 && t < 1.0) splits_[s].push_back({t, p});
  }

  void intersect(size_t s1, size_t s2) {
    const int a = segments_[s1].from, b = segments_[s1].to;
    const int c = segments_[s2].from, d = segments_[s2].to;
    if ((a == c && b == d) || (a == d && b == c)) return;
    // Vertices lying on the other segment (T-junctions and collinear overlaps) split it; no new
    // vertex is needed.
    splitIfInside(s1, c);
    splitIfInside(s1, d);
    splitIfInside(s2, a);
    splitIfInside(s2, b);
    if (a == c || a == d || b == c || b == d) return;

    const PlanarPoint &pa = point(a), &pb = point(b), &pc = point(c), &pd = point(d);
    const double o1 = orientation(pa, pb, pc), o2 = orientation(pa, pb, pd);
    const double o3 = orientation(pc, pd, pa), o4 = orientation(pc, pd, pb);
    const bool crosses = ((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
                         ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0));
    if (!crosses) return;

    // The signed distances from the other line vary linearly along each segment: the crossing
    // is where they vanish.
    const double t = o3 / (o3 - o4);
    const double u = o1 / (o1 - o2);
    const PlanarPoint p{pa.x + t * (pb.x - pa.x), pa.y + t * (pb.y - pa.y)};
    const int v = crossingVertex(p, a, b, c, d);
    if (v != a && v != b) splits_[s1].push_back({t, v});
    if (v != c && v != d) splits_[s2].push_back({u, v});
  }

  // The vertex at crossing p of edges (a, b) and (c, d): an existing vertex at (or, for earlier
  // crossings, within a rounding error of) p, else a new one weighted as GLU weights it: each
  // edge carries 1/2, split between its ends in inverse proportion to their distance from p.
  int crossingVertex(const PlanarPoint& p, int a, int b, int c, int d) {
    if (const auto found = byPosition_.find({p.x, p.y}); found != byPosition_.end()) {
      return finalVertex(found->second);
    }
    for (int v : crossings_) {
      if (l1Distance(point(v), p) <= snapDistance_) return v;
    }
    CreatedVertex crossing;
    crossing.position = p;
    crossing.isCrossing = true;
    crossing.sources = {a, b, c, d};
    const double ta = l1Distance(point(a), p), tb = l1Distance(point(b), p);
    const double tc = l1Distance(point(c), p), td = l1Distance(point(d), p);
    crossing.weights = {0.5 * tb / (ta + tb), 0.5 * ta / (ta + tb), 0.5 * td / (tc + td),
                        0.5 * tc / (tc + td)};
    const int id = addCreated(crossing);
    byPosition_.emplace(std::make_pair(p.x, p.y), id);
    crossings_.push_back(id);
    return id;
  }

  // Each segment cut at its split points; the pieces' directed counts summed per vertex pair.
  void collectEdges() {
    std::map<std::pair<int, int>, int> counts;
    for (size_t s = 0; s < segments_.size(); ++s) {
      auto& splits = splits_[s];
      std::sort(splits.begin(), splits.end(), [](const SplitPoint& x, const SplitPoint& y) {
        return x.t < y.t || (x.t == y.t && x.vertex < y.vertex);
      });
      std::vector<int> chain{segments_[s].from};
      for (const SplitPoint& sp : splits) {
        if (chain.back() != sp.vertex) chain.push_back(sp.vertex);
      }
      if (chain.back() != segments_[s].to) chain.push_back(segments_[s].to);
      for (size_t k = 0; k + 1 < chain.size(); ++k) {
        const int u = chain[k], v = chain[k + 1];
        if (u < v) {
          ++counts[{u, v}];
        } else {
          --counts[{v, u}];
        }
      }
    }
    for (const auto& [key, count] : counts) {
      if (count != 0) result_.edges.push_back({key.first, key.second, count});
    }
  }

  const std::vector<std::vector<PlanarPoint>>& contours_;
  PolygonArrangement result_;
  std::vector<int> mergedInto_;  // per vertex: the vertex it merged into, or -1
  std::map<std::pair<double, double>, int> byPosition_;
  std::vector<int> crossings_;
  double snapDistance_ = 0.0;
  std::vector<Segment> segments_;
  std::vector<std::vector<SplitPoint>> splits_;
};

}  // namespace

PolygonArrangement arrangeContours(const std::vector<std::vector<PlanarPoint>>& contours) {
  return ArrangementBuilder(contours).build();
}

}  // namespace glass::geometry
