// Clipping in homogeneous clip space (OpenGL 1.5 spec, section 2.12) against the six frustum
// planes -w <= x, y, z <= w and the enabled user clip planes. Attributes of new vertices are
// interpolated linearly in clip space at the cut, as the specification requires.
#pragma once

#include "glass/raster/vertex.h"

namespace glass::raster {

// Enough room for a triangle clipped by 6 frustum planes and 6 user planes.
inline constexpr int kMaxClippedPolygonVertices = 3 + 6 + kMaxUserClipPlanes;

struct ClipSettings {
  unsigned userPlaneMask = 0;  // bit i set: user plane i is enabled
  int varyingCount = 0;        // varyings[0 .. varyingCount) are interpolated at cuts
};

// Clips a convex polygon of n vertices (n <= 3 is the common case; any n up to
// kMaxClippedPolygonVertices - 12 works). Writes the clipped polygon to out, which must hold
// kMaxClippedPolygonVertices + n vertices, and returns its vertex count (0 when nothing remains).
// Vertex order (and so orientation) is preserved.
int clipPolygon(const ClipVertex* in, int n, const ClipSettings& settings, ClipVertex* out);

// Clips a segment in place. Returns false when nothing remains.
bool clipLine(ClipVertex& a, ClipVertex& b, const ClipSettings& settings);

// A point survives when its vertex lies inside every plane.
bool pointInside(const ClipVertex& v, const ClipSettings& settings);

// Bit mask of planes a vertex lies outside of (bits 0-5 frustum, 6-11 user planes), for trivial
// accept (all masks zero) and reject (the AND of the masks non-zero). A vertex with an infinite
// or NaN clip coordinate is outside every enabled plane and has kNotFinite set as well; clipLine
// and clipPolygon then remove the whole primitive.
inline constexpr unsigned kNotFinite = 1u << 31;
unsigned outcode(const ClipVertex& v, const ClipSettings& settings);

// outcode of `count` vertices without user clip planes, their clip coordinates in rows (vertex
// i at x[i], y[i], z[i], w[i]), into codes[i]: the same values, a loop over the vertices without
// branches that the compiler turns into vector code.
void frustumOutcodes(const float* x, const float* y, const float* z, const float* w, int count,
                     unsigned* codes);

}  // namespace glass::raster
