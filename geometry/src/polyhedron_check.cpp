// The checks of polyhedron_check.h.
//
// Edges: each face's loop runs along its edges in order; an edge of a closed solid whose faces are
// turned alike is run along once in each direction. Volume: the divergence theorem over each
// face's triangles (any triangulation of the face's loop gives the same sum). Crossing: faces are
// cut into triangles (a fan for a convex face, the polygon tessellator's triangles otherwise), and
// two triangles cross when each has vertices strictly on both sides of the other's plane and the
// segments where each meets the other's plane overlap along the planes' common line by more than
// the tolerance; faces are paired by a sweep over their bounding boxes along x, so that a mesh of
// many faces is not checked pair by pair. Faces with common vertices are checked like the others:
// a common vertex or edge lies in both planes, so it makes no triangle straddle the other's plane,
// and two faces that meet only there give segments along the common line that touch at the
// vertex, or lie on opposite sides of it, without overlapping; two that cut through each other
// beyond it give segments that overlap.
#include "glass/geometry/polyhedron_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "glass/geometry/polygon_tessellation.h"

namespace glass::geometry {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

void countEdges(const MarkedPolyhedron& shape, PolyhedronCheck& check) {
  // Per edge (smaller vertex first): how often it is run along upwards and downwards.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<int, 2>> runs;
  for (const MarkedPolyhedron::Face& face : shape.faces) {
    const std::size_t n = face.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t a = face.vertices[k], b = face.vertices[(k + 1) % n];
      if (a == b) continue;
      ++runs[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1];
    }
  }
  for (const auto& [edge, count] : runs) {
    const std::array<std::uint32_t, 2> vertices{edge.first, edge.second};
    const int faces = count[0] + count[1];
    if (faces == 1) {
      if (check.openEdges++ == 0) check.firstOpenEdge = vertices;
    } else if (faces > 2) {
      if (check.nonManifoldEdges++ == 0) check.firstNonManifoldEdge = vertices;
    } else if (count[0] != 1) {
      if (check.reversedEdges++ == 0) check.firstReversedEdge = vertices;
    }
  }
}

// The face's loop in the plane across its normal's largest component, turned so that the loop
// keeps its sense.
std::vector<PlanarPoint> projectedLoop(const MarkedPolyhedron& shape, const MarkedPolyhedron::Face& face,
                                       const glm::dvec3& normal) {
  const glm::dvec3 size = glm::abs(normal);
  const int drop = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const bool flip = normal[drop] < 0.0;
  std::vector<PlanarPoint> loop;
  for (const std::uint32_t i : face.vertices) {
    const glm::dvec3& p = shape.vertices[i];
    loop.push_back({flip ? p[v] : p[u], flip ? p[u] : p[v]});
  }
  return loop;
}

bool isConvex(const std::vector<PlanarPoint>& loop) {
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const PlanarPoint& a = loop[k];
    const PlanarPoint& b = loop[(k + 1) % n];
    const PlanarPoint& c = loop[(k + 2) % n];
    if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0.0) return false;
  }
  return true;
}

std::vector<Triangle> faceTriangles(const MarkedPolyhedron& shape, const MarkedPolyhedron::Face& face) {
  std::vector<Triangle> triangles;
  const std::size_t n = face.vertices.size();
  if (n < 3) return triangles;
  const auto at = [&](std::size_t k) { return shape.vertices[face.vertices[k]]; };
  const std::vector<PlanarPoint> loop = projectedLoop(shape, face, newellNormal(shape, face));
  if (n > 3 && !isConvex(loop)) {
    const PolygonTessellation tessellation = tessellatePolygon({loop}, WindingRule::NonZero, false);
    if (tessellation.created.empty()) {
      for (const TessellatedTriangle& t : tessellation.triangles)
        triangles.push_back({at(static_cast<std::size_t>(t.vertices[0])), at(static_cast<std::size_t>(t.vertices[1])),
                             at(static_cast<std::size_t>(t.vertices[2]))});
      return triangles;
    }
  }
  for (std::size_t k = 1; k + 1 < n; ++k) triangles.push_back({at(0), at(k), at(k + 1)});
  return triangles;
}

// The extent along `direction` of the part of triangle t that lies in the plane its vertices are
// at signed distances d[] from (some vertex strictly on each side).
std::pair<double, double> extentInPlane(const Triangle& t, const double d[3], double tolerance,
                                        const glm::dvec3& direction) {
  double low = 1e300, high = -1e300;
  const auto take = [&](const glm::dvec3& p) {
    const double s = glm::dot(direction, p);
    low = std::min(low, s);
    high = std::max(high, s);
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(d[i]) <= tolerance) take(t[i]);
    if ((d[i] > tolerance && d[j] < -tolerance) || (d[i] < -tolerance && d[j] > tolerance))
      take(t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j])));
  }
  return {low, high};
}

bool straddles(const double d[3], double tolerance) {
  bool above = false, below = false;
  for (int i = 0; i < 3; ++i) {
    above |= d[i] > tolerance;
    below |= d[i] < -tolerance;
  }
  return above && below;
}

bool trianglesCross(const Triangle& p, const Triangle& q, double tolerance) {
  const glm::dvec3 np = glm::cross(p[1] - p[0], p[2] - p[0]), nq = glm::cross(q[1] - q[0], q[2] - q[0]);
  const double lp = glm::length(np), lq = glm::length(nq);
  if (!(lp > 0.0) || !(lq > 0.0)) return false;
  const glm::dvec3 up = np / lp, uq = nq / lq;
  double dp[3], dq[3];
  for (int i = 0; i < 3; ++i) {
    dp[i] = glm::dot(uq, p[i] - q[0]);
    dq[i] = glm::dot(up, q[i] - p[0]);
  }
  if (!straddles(dp, tolerance) || !straddles(dq, tolerance)) return false;
  const glm::dvec3 along = glm::cross(up, uq);
  const auto [lowP, highP] = extentInPlane(p, dp, tolerance, along);
  const auto [lowQ, highQ] = extentInPlane(q, dq, tolerance, along);
  return std::min(highP, highQ) - std::max(lowP, lowQ) > tolerance;
}

struct FaceBox {
  glm::dvec3 low, high;
  int face;
};

void findCrossings(const MarkedPolyhedron& shape, PolyhedronCheck& check) {
  if (shape.vertices.empty()) return;
  glm::dvec3 low = shape.vertices[0], high = shape.vertices[0];
  for (const glm::dvec3& v : shape.vertices) {
    low = glm::min(low, v);
    high = glm::max(high, v);
  }
  // Distances below this share of the object's size count as touching, not crossing.
  const double tolerance = 1e-9 * std::max(glm::length(high - low), 1e-300);

  std::vector<FaceBox> boxes;
  std::vector<std::vector<Triangle>> triangles(shape.faces.size());
  for (std::size_t f = 0; f < shape.faces.size(); ++f) {
    const MarkedPolyhedron::Face& face = shape.faces[f];
    if (face.vertices.size() < 3) continue;
    FaceBox box{shape.vertices[face.vertices[0]], shape.vertices[face.vertices[0]], static_cast<int>(f)};
    for (const std::uint32_t i : face.vertices) {
      box.low = glm::min(box.low, shape.vertices[i]);
      box.high = glm::max(box.high, shape.vertices[i]);
    }
    boxes.push_back(box);
    triangles[f] = faceTriangles(shape, face);
  }
  std::sort(boxes.begin(), boxes.end(), [](const FaceBox& a, const FaceBox& b) {
    return a.low.x < b.low.x || (a.low.x == b.low.x && a.face < b.face);
  });
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].low.x < boxes[i].high.x - tolerance; ++j) {
      const FaceBox &a = boxes[i], &b = boxes[j];
      if (b.low.y >= a.high.y - tolerance || a.low.y >= b.high.y - tolerance ||
          b.low.z >= a.high.z - tolerance || a.low.z >= b.high.z - tolerance)
        continue;
      bool cross = false;
      for (const Triangle& p : triangles[static_cast<std::size_t>(a.face)])
        for (const Triangle& q : triangles[static_cast<std::size_t>(b.face)])
          cross = cross || trianglesCross(p, q, tolerance);
      if (!cross) continue;
      const std::array<int, 2> pair{std::min(a.face, b.face), std::max(a.face, b.face)};
      if (check.crossingFacePairs++ == 0 || pair < check.firstCrossing) check.firstCrossing = pair;
    }
  }
}

}  // namespace

PolyhedronCheck checkPolyhedron(const MarkedPolyhedron& shape) {
  PolyhedronCheck check;
  countEdges(shape, check);
  for (const MarkedPolyhedron::Face& face : shape.faces)
    for (const Triangle& t : faceTriangles(shape, face)) check.volume += glm::dot(t[0], glm::cross(t[1], t[2])) / 6.0;
  findCrossings(shape, check);
  return check;
}

}  // namespace glass::geometry
