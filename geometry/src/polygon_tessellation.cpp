#include "glass/geometry/polygon_tessellation.h"

#include <cstdlib>

#include "polygon_arrangement.h"
#include "polygon_faces.h"
#include "polygon_triangulation.h"

namespace glass::geometry {

bool isInsideByWindingRule(WindingRule rule, int winding) {
  switch (rule) {
    case WindingRule::Odd: return (winding & 1) != 0;
    case WindingRule::NonZero: return winding != 0;
    case WindingRule::Positive: return winding > 0;
    case WindingRule::Negative: return winding < 0;
    case WindingRule::AbsGeqTwo: return std::abs(winding) >= 2;
  }
  return false;
}

namespace {

// Whether the face on the left of half-edge h is inside.
bool insideLeftOf(const PolygonFaces& faces, const std::vector<bool>& insideFace, int h) {
  const int f = faces.faceOf(h);
  return f != kOutsideFace && insideFace[f];
}

PolygonRing ringOfCycle(const PolygonFaces& faces, const std::vector<bool>& insideFace, int c) {
  PolygonRing ring;
  const int start = faces.cycleStart[c];
  int h = start;
  do {
    ring.vertices.push_back(faces.origin[h]);
    ring.boundary.push_back(!insideLeftOf(faces, insideFace, faces.twin(h)));
    h = faces.next[h];
  } while (h != start);
  return ring;
}

// The loops around the inside region: half-edges with the inside on their left and the outside
// on their right, each followed at its end by the next such half-edge clockwise around the vertex
// (the region's boundary turns there, keeping the region on the left).
std::vector<std::vector<int>> boundaryLoops(const PolygonFaces& faces,
                                            const std::vector<bool>& insideFace) {
  const int halfEdges = static_cast<int>(faces.origin.size());
  auto isBoundary = [&](int h) {
    return insideLeftOf(faces, insideFace, h) && !insideLeftOf(faces, insideFace, faces.twin(h));
  };
  std::vector<bool> used(halfEdges, false);
  std::vector<std::vector<int>> loops;
  for (int start = 0; start < halfEdges; ++start) {
    if (used[start] || !isBoundary(start)) continue;
    std::vector<int> loop;
    int h = start;
    while (!used[h]) {
      used[h] = true;
      loop.push_back(faces.origin[h]);
      const auto& around = faces.outgoing[faces.target(h)];
      const int n = static_cast<int>(around.size());
      int i = faces.outgoingIndex[faces.twin(h)];
      do {
        i = (i + n - 1) % n;
      } while (!isBoundary(around[i]));
      h = around[i];
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

PolygonTessellation tessellatePolygon(const std::vector<std::vector<PlanarPoint>>& contours,
                                      WindingRule rule, bool boundaryOnly) {
  PolygonArrangement arrangement = arrangeContours(contours);
  const PolygonFaces faces = findFaces(arrangement);
  const int cycles = static_cast<int>(faces.cycleStart.size());
  std::vector<bool> insideFace(cycles, false);
  for (int c = 0; c < cycles; ++c) {
    insideFace[c] = faces.cycleArea[c] > 0.0 && isInsideByWindingRule(rule, faces.winding[c]);
  }

  PolygonTessellation result;
  if (boundaryOnly) {
    result.boundaryLoops = boundaryLoops(faces, insideFace);
  } else {
    std::vector<std::vector<PolygonRing>> holes(cycles);
    for (int c = 0; c < cycles; ++c) {
      const int f = faces.face[c];
      if (faces.cycleArea[c] <= 0.0 && f != kOutsideFace && insideFace[f]) {
        holes[f].push_back(ringOfCycle(faces, insideFace, c));
      }
    }
    for (int c = 0; c < cycles; ++c) {
      if (!insideFace[c]) continue;
      triangulateRing(arrangement.points, ringOfCycle(faces, insideFace, c), holes[c],
                      result.triangles);
    }
  }
  result.created = std::move(arrangement.created);
  return result;
}

}  // namespace glass::geometry
