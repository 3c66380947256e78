// Is a polyhedron given by its faces a solid whose faces face outwards? Closed (every edge shared
// by exactly two faces), its faces turned alike (the two faces at an edge run along it in opposite
// directions), facing out (a positive volume) and not crossing itself (no two faces cut through
// each other; faces that meet only at common vertices or edges do not). A mesh that fails draws all the same, but lighting and
// back-face culling take the side its faces face for the outside, and the rounding of its edges
// assumes one solid: the scene language warns of each problem it finds in a model
// (docs/scene-format.md, "model").
#pragma once

#include <array>
#include <cstdint>

#include "glass/geometry/edge_rounding.h"

namespace glass::geometry {

struct PolyhedronCheck {
  // Edges (vertex pairs) with one face, with three faces or more, and with two faces running along
  // them in the same direction (one of the two is turned the other way round); the first of each
  // as found, by vertex index.
  int openEdges = 0, nonManifoldEdges = 0, reversedEdges = 0;
  std::array<std::uint32_t, 2> firstOpenEdge{}, firstNonManifoldEdge{}, firstReversedEdge{};
  // The signed volume enclosed (the sum over the faces' triangles of det(a, b, c) / 6): positive
  // when the faces face outwards. Meaningful only for a closed mesh with its faces turned alike.
  double volume = 0.0;
  // Pairs of faces with no vertex in common whose interiors cross along a segment (faces that
  // only touch, or lie in one plane, do not count); the first pair found, by face index.
  int crossingFacePairs = 0;
  std::array<int, 2> firstCrossing{-1, -1};

  bool closed() const { return openEdges == 0 && nonManifoldEdges == 0; }
  bool consistent() const { return closed() && reversedEdges == 0; }
  bool insideOut() const { return consistent() && volume < 0.0; }
};

PolyhedronCheck checkPolyhedron(const MarkedPolyhedron& shape);

}  // namespace glass::geometry
