// Step 3 of polygon tessellation (glass/geometry/polygon_tessellation.h): triangulating one face,
// a counter-clockwise outer ring with clockwise holes, by ear clipping.
#pragma once

#include <vector>

#include "glass/geometry/polygon_tessellation.h"

namespace glass::geometry {

// A closed ring of vertices; boundary[k] says whether the edge from vertices[k] to
// vertices[k + 1] (cyclically) is a boundary edge of the region (GLU's edge flag).
struct PolygonRing {
  std::vector<int> vertices;
  std::vector<bool> boundary;
};

// Appends triangles covering `outer` minus `holes` to `out`. Each hole is first joined to the
// outer ring by a bridge to a vertex it can see (the bridge's two edges are not boundary edges),
// then ears are clipped: a convex corner whose triangle holds no other ring vertex. The rings
// may touch themselves at vertices (weakly simple polygons), as faces of a planar graph do.
void triangulateRing(const std::vector<PlanarPoint>& points, const PolygonRing& outer,
                     const std::vector<PolygonRing>& holes, std::vector<TessellatedTriangle>& out);

}  // namespace glass::geometry
