// Rounding the marked (hard) edges of a polyhedron "made of cubes" with radius R, built from
// rational Bezier patches (study guide, homeworks 4-5 and Figure 2.8; the patches are those of
// section 2.4: rational quadratic arcs and the surfaces swept by them).
//
// What is built, for a radius R > 0:
// - every marked edge becomes a strip that is an exact quarter of a cylinder of radius R: a
//   rational patch of bi-degree (2, 1), the arc (end weights 1, middle weight sqrt(2)/2) swept
//   along the edge. It touches its two faces along lines at distance R from the edge, where its
//   normal is the face's normal, so normals are continuous;
// - every corner where three marked edges meet becomes an eighth of a sphere of radius R: a
//   rational bi-quadratic patch of revolution whose three boundary curves are the ends of the
//   three strips (one side collapses to a pole);
// - where two marked edges meet and the third edge at the corner is sharp, the two strips end on
//   the corner's bisecting plane (a mitre): both end in the same rational quadratic (an ellipse
//   arc, the strip's arc projected along the edge onto that plane), so no further patch is
//   needed;
// - where one marked edge ends at a corner whose other edges are sharp, the strip ends in the
//   plane of the face across it, and that face loses its corner to the same quarter arc;
// - a concave marked edge (the inner edge of an L, where two faces meet at 270 degrees seen from
//   inside) becomes a concave fillet: the same rational quadratic strip, a quarter of a cylinder
//   of radius R whose axis lies outside the solid (each face's plane moved out by R), touching
//   both faces along lines at distance R from the edge and filling the inner corner. Its normals
//   point towards the axis. Where it ends at a corner whose other two edges are sharp (the top of
//   the L's inner upright), the strip ends in the plane of the faces across, and a flat web of
//   that plane fills the corner between the two sharp edges and the strip's end arc;
// - where a concave marked edge ends at a corner whose two other creases are rounded convex
//   edges (an L with all its edges marked, where its inner upright meets the top), the three
//   meet in a piece of a torus: the convex edges' quarter circle swept around the fillet's axis
//   at distance 2 R, from one convex strip's end to the other's. It is the product of two quarter
//   arcs, the major one (radius 2 R in the end face's plane down to R at the fillet's end) and
//   the minor one (radius R), so a rational bi-quadratic patch with weights w_i w_j (w = 1,
//   sqrt(2)/2, 1) is exactly that torus. Its four sides are the fillet's end arc, the two strips'
//   end arcs and an arc of radius 2 R in the end face's plane, which the faces there (split by
//   flat edges along the convex edges' continuations, as a reflex corner of a face must be) lose
//   their corners to. That arc crosses those flat edges at 30 and 60 degrees, so the torus is
//   split there (and in the middle, 45 degrees, as strips are), and so is the fillet along its
//   whole run, so that their shared sides stay equal;
// - where one of those two convex creases is rounded and the other sharp, the torus piece is the
//   same (the rounded crease's quarter circle turned all the way round the fillet's axis, to the
//   sharp crease's line R beyond the corner), and ends there in a flat cap: the piece of the
//   plane normal to the sharp edge between the torus's end arc and that arc's middle control
//   point, the point R along the sharp edge where its crease begins. Beyond it the sharp edge
//   keeps its full corner, so the cap is a step, a crease all round, in the sharp edge's
//   direction (an edge rounding that ends in the middle of a smooth crease has no smooth
//   ending). The end face beside the sharp edge loses its corner to the torus's arc and the
//   cap's top side; the face holding the sharp edge and the fillet keeps its sharp edge from the
//   cap on, and its side along the fillet is shared by the fillet (up to the torus) and the cap;
// - the same corner turned inside out, where a cube stands on a layer's top: a convex rounded
//   edge (the cube's upright) ends between two rounded concave edges (the fillets along its
//   foot), the layer's top split by flat edges along their continuations. The fillets' quarter
//   circle swept around the upright's axis at distance 2 R is again a torus piece with the same
//   net (the upright's end arc, the fillets' end arcs and an arc of radius 2 R in the layer's
//   top), now concave: its normals point towards its tube's centre circle, which lies R above the
//   layer's top. It is split as the fillet's torus is, and the upright along its whole run with
//   it (the sphere corner at its top too, in its halves' 30 degree cuts); where the fillets are
//   split at 30 and 60 degrees because they meet a fillet's torus piece at their other ends, the
//   torus piece is split there along its tube as well;
// - where the cube's upright there is left sharp, the two fillets meet round its foot in a piece
//   of a horn torus: their quarter circle turned a quarter round the upright's line (major radius
//   R), its inner side collapsed to the point R up the upright, where the upright's crease
//   begins; the layer's top loses its corner to the piece's quarter circle of radius R there;
// - every face shrinks by R away from its marked edges; it is a fan of flat patches from its
//   centre to the pieces of its boundary (segments of degree 1, arcs of degree 2).
//
// Every boundary curve two patches share is built once, from the same points in the same order
// of operations, so both patches hold the same control points bit for bit; the adaptive
// tessellator (tessellation.h) then meets them without cracks at any depth.
//
// Texture coordinates continue across the rounding by arc length: each strip and corner patch is
// split in the middle (the strip at 45 degrees, the corner into four) and each half belongs to the
// face it touches; a point at arc length s from that face's line gets the face's texture
// coordinates at distance s * 4 / pi beyond the line, so the quarter arc (length pi R / 2) takes
// exactly the 2 R of texture the sharp edge took, and a texture that runs on across the sharp
// edge runs on across the rounded one. A torus piece's half next to the end face unrolls as a
// strip along its tube does; its half next to the fillet unrolls as the fillet does, then by its
// tube's arc towards the end face: each runs on into the strips' and the fillet's unrolling at
// their shared ends.
//
// Where two rounded convex edges meet and the corner's third edge is sharp, the mitre is the
// exact rounded solid, not an approximation: the solid with both edges rounded is the
// intersection of the two rounded slabs, whose boundaries cross in the bisecting plane. The
// crease along the mitre continues the sharp third edge and fades to nothing at the top, as a
// rolling-ball blend of those two edges alone gives it (a smooth patch there would round the
// third edge too, which is not marked).
//
// What is supported, for R > 0: marked edges between two faces at a right angle, convex or
// concave; corners where a convex marked edge ends have three edges at right angles (a corner of
// a cube) or two marked edges in one straight line with flat edges across (where coplanar faces
// of two cubes meet); a concave marked edge runs straight through such corners or ends where its
// two other creases are convex and at right angles, both sharp (a web), both rounded (a torus
// piece) or one of each (a torus piece and a cap), the end face split by two flat edges along
// their continuations where one of them is rounded; a rounded convex edge ends between two
// rounded concave ones in the same way (a cube standing on a layer's top, every crease there
// rounded, or the upright sharp: a horn piece), running up to a sphere corner, the face across its end or straight on; faces next to a marked
// edge have right angles there; every face is convex. Anything else is refused with a message naming the edge, vertex or face.
// R = 0 gives the sharp object.
#pragma once

#include "glass/geometry/bezier_surface.h"
#include "glass/geometry/tessellation.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace glass::geometry {

// A closed polyhedron with some edges marked for rounding.
struct MarkedPolyhedron {
  struct Face {
    std::vector<std::uint32_t> vertices;  // counter-clockwise seen from outside
    std::vector<glm::dvec2> uvs;          // texture coordinates at each vertex, or empty
    int material = -1;
  };
  std::vector<glm::dvec3> vertices;
  std::vector<Face> faces;
  std::vector<std::array<std::uint32_t, 2>> markedEdges;  // vertex pairs
};

// The unit normal of a face by Newell's method (the sum over its edges, which stays right for a
// concave or slightly warped loop); zero for a face without area.
glm::dvec3 newellNormal(const MarkedPolyhedron& poly, const MarkedPolyhedron::Face& face);

// A polyhedron the rounding cannot handle, or a radius out of range; what() names the edge,
// vertex or face.
class RoundingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How one patch of the rounded surface gets its texture coordinates: the face's chart (an affine
// map from the face's plane to (s, t)), either directly (a flat piece of the face) or after
// unrolling a rounded piece onto the face's plane (see the file comment).
struct RoundedPatchInfo {
  int face = -1;      // the face whose chart and material the patch takes
  bool rounded = false;
  // A concave fillet: its centre line lies outside the solid and its normals point towards it;
  // faceNormal and acrossNormals are then the faces' normals reversed (see below).
  bool concave = false;
  // For rounded pieces: the centre is the point `centre` (sphere) or the line through it along
  // `axis` (cylinder, axis of unit length); faceNormal points from the centre to the face,
  // acrossNormals from the centre towards the other faces of the rounding (one for a strip, two
  // for a sphere piece). For convex pieces these are the faces' outward normals.
  glm::dvec3 centre{0.0};
  glm::dvec3 axis{0.0};
  bool alongAxis = false;
  glm::dvec3 faceNormal{0.0};
  std::vector<glm::dvec3> acrossNormals;
  // Strips mitred at a sharp corner: the strip's line on its face runs from lineStart to lineEnd;
  // at an end with a mitre, mitreStart or mitreEnd is the unit vector from that end into the
  // strip (zero otherwise). There the unrolled point slides along the strip by
  // R sin(angle) - (4 / pi) angle R, so that two mitred strips unroll onto the same diagonal, as
  // the sharp corner's faces do; the slide fades linearly towards the other end.
  glm::dvec3 lineStart{0.0}, lineEnd{0.0};
  glm::dvec3 mitreStart{0.0}, mitreEnd{0.0};
  // A torus piece: its centre is the circle of radius majorRadius around `axis` through `centre`
  // (the fillet's axis, pointing out of the end face), in the plane through `centre` normal to it.
  // Pieces next to the end face have faceNormal == axis; those next to the fillet take the
  // fillet's faceNormal and acrossNormals.
  bool torus = false;
  double majorRadius = 0.0;
  // A cap (a flat piece where a torus piece ends at a sharp crease): the normal of its plane,
  // which is no face's. Zero for every other patch.
  glm::dvec3 capNormal{0.0};
  // A horn piece's half next to a wall (a torus piece of major radius R turned about a sharp
  // upright, see roundMarkedEdges): the direction in the wall's plane, away from the wall across
  // the upright's line, along which the turn about the upright unrolls. Zero for every other patch.
  glm::dvec3 hornBeyond{0.0};
};

// The point of a rounded patch's centre (point, line or circle) nearest p: p lies at distance R
// from it, and the patch's normal at p points away from it (towards it for a concave fillet).
glm::dvec3 roundingCentre(const RoundedPatchInfo& info, const glm::dvec3& p);

// A side of a rounded patch: where it meets a face.
struct PatchSideRef {
  std::size_t patch = 0;
  PatchSide side = PatchSide::UMin;
};

// The outline of a face next to the rounding, counter-clockwise: segments and quarter arcs, each
// with the sides of the rounded patches that run along it (none for a side whose edge is sharp).
struct FaceOutline {
  struct Piece {
    glm::dvec3 start{0.0}, end{0.0};
    std::vector<PatchSideRef> along;
  };
  int face = -1;
  std::vector<Piece> pieces;
  glm::dvec3 normal{0.0};  // the plane's normal where it is not the face's (a cap), else zero
};

struct RoundedSurface {
  double radius = 0.0;
  // The rounded pieces (strips, sphere corners) and each face as a fan of flat patches from its
  // centre to its outline; together a closed surface.
  std::vector<BezierSurface> patches;
  std::vector<RoundedPatchInfo> info;  // one per patch
  std::vector<FaceOutline> outlines;   // the faces next to the rounding
};

// The largest radius the object can be rounded with: half the shortest side of a face next to a
// marked edge (or next to a corner a marked edge ends at). `limit` gets what sets it.
// Infinite when nothing is marked.
double maximumRoundingRadius(const MarkedPolyhedron& polyhedron, std::string* limit = nullptr);

// The patches of the object with its marked edges rounded with `radius` (0: the sharp object).
// Throws RoundingError.
RoundedSurface roundMarkedEdges(const MarkedPolyhedron& polyhedron, double radius);

// Triangles of a rounded surface: positions, unit normals, texture coordinates from the faces'
// charts, and the face each triangle belongs to (for its material). The rounded patches are
// tessellated adaptively (crack-free among themselves); each face is a flat polygon through its
// outline and every vertex those patches put on it, so the faces meet them without cracks too.
struct RoundedMesh {
  TriangleMesh mesh;
  std::vector<int> triangleFaces;
};
RoundedMesh tessellateRounded(const MarkedPolyhedron& polyhedron, const RoundedSurface& surface,
                              const AdaptiveOptions& options);

// The texture coordinates a face gives to a point of its plane: from its vertices' uvs (the affine
// map that fits them best), or, without uvs, a projection along the face's normal with the world's
// y axis (z for horizontal faces) as t.
struct FaceChart {
  glm::dvec3 origin{0.0};
  glm::dvec3 sAxis{1.0, 0.0, 0.0}, tAxis{0.0, 1.0, 0.0};  // s = s0 + dot(p - origin, sAxis)
  glm::dvec2 atOrigin{0.0};
  glm::dvec2 at(const glm::dvec3& p) const;
};
FaceChart faceChart(const MarkedPolyhedron& polyhedron, std::size_t face);

// Point p of a cap (its plane's normal capNormal) turned about the line where the cap's plane
// meets the face of `chart`, onto that face: where the cap takes its texture coordinates.
glm::dvec3 capFoldedOntoFace(const FaceChart& chart, const glm::dvec3& capNormal, const glm::dvec3& p);

// The texture coordinates of point p of a patch with this info (a cap's folded onto its face).
glm::dvec2 roundedTexCoord(const RoundedPatchInfo& info, const FaceChart& chart, double radius, const glm::dvec3& p);

}  // namespace glass::geometry
