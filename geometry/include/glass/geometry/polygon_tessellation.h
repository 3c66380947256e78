// Tessellating planar polygons with any number of contours, which may cross themselves and each
// other, into triangles covering the region a winding rule selects, or into the loops that bound
// that region. This is the geometry of the GLU 1.3 tessellator (GLU specification, chapter 5),
// without GL: pipeline/src/glu/ projects GLU's 3D vertices onto a plane and calls this.
//
// How it works (polygon_arrangement.cpp, polygon_faces.cpp, polygon_triangulation.cpp):
//  1. Vertices at the same position are merged, and every crossing of two edges becomes a vertex
//     (a CreatedVertex, described as a weighted sum of the vertices it comes from, so that the
//     caller can interpolate its data, as GLU's combine callback does). Edges are split at the
//     vertices that lie on them; the result is a planar graph whose edges carry the number of
//     contour edges running along them, counted with their direction.
//  2. The graph's faces are found by walking its half-edges, each keeping its face on the left;
//     a face's winding number is the outside's (0) plus the directed edge counts crossed to reach
//     it from outside (crossing a contour edge from its right to its left adds 1).
//  3. The faces the winding rule selects are triangulated by ear clipping, their holes joined to
//     their outer boundary by bridges first; or their boundary is collected into loops.
// Every triangle and loop uses only the input vertices and the created ones: no point is moved.
#pragma once

#include <array>
#include <vector>

namespace glass::geometry {

// GLU_TESS_WINDING_*: which winding numbers are inside.
enum class WindingRule { Odd, NonZero, Positive, Negative, AbsGeqTwo };

bool isInsideByWindingRule(WindingRule rule, int winding);

struct PlanarPoint {
  double x = 0.0;
  double y = 0.0;
  bool operator==(const PlanarPoint&) const = default;
};

// A vertex the tessellation adds, numbered after the input vertices (input vertices are numbered
// in the order of the contours and of the points in each). Its position is the weighted sum of
// its sources' positions (approximately, for crossings: the crossing is computed exactly in the
// plane, the weights describe it along each edge). Unused sources are -1 with weight 0. Sources
// may be input vertices or earlier created ones.
struct CreatedVertex {
  PlanarPoint position;
  std::array<int, 4> sources{-1, -1, -1, -1};
  std::array<double, 4> weights{0.0, 0.0, 0.0, 0.0};
  // True where two edges cross: the four sources are the two edges' ends, each edge's pair of
  // weights summing to 1/2 and split by the crossing's relative distance to its ends. False where
  // input vertices at the same position merge: two sources weighing 1/2 each.
  bool isCrossing = false;
};

struct TessellatedTriangle {
  std::array<int, 3> vertices{};  // counter-clockwise
  // boundaryEdge[k]: the edge from vertices[k] to vertices[(k + 1) % 3] separates the region
  // from the outside (GLU's edge flag); false for edges inside the region.
  std::array<bool, 3> boundaryEdge{};
};

struct PolygonTessellation {
  std::vector<CreatedVertex> created;
  std::vector<TessellatedTriangle> triangles;   // filled tessellations
  std::vector<std::vector<int>> boundaryLoops;  // boundary-only tessellations: inside on the left
};

// Tessellates the polygon made of `contours`. With boundaryOnly the loops around the inside
// region are returned instead of triangles.
PolygonTessellation tessellatePolygon(const std::vector<std::vector<PlanarPoint>>& contours,
                                      WindingRule rule, bool boundaryOnly);

}  // namespace glass::geometry
