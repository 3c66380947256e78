// Turning Bezier curves into polylines and Bezier patches into triangle meshes, uniformly or
// adaptively.
//
// Adaptive tessellation splits each patch into a quadtree of parameter cells, halving a cell until
// it is flat enough (ObjectSpaceTolerance) or small and flat enough on screen
// (ScreenSpaceTolerance). Neighbouring cells of different sizes never leave cracks: every cell is
// triangulated with all mesh vertices that lie on its sides (the corners of its smaller
// neighbours), as a fan around its centre, so the triangles of the two sides of a shared cell edge
// meet at exactly the same vertices and the mesh is conforming (no T-junctions). Across patches,
// two patches whose boundary curves have the same control points (in the same or the opposite
// order) also get the union of both sides' vertices on that edge, and vertices on a patch boundary
// are computed from the boundary curve in one canonical orientation, so both patches produce the
// same positions bit for bit.
#pragma once

#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/bezier_surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <variant>
#include <vector>

namespace glass::geometry {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;    // unit surface normals (BezierSurface::normal)
  std::vector<glm::dvec2> texCoords;  // the patch parameters (u, v), mapped by a TextureRect
  // Three per triangle, counter-clockwise seen from the side the normals point to.
  std::vector<std::uint32_t> indices;

  std::size_t triangleCount() const { return indices.size() / 3; }
  void append(const TriangleMesh& other);
};

struct Polyline {
  std::vector<glm::dvec3> points;
  std::vector<double> parameters;  // the curve parameter of each point, increasing from 0 to 1
};

// Texture coordinates of a patch: (s, t) = origin + size * (u, v). Several patches of one surface
// (the sixteen patches of a torus) can so share one texture.
struct TextureRect {
  glm::dvec2 origin{0.0, 0.0};
  glm::dvec2 size{1.0, 1.0};
};

// Split until the triangles are within maxDeviation of the surface in object space. For integral
// patches this is a bound: the test is 2 d + |t| / 4 <= maxDeviation, where d is the largest
// distance of a control point p_ij from the bilinear interpolant of the four corners at
// (i/m, j/n), and t = p_00 - p_m0 - p_0n + p_mn the twist of that interpolant. (S - bilinear is the
// Bezier patch with control points p_ij - bilinear(i/m, j/n), so |S - bilinear| <= d; the mesh
// interpolates S and the bilinear interpolant within d at its vertices, and a linear triangle
// differs from the bilinear interpolant by at most |t| / 4.) For rational patches the same test
// runs on the projected control points, with in addition the true surface at the cell's centre and
// edge midpoints compared with the bilinear interpolant; that is an estimate, not a bound.
struct ObjectSpaceTolerance {
  double maxDeviation = 1e-3;
};

// The same flatness test on the control points mapped to the screen by project (object space to
// pixels, e.g. modelview, projection, perspective division and viewport), in pixels; and, when
// maxEdgePixels > 0, split until the projected control net of a cell spans at most maxEdgePixels
// along x and y. A control point behind the eye (project returning a non-finite value) forces a
// split down to the maximum depth.
struct ScreenSpaceTolerance {
  std::function<glm::dvec2(const glm::dvec3&)> project;
  double maxDeviationPixels = 0.5;
  double maxEdgePixels = 0.0;
};

struct AdaptiveOptions {
  std::variant<ObjectSpaceTolerance, ScreenSpaceTolerance> criterion = ObjectSpaceTolerance{};
  int maxDepth = 8;  // at most 2^maxDepth cells along u and along v (clamped to 0..20)
};

// A (segmentsU + 1) x (segmentsV + 1) grid of vertices at u = i / segmentsU, v = j / segmentsV,
// two triangles per grid cell. Triangles whose corners coincide (at collapsed rows) are left out.
TriangleMesh tessellateUniform(const BezierSurface& patch, int segmentsU, int segmentsV,
                               const TextureRect& texture = {});
// Several patches in one mesh. Boundary vertices are evaluated on the canonical boundary curve,
// so patches sharing an edge with the same number of segments on it meet without cracks.
TriangleMesh tessellateUniform(std::span<const BezierSurface> patches, int segmentsU, int segmentsV,
                               std::span<const TextureRect> textures = {});

TriangleMesh tessellateAdaptive(const BezierSurface& patch, const AdaptiveOptions& options,
                                const TextureRect& texture = {});
// Several patches, crack-free across edges whose boundary curves have equal control points.
TriangleMesh tessellateAdaptive(std::span<const BezierSurface> patches, const AdaptiveOptions& options,
                                std::span<const TextureRect> textures = {});

// segments + 1 points at t = i / segments.
Polyline tessellateUniform(const BezierCurve& curve, int segments);
// Recursive halving until the control polygon of a piece is within the tolerance of its chord
// (object space) or of its projected chord (screen space); for integral curves the chord is then
// within the tolerance of the curve.
Polyline tessellateAdaptive(const BezierCurve& curve, const AdaptiveOptions& options);

}  // namespace glass::geometry
