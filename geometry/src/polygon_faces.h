// Step 2 of polygon tessellation (glass/geometry/polygon_tessellation.h): the faces of the planar
// graph and their winding numbers.
//
// Each graph edge is two half-edges, 2e (from -> to) and 2e + 1 (to -> from); a half-edge's face
// lies on its left. Following next() from a half-edge walks a cycle around its face. A cycle with
// positive area is the outer boundary of a bounded face; every other cycle is the outside of a
// connected piece of the graph, and its left side belongs to the face that piece lies in (found
// by a ray to the left), or to the unbounded outside.
#pragma once

#include <vector>

#include "polygon_arrangement.h"

namespace glass::geometry {

inline constexpr int kOutsideFace = -1;

struct PolygonFaces {
  // Per half-edge.
  std::vector<int> origin;  // the vertex it leaves
  std::vector<int> count;   // directed contour edges along it (the graph edge's count, signed)
  std::vector<int> next;    // the next half-edge around its face
  std::vector<int> cycle;   // the cycle it belongs to
  // Outgoing half-edges of each vertex, counter-clockwise by direction, and each half-edge's
  // place in its origin's list.
  std::vector<std::vector<int>> outgoing;
  std::vector<int> outgoingIndex;

  // Per cycle.
  std::vector<int> cycleStart;    // a half-edge of it
  std::vector<double> cycleArea;  // twice the signed area it encloses
  // The face on the left of the cycle: the cycle's own index when it bounds a face
  // (cycleArea > 0), else the face containing this piece of the graph, or kOutsideFace.
  std::vector<int> face;
  // The winding number of the face a (positive-area) cycle bounds; 0 for the others.
  std::vector<int> winding;

  int twin(int halfEdge) const { return halfEdge ^ 1; }
  int target(int halfEdge) const { return origin[twin(halfEdge)]; }
  int faceOf(int halfEdge) const { return face[cycle[halfEdge]]; }
};

PolygonFaces findFaces(const PolygonArrangement& arrangement);

}  // namespace glass::geometry
