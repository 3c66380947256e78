#include "polygon_triangulation.h"

#include <algorithm>
#include <cmath>

#include "polygon_arrangement.h"

namespace glass::geometry {

namespace {

// The ring as a doubly linked list of nodes; a vertex may appear in several nodes (a ring that
// touches itself, or the two ends of a bridge).
struct RingNode {
  int vertex = 0;
  int prev = 0;
  int next = 0;
  bool boundary = false;  // the edge from this node to the next
};

class EarClipper {
 public:
  EarClipper(const std::vector<PlanarPoint>& points, std::vector<TessellatedTriangle>& out)
      : points_(points), out_(out) {}

  // Adds a ring's nodes; returns the first.
  int addRing(const PolygonRing& ring) {
    const int first = static_cast<int>(nodes_.size());
    const int n = static_cast<int>(ring.vertices.size());
    for (int k = 0; k < n; ++k) {
      RingNode node;
      node.vertex = ring.vertices[k];
      node.prev = first + (k + n - 1) % n;
      node.next = first + (k + 1) % n;
      node.boundary = ring.boundary[k];
      nodes_.push_back(node);
    }
    return first;
  }

  // Joins the hole starting at `hole` into the ring through `outer`. Holes are joined from the
  // rightmost one outwards, each at its rightmost vertex, so that no later bridge crosses an
  // earlier one.
  void bridgeHole(int outer, int hole) {
    const int m = rightmostNode(hole);
    const int p = visibleNode(outer, m);
    if (p < 0) return;  // numerically impossible to join; the hole is left out
    const int mCopy = copyNode(m), pCopy = copyNode(p);
    // ... p -> m -> (around the hole) -> m' -> p' -> (p's old successor) ...
    const int pNext = nodes_[p].next, mPrev = nodes_[m].prev;
    nodes_[pCopy].next = pNext;
    nodes_[pNext].prev = pCopy;
    nodes_[pCopy].boundary = nodes_[p].boundary;
    nodes_[p].next = m;
    nodes_[m].prev = p;
    nodes_[p].boundary = false;
    nodes_[mPrev].next = mCopy;
    nodes_[mCopy].prev = mPrev;
    nodes_[mCopy].next = pCopy;
    nodes_[pCopy].prev = mCopy;
    nodes_[mCopy].boundary = false;
  }

  int rightmostNode(int start) const {
    int best = start;
    for (int i = nodes_[start].next; i != start; i = nodes_[i].next) {
      const PlanarPoint &a = at(i), &b = at(best);
      if (a.x > b.x || (a.x == b.x && a.y < b.y)) best = i;
    }
    return best;
  }

  void clip(int start) {
    int count = 1;
    for (int i = nodes_[start].next; i != start; i = nodes_[i].next) ++count;
    int node = start;
    int stalled = 0;
    while (count > 3) {
      if (isEar(node)) {
        const int next = nodes_[node].next;
        emitAndRemove(node);
        --count;
        node = next;
        stalled = 0;
        continue;
      }
      node = nodes_[node].next;
      if (++stalled < count) continue;
      // A full turn without an ear: the ring is degenerate somewhere (collinear or rounding).
      node = resolveStall(node, count);
      if (node < 0) return;
      --count;
      stalled = 0;
    }
    if (count == 3 && area(node) > 0.0) emit(nodes_[node].prev, node, nodes_[node].next, false);
  }

 private:
  const PlanarPoint& at(int node) const { return points_[nodes_[node].vertex]; }

  int copyNode(int i) {
    nodes_.push_back(nodes_[i]);
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Twice the signed area of the corner at `node`: positive where the ring turns left (convex).
  double area(int node) const {
    return orientation(at(nodes_[node].prev), at(node), at(nodes_[node].next));
  }

  // The ring node that vertex node m of a hole can be joined to: where a ray from m to the right
  // first meets the ring, the end of that edge further right, unless a reflex vertex inside the
  // triangle (m, hit, end) blocks the view; then the blocking vertex at the smallest angle from
  // the ray.
  int visibleNode(int outer, int m) const {
    const PlanarPoint mp = at(m);
    int edge = -1;
    double hitX = 0.0;
    int i = outer;
    do {
      const int j = nodes_[i].next;
      const PlanarPoint &a = at(i), &b = at(j);
      // A counter-clockwise ring's edges that face a point on their left to the right go up.
      if (a.y <= mp.y && mp.y <= b.y && a.y < b.y) {
        const double x = a.x + (mp.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x >= mp.x && (edge < 0 || x < hitX)) {
          edge = i;
          hitX = x;
        }
      }
      i = j;
    } while (i != outer);
    if (edge < 0) return -1;
    const int a = edge, b = nodes_[edge].next;
    if (at(a).y == mp.y && at(a).x == hitX) return a;
    if (at(b).y == mp.y && at(b).x == hitX) return b;
    int candidate = at(a).x > at(b).x ? a : b;
    const PlanarPoint hit{hitX, mp.y};
    const PlanarPoint cp = at(candidate);
    double bestTangent = INFINITY, bestDistance = INFINITY;
    int blocker = -1;
    i = outer;
    do {
      const PlanarPoint& q = at(i);
      if (i != candidate && q.x >= mp.x && area(i) <= 0.0 && insideOrOn(mp, hit, cp, q)) {
        const double tangent = std::abs(q.y - mp.y) / (q.x - mp.x);
        const double distance = q.x - mp.x;
        if (tangent < bestTangent || (tangent == bestTangent && distance < bestDistance)) {
          blocker = i;
          bestTangent = tangent;
          bestDistance = distance;
        }
      }
      i = nodes_[i].next;
    } while (i != outer);
    return blocker >= 0 ? blocker : candidate;
  }

  // Whether q lies in triangle (a, b, c) or on its sides, whatever the triangle's orientation.
  static bool insideOrOn(const PlanarPoint& a, const PlanarPoint& b, const PlanarPoint& c,
                         const PlanarPoint& q) {
    const double d1 = orientation(a, b, q), d2 = orientation(b, c, q), d3 = orientation(c, a, q);
    const bool hasNegative = d1 < 0.0 || d2 < 0.0 || d3 < 0.0;
    const bool hasPositive = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
    return !(hasNegative && hasPositive);
  }

  // An ear: a convex corner whose triangle contains no other ring vertex (vertices at the
  // corners' positions excepted: a ring may pass through a point twice).
  bool isEar(int node) const {
    if (area(node) <= 0.0) return false;
    const int prev = nodes_[node].prev, next = nodes_[node].next;
    const PlanarPoint &a = at(prev), &b = at(node), &c = at(next);
    for (int i = nodes_[next].next; i != prev; i = nodes_[i].next) {
      const PlanarPoint& q = at(i);
      if (q == a || q == b || q == c) continue;
      if (area(i) > 0.0) continue;  // a convex vertex inside implies a reflex one inside
      if (orientation(a, b, q) >= 0.0 && orientation(b, c, q) >= 0.0 &&
          orientation(c, a, q) >= 0.0) {
        return false;
      }
    }
    return true;
  }

  void emit(int a, int b, int c, bool closingBoundary) {
    TessellatedTriangle t;
    t.vertices = {nodes_[a].vertex, nodes_[b].vertex, nodes_[c].vertex};
    t.boundaryEdge = {nodes_[a].boundary, nodes_[b].boundary,
                      closingBoundary || nodes_[c].boundary};
    out_.push_back(t);
  }

  // Outputs the ear at `node` and removes the node; the new edge prev -> next is a diagonal.
  void emitAndRemove(int node) {
    const int prev = nodes_[node].prev, next = nodes_[node].next;
    TessellatedTriangle t;
    t.vertices = {nodes_[prev].vertex, nodes_[node].vertex, nodes_[next].vertex};
    t.boundaryEdge = {nodes_[prev].boundary, nodes_[node].boundary, false};
    out_.push_back(t);
    unlink(node, false);
  }

  void unlink(int node, bool boundary) {
    const int prev = nodes_[node].prev, next = nodes_[node].next;
    nodes_[prev].next = next;
    nodes_[next].prev = prev;
    nodes_[prev].boundary = boundary;
  }

  // Makes progress on a ring without ears: drops a corner of zero area (a straight vertex or a
  // spike, which covers nothing), else clips the convex corner whose triangle holds the fewest
  // other vertices. Returns the node to continue from, or -1 when nothing can be done.
  int resolveStall(int start, int count) {
    int node = start;
    for (int k = 0; k < count; ++k, node = nodes_[node].next) {
      if (area(node) == 0.0) {
        const int next = nodes_[node].next;
        unlink(node, nodes_[nodes_[node].prev].boundary && nodes_[node].boundary);
        return next;
      }
    }
    for (int k = 0; k < count; ++k, node = nodes_[node].next) {
      if (area(node) > 0.0) {
        const int next = nodes_[node].next;
        emitAndRemove(node);
        return next;
      }
    }
    return -1;
  }

  const std::vector<PlanarPoint>& points_;
  std::vector<TessellatedTriangle>& out_;
  std::vector<RingNode> nodes_;
};

}  // namespace

void triangulateRing(const std::vector<PlanarPoint>& points, const PolygonRing& outer,
                     const std::vector<PolygonRing>& holes, std::vector<TessellatedTriangle>& out) {
  if (outer.vertices.size() < 3) return;
  EarClipper clipper(points, out);
  const int start = clipper.addRing(outer);
  std::vector<std::pair<double, int>> holeStarts;  // (rightmost x, first node), rightmost first
  for (const PolygonRing& hole : holes) {
    if (hole.vertices.size() < 3) continue;
    const int first = clipper.addRing(hole);
    double maxX = -INFINITY;
    for (int v : hole.vertices) maxX = std::max(maxX, points[v].x);
    holeStarts.emplace_back(maxX, first);
  }
  std::sort(holeStarts.begin(), holeStarts.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [x, first] : holeStarts) clipper.bridgeHole(start, first);
  clipper.clip(start);
}

}  // namespace glass::geometry
