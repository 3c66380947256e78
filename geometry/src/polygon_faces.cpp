#include "polygon_faces.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

namespace {

int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

class FaceFinder {
 public:
  FaceFinder(const PolygonArrangement& arrangement, PolygonFaces& faces)
      : arrangement_(arrangement), points_(arrangement.points), f_(faces) {}

  void run() {
    buildHalfEdges();
    linkAroundVertices();
    walkCycles();
    findComponents();
    f_.face.assign(f_.cycleStart.size(), kOutsideFace);
    state_.assign(f_.cycleStart.size(), State::Unresolved);
    for (int c = 0; c < static_cast<int>(f_.cycleStart.size()); ++c) resolveFace(c);
    computeWindings();
  }

 private:
  enum class State { Unresolved, Resolving, Resolved };

  void buildHalfEdges() {
    const auto& edges = arrangement_.edges;
    const size_t halfEdges = 2 * edges.size();
    f_.origin.resize(halfEdges);
    f_.count.resize(halfEdges);
    for (size_t e = 0; e < edges.size(); ++e) {
      f_.origin[2 * e] = edges[e].from;
      f_.origin[2 * e + 1] = edges[e].to;
      f_.count[2 * e] = edges[e].count;
      f_.count[2 * e + 1] = -edges[e].count;
    }
  }

  double direction(int h) const {
    const PlanarPoint& a = points_[f_.origin[h]];
    const PlanarPoint& b = points_[f_.target(h)];
    return portable::atan2(b.y - a.y, b.x - a.x);
  }

  // Around each vertex the outgoing half-edges run counter-clockwise; the face on the left of
  // an incoming half-edge continues along the outgoing half-edge just clockwise of its twin.
  void linkAroundVertices() {
    const int halfEdges = static_cast<int>(f_.origin.size());
    f_.outgoing.assign(points_.size(), {});
    for (int h = 0; h < halfEdges; ++h) f_.outgoing[f_.origin[h]].push_back(h);
    f_.outgoingIndex.assign(halfEdges, 0);
    for (auto& list : f_.outgoing) {
      std::vector<std::pair<double, int>> keyed;
      keyed.reserve(list.size());
      for (int h : list) keyed.emplace_back(direction(h), h);
      std::sort(keyed.begin(), keyed.end());
      for (size_t i = 0; i < list.size(); ++i) {
        list[i] = keyed[i].second;
        f_.outgoingIndex[list[i]] = static_cast<int>(i);
      }
    }
    f_.next.assign(halfEdges, -1);
    for (int h = 0; h < halfEdges; ++h) {
      const auto& around = f_.outgoing[f_.target(h)];
      const int n = static_cast<int>(around.size());
      f_.next[h] = around[(f_.outgoingIndex[f_.twin(h)] + n - 1) % n];
    }
  }

  void walkCycles() {
    const int halfEdges = static_cast<int>(f_.origin.size());
    f_.cycle.assign(halfEdges, -1);
    for (int start = 0; start < halfEdges; ++start) {
      if (f_.cycle[start] >= 0) continue;
      const int c = static_cast<int>(f_.cycleStart.size());
      const PlanarPoint& base = points_[f_.origin[start]];
      double area = 0.0;
      int h = start;
      do {
        f_.cycle[h] = c;
        // The shoelace formula, relative to the cycle's first point for precision.
        const PlanarPoint& a = points_[f_.origin[h]];
        const PlanarPoint& b = points_[f_.target(h)];
        area += (a.x - base.x) * (b.y - base.y) - (b.x - base.x) * (a.y - base.y);
        h = f_.next[h];
      } while (h != start);
      f_.cycleStart.push_back(start);
      f_.cycleArea.push_back(area);
    }
  }

  void findComponents() {
    component_.resize(points_.size());
    std::iota(component_.begin(), component_.end(), 0);
    for (const ArrangementEdge& e : arrangement_.edges) {
      component_[findRoot(component_, e.from)] = findRoot(component_, e.to);
    }
    for (size_t v = 0; v < component_.size(); ++v) findRoot(component_, static_cast<int>(v));
  }

  int componentOf(int v) { return findRoot(component_, v); }

  // The face on the left of cycle c. A cycle of non-positive area is the outside of its piece of
  // the graph; the first edge of another piece that a ray from the piece's leftmost vertex meets
  // going left bounds the face the piece lies in, on the side facing the ray's start.
  int resolveFace(int c) {
    if (state_[c] == State::Resolved) return f_.face[c];
    if (f_.cycleArea[c] > 0.0) {
      state_[c] = State::Resolved;
      return f_.face[c] = c;
    }
    if (state_[c] == State::Resolving) return kOutsideFace;  // cannot happen in a planar graph
    state_[c] = State::Resolving;

    int leftmost = f_.origin[f_.cycleStart[c]];
    for (int h = f_.next[f_.cycleStart[c]]; h != f_.cycleStart[c]; h = f_.next[h]) {
      const PlanarPoint& p = points_[f_.origin[h]];
      const PlanarPoint& q = points_[leftmost];
      if (p.x < q.x || (p.x == q.x && p.y < q.y)) leftmost = f_.origin[h];
    }
    const PlanarPoint p = points_[leftmost];
    const int piece = componentOf(leftmost);

    int hitEdge = -1;
    double hitX = 0.0, hitSlope = 0.0;
    const auto& edges = arrangement_.edges;
    for (size_t e = 0; e < edges.size(); ++e) {
      if (componentOf(edges[e].from) == piece) continue;
      const PlanarPoint& a = points_[edges[e].from];
      const PlanarPoint& b = points_[edges[e].to];
      // Half-open in y, so that a ray through a vertex meets the edges above it: the ray is
      // taken an infinitesimal distance above p.
      const bool spans = (a.y <= p.y && p.y < b.y) || (b.y <= p.y && p.y < a.y);
      if (!spans) continue;
      const double slope = (b.x - a.x) / (b.y - a.y);
      const double x = a.x + (p.y - a.y) * slope;
      if (!(x < p.x)) continue;
      if (hitEdge < 0 || x > hitX || (x == hitX && slope > hitSlope)) {
        hitEdge = static_cast<int>(e);
        hitX = x;
        hitSlope = slope;
      }
    }
    int result = kOutsideFace;
    if (hitEdge >= 0) {
      const PlanarPoint& a = points_[edges[hitEdge].from];
      const PlanarPoint& b = points_[edges[hitEdge].to];
      const int facing = orientation(a, b, p) > 0.0 ? 2 * hitEdge : 2 * hitEdge + 1;
      result = resolveFace(f_.cycle[facing]);
    }
    state_[c] = State::Resolved;
    return f_.face[c] = result;
  }

  // From the outside (winding 0), across every edge: the face on a half-edge's left has the
  // winding number of the face on its right plus the half-edge's count.
  void computeWindings() {
    const int cycles = static_cast<int>(f_.cycleStart.size());
    const int outside = cycles;  // the outside's slot in the lists below
    auto slot = [&](int face) { return face == kOutsideFace ? outside : face; };
    std::vector<std::vector<int>> halfEdgesOfFace(cycles + 1);
    for (int h = 0; h < static_cast<int>(f_.origin.size()); ++h) {
      halfEdgesOfFace[slot(f_.faceOf(h))].push_back(h);
    }
    std::vector<int> winding(cycles + 1, 0);
    std::vector<bool> known(cycles + 1, false);
    std::deque<int> queue{outside};
    known[outside] = true;
    while (!queue.empty()) {
      const int x = queue.front();
      queue.pop_front();
      for (int h : halfEdgesOfFace[x]) {
        const int y = slot(f_.faceOf(f_.twin(h)));
        if (known[y]) continue;
        known[y] = true;
        winding[y] = winding[x] + f_.count[f_.twin(h)];
        queue.push_back(y);
      }
    }
    f_.winding.assign(winding.begin(), winding.begin() + cycles);
  }

  const PolygonArrangement& arrangement_;
  const std::vector<PlanarPoint>& points_;
  PolygonFaces& f_;
  std::vector<int> component_;
  std::vector<State> state_;
};

}  // namespace

PolygonFaces findFaces(const PolygonArrangement& arrangement) {
  PolygonFaces faces;
  FaceFinder(arrangement, faces).run();
  return faces;
}

}  // namespace glass::geometry
