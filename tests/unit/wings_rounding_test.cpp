// Rounding marked edges with rational Bezier patches: exact seams, continuous normals and texture
// coordinates, the strips on their cylinders, crack-free meshes at every depth, and the refusals.
#include <doctest/doctest.h>

#include "glass/geometry/edge_rounding.h"
#include "glass/scene/wings_file.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

using namespace glass::geometry;

namespace {

MarkedPolyhedron readShape(const std::string &name) {
  const auto file = glass::scene::readWingsFile(std::string(GLASS_SOURCE_DIR) + "/tests/unit/data/wings/" + name);
  REQUIRE(file.objects.size() == 1);
  return file.objects[0].shape;
}

constexpr PatchSide kSides[] = {PatchSide::UMin, PatchSide::UMax, PatchSide::VMin, PatchSide::VMax};
constexpr double kSamples[] = {0.0, 0.125, 0.25, 0.5, 0.75, 0.875, 1.0};

// (u, v) of the point at parameter t along a side.
glm::dvec2 onSide(PatchSide side, double t) {
  switch (side) {
  case PatchSide::UMin: return {0.0, t};
  case PatchSide::UMax: return {1.0, t};
  case PatchSide::VMin: return {t, 0.0};
  case PatchSide::VMax: return {t, 1.0};
  }
  return {};
}

struct SideMatch {
  std::size_t patch;
  PatchSide side;
  bool reversed;
};

bool collapsed(const BezierSurface &patch, PatchSide side) {
  const glm::dvec2 a = onSide(side, 0.0), b = onSide(side, 0.5), c = onSide(side, 1.0);
  const glm::dvec3 pa = patch.evaluate(a.x, a.y), pb = patch.evaluate(b.x, b.y), pc = patch.evaluate(c.x, c.y);
  return glm::length(pa - pb) < 1e-12 && glm::length(pb - pc) < 1e-12;
}

// The points of every patch side at kSamples, evaluated once per surface: the seam checks
// compare each side with every other, which for an object of a thousand faces is millions of
// comparisons.
class SideSamples {
public:
  explicit SideSamples(const RoundedSurface &s) : points_(s.patches.size() * 4) {
    for (std::size_t p = 0; p < s.patches.size(); ++p)
      for (int k = 0; k < 4; ++k)
        for (std::size_t i = 0; i < std::size(kSamples); ++i) {
          const glm::dvec2 a = onSide(kSides[k], kSamples[i]);
          points_[p * 4 + static_cast<std::size_t>(k)][i] = s.patches[p].evaluate(a.x, a.y);
        }
  }
  const std::array<glm::dvec3, std::size(kSamples)> &at(std::size_t patch, PatchSide side) const {
    return points_[patch * 4 + static_cast<std::size_t>(side)];  // kSides is in PatchSide's order
  }
  std::size_t patchCount() const { return points_.size() / 4; }

private:
  std::vector<std::array<glm::dvec3, std::size(kSamples)>> points_;
};

// The other patch sides whose points equal this side's to `tolerance`, in either direction
// (kSamples is symmetric: the sample at 1 - t is the one at the mirrored index).
std::vector<SideMatch> neighboursOf(const SideSamples &samples, std::size_t p, PatchSide side, double tolerance) {
  std::vector<SideMatch> found;
  const auto &mine = samples.at(p, side);
  const std::size_t n = mine.size();
  for (std::size_t q = 0; q < samples.patchCount(); ++q) {
    for (PatchSide other : kSides) {
      if (q == p && other == side) continue;
      const auto &theirs = samples.at(q, other);
      for (bool reversed : {false, true}) {
        bool all = true;
        for (std::size_t i = 0; i < n && all; ++i)
          all = glm::length(mine[i] - theirs[reversed ? n - 1 - i : i]) <= tolerance;
        if (all) found.push_back({q, other, reversed});
      }
    }
  }
  return found;
}

bool onPolygonFaces(const MarkedPolyhedron &poly, const RoundedSurface &s, const glm::dvec3 &p) {
  std::vector<bool> patched(poly.faces.size(), false);
  for (const auto &info : s.info)
    if (!info.rounded) patched[static_cast<std::size_t>(info.face)] = true;
  for (std::size_t f = 0; f < poly.faces.size(); ++f) {
    if (patched[f]) continue;
    const auto &vs = poly.faces[f].vertices;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const glm::dvec3 a = poly.vertices[vs[i]], b = poly.vertices[vs[(i + 1) % vs.size()]];
      const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
      if (glm::length(a + t * (b - a) - p) < 1e-12) return true;
    }
  }
  return false;
}

// The unit normal of a face of the polyhedron (its first three corners; the test objects' faces
// are rectangles).
glm::dvec3 faceNormal(const MarkedPolyhedron &poly, int face) {
  const auto &vs = poly.faces[static_cast<std::size_t>(face)].vertices;
  const glm::dvec3 a = poly.vertices[vs[0]], b = poly.vertices[vs[1]], c = poly.vertices[vs[2]];
  return glm::normalize(glm::cross(b - a, c - b));
}

// The normal of a patch at (u, v). A flat piece of a face lies in the face's plane (checked) and
// takes its normal: the derivatives' cross product has no direction at the cusps of a concave
// fillet's web, where the arc runs into the sharp edge at a zero angle.
glm::dvec3 patchNormal(const MarkedPolyhedron &poly, const RoundedSurface &s, std::size_t p, double u, double v) {
  if (s.info[p].rounded) return s.patches[p].normal(u, v);
  if (s.info[p].capNormal != glm::dvec3(0.0)) {
    // A cap lies in its own plane, through its first control point.
    const glm::dvec4 first = s.patches[p].homogeneousControlPoint(0, 0);
    CHECK(std::abs(glm::dot(s.patches[p].evaluate(u, v) - glm::dvec3(first) / first.w, s.info[p].capNormal)) < 1e-12);
    return s.info[p].capNormal;
  }
  const glm::dvec3 n = faceNormal(poly, s.info[p].face);
  const glm::dvec3 corner = poly.vertices[poly.faces[static_cast<std::size_t>(s.info[p].face)].vertices[0]];
  CHECK(std::abs(glm::dot(s.patches[p].evaluate(u, v) - corner, n)) < 1e-12);
  return n;
}

// Every side of every patch either collapses to a point, lies on a face drawn as a polygon, or
// is shared with exactly one other patch: the same curve to 1e-12, the same normals to 1e-9 (but
// for the creases of edges left sharp and around a cap), and (for two pieces of one face's chart
// meeting smoothly) the same texture coordinates to 1e-9.
void checkSeams(const MarkedPolyhedron &poly, const RoundedSurface &s) {
  std::map<int, FaceChart> charts;
  for (std::size_t f = 0; f < poly.faces.size(); ++f) charts[static_cast<int>(f)] = faceChart(poly, f);
  int shared = 0;
  const SideSamples samples(s);
  for (std::size_t p = 0; p < s.patches.size(); ++p) {
    for (PatchSide side : kSides) {
      if (collapsed(s.patches[p], side)) continue;
      const auto found = neighboursOf(samples, p, side, 1e-12);
      if (found.empty()) {
        bool onPolygon = true;
        for (double t : kSamples) {
          const glm::dvec2 a = onSide(side, t);
          onPolygon = onPolygon && onPolygonFaces(poly, s, s.patches[p].evaluate(a.x, a.y));
        }
        CAPTURE(p);
        CAPTURE(static_cast<int>(side));
        if (!onPolygon) {
          const glm::dvec2 a = onSide(side, 0.0), b = onSide(side, 1.0);
          const glm::dvec3 pa = s.patches[p].evaluate(a.x, a.y), pb = s.patches[p].evaluate(b.x, b.y);
          MESSAGE("unmatched side from " << pa.x << " " << pa.y << " " << pa.z << " to " << pb.x << " " << pb.y << " " << pb.z);
        }
        CHECK(onPolygon);
        continue;
      }
      CAPTURE(p);
      CAPTURE(static_cast<int>(side));
      if (found.size() != 1) {
        for (const auto &f : found) MESSAGE("matches patch " << f.patch << " side " << static_cast<int>(f.side) << (f.reversed ? " reversed" : ""));
        const glm::dvec2 a = onSide(side, 0.0), b = onSide(side, 1.0);
        const glm::dvec3 pa = s.patches[p].evaluate(a.x, a.y), pb = s.patches[p].evaluate(b.x, b.y);
        MESSAGE("from " << pa.x << " " << pa.y << " " << pa.z << " to " << pb.x << " " << pb.y << " " << pb.z);
      }
      REQUIRE(found.size() == 1);
      ++shared;
      const SideMatch &m = found[0];
      // Edges left sharp stay creases: two faces along a sharp edge, a strip ending on a sharp
      // face (along a quarter arc), two strips mitred at a sharp corner.
      const RoundedPatchInfo &a = s.info[p], &b = s.info[m.patch];
      const glm::dvec2 u0 = onSide(side, 0.0), u1 = onSide(side, 1.0), uh = onSide(side, 0.5);
      const glm::dvec3 p0 = s.patches[p].evaluate(u0.x, u0.y), p1 = s.patches[p].evaluate(u1.x, u1.y);
      const glm::dvec3 ph = s.patches[p].evaluate(uh.x, uh.y);
      const bool curved = glm::length(ph - (p0 + p1) / 2.0) > 1e-9;
      const bool mitre = a.alongAxis && b.alongAxis && glm::length(glm::cross(a.axis, b.axis)) > 1e-9;
      // (A torus piece meets its end face tangentially, along a curve.)
      const bool stripEnd = a.rounded != b.rounded && curved && !a.torus && !b.torus;
      const bool sharpEdge = !a.rounded && !b.rounded && a.face != b.face;
      // A cap stands at a right angle to everything around it (but its other half).
      const bool cap = (a.capNormal != glm::dvec3(0.0)) != (b.capNormal != glm::dvec3(0.0));
      for (double t : kSamples) {
        const glm::dvec2 ua = onSide(side, t), ub = onSide(m.side, m.reversed ? 1.0 - t : t);
        const glm::dvec3 pa = s.patches[p].evaluate(ua.x, ua.y), pb = s.patches[m.patch].evaluate(ub.x, ub.y);
        const glm::dvec3 na = patchNormal(poly, s, p, ua.x, ua.y), nb = patchNormal(poly, s, m.patch, ub.x, ub.y);
        // A horn piece's point on its sharp upright is a cusp (see checkRadius): no one normal.
        const auto onHornAxis = [&](const RoundedPatchInfo &info) {
          const glm::dvec3 offset = pa - info.centre;
          return info.torus && glm::length(offset - info.axis * glm::dot(offset, info.axis)) < 1e-12;
        };
        if (onHornAxis(a) || onHornAxis(b)) continue;
        // Cubes' faces meet at right angles, or are coplanar (a flat edge).
        if (stripEnd || cap) CHECK(std::abs(glm::dot(na, nb)) < 1e-9);
        else if (sharpEdge) CHECK((std::abs(glm::dot(na, nb)) < 1e-9 || glm::length(na - nb) < 1e-9));
        else if (!mitre) CHECK(glm::length(na - nb) < 1e-9);
        if (a.face == b.face && !cap) {
          const FaceChart &chart = charts[a.face];
          const glm::dvec2 ta = roundedTexCoord(a, chart, s.radius, pa);
          const glm::dvec2 tb = roundedTexCoord(b, chart, s.radius, pb);
          CHECK(glm::length(ta - tb) < 1e-9);
        }
      }
    }
  }
  CHECK(shared > 0);
}

// Every point of a strip lies at distance R from its axis, of a sphere piece at R from its centre,
// of a torus piece at R from its circle of centres.
void checkRadius(const RoundedSurface &s) {
  for (std::size_t p = 0; p < s.patches.size(); ++p) {
    const RoundedPatchInfo &info = s.info[p];
    if (!info.rounded) continue;
    for (double u : kSamples)
      for (double v : kSamples) {
        const glm::dvec3 point = s.patches[p].evaluate(u, v);
        const glm::dvec3 centre = roundingCentre(info, point);
        CHECK(std::abs(glm::length(point - centre) - s.radius) < 1e-9);
        // The normal points straight away from the centre (towards it for a concave fillet), but
        // at a horn piece's point on its sharp upright (on its axis), where every direction
        // around the axis is one (a cusp, where the upright's crease begins).
        const glm::dvec3 fromCentre = point - info.centre;
        if (info.torus && glm::length(fromCentre - info.axis * glm::dot(fromCentre, info.axis)) < 1e-12) continue;
        const double outward = info.concave ? -1.0 : 1.0;
        CHECK(glm::length(s.patches[p].normal(u, v) - outward * (point - centre) / s.radius) < 1e-9);
      }
  }
}

// Every triangle edge of the mesh is met by exactly one triangle edge running the other way, with
// endpoints equal bit for bit: no cracks and no T-junctions. Returns the number of triangles.
std::size_t checkWatertight(const RoundedMesh &rounded) {
  using Point = std::tuple<double, double, double>;
  auto key = [&](std::uint32_t i) {
    const glm::dvec3 &p = rounded.mesh.positions[i];
    return Point{p.x, p.y, p.z};
  };
  std::map<std::pair<Point, Point>, int> edges;
  const auto &idx = rounded.mesh.indices;
  for (std::size_t t = 0; t < idx.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++edges[{key(idx[t + k]), key(idx[t + (k + 1) % 3])}];
  int unmatched = 0;
  for (const auto &[edge, count] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (count != 1 || back == edges.end() || back->second != 1) {
      if (++unmatched <= 8) {
        const auto &[a, b] = edge;
        MESSAGE("unmatched edge (" << std::get<0>(a) << ", " << std::get<1>(a) << ", " << std::get<2>(a) << ") to ("
                                   << std::get<0>(b) << ", " << std::get<1>(b) << ", " << std::get<2>(b) << ")");
      }
    }
  }
  CHECK(unmatched == 0);
  return idx.size() / 3;
}

// The volume a closed mesh holds (the divergence theorem over its triangles).
double meshVolume(const RoundedMesh &mesh) {
  double sum = 0.0;
  const auto &idx = mesh.mesh.indices;
  for (std::size_t t = 0; t < idx.size(); t += 3) {
    const glm::dvec3 &a = mesh.mesh.positions[idx[t]], &b = mesh.mesh.positions[idx[t + 1]], &c = mesh.mesh.positions[idx[t + 2]];
    sum += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return sum;
}

} // namespace

const char *const kRoundable[] = {"cube_all_hard.wings", "cube_top_ring.wings", "cube_one_edge.wings",   "block.wings",
                                  "l_uprights.wings",    "l_tall_uprights.wings", "l_block.wings", "concave_l.wings",
                                  "concave_l_one_sharp.wings", "slab_corner_cube.wings", "slab_middle_cube.wings",
                                  "slab_corner_cube_mixed.wings", "l_arm_cube.wings", "slab_tower.wings",
                                  "slab_middle_cube_sharp_uprights.wings"};

TEST_CASE("Rounding: every seam is exact, with continuous normals and texture coordinates") {
  for (std::string name : kRoundable) {
    // The largest radius, but for l_block, where it leaves nothing of the faces one cube wide
    // between two rounded uprights (their patches collapse to lines on top of each other).
    for (double radius : {0.05, 0.2, name == "l_block.wings" ? 0.3 : 0.375}) {
      CAPTURE(name);
      CAPTURE(radius);
      const MarkedPolyhedron poly = readShape(name);
      const RoundedSurface s = roundMarkedEdges(poly, radius);
      CHECK(s.radius == radius);
      checkSeams(poly, s);
      checkRadius(s);
    }
  }
}

namespace {

// The rounded surface tessellated at depths 0 to 6: closed each time, with no fewer triangles
// at each depth than at the one before, and unit normals.
void checkClosedAtEveryDepth(const MarkedPolyhedron &poly, const RoundedSurface &s) {
  std::size_t previous = 0;
  for (int depth = 0; depth <= 6; ++depth) {
    CAPTURE(depth);
    AdaptiveOptions options;
    options.criterion = ObjectSpaceTolerance{1e-6};
    options.maxDepth = depth;
    const RoundedMesh mesh = tessellateRounded(poly, s, options);
    const std::size_t triangles = checkWatertight(mesh);
    CHECK(triangles >= previous);
    previous = triangles;
    for (const glm::dvec3 &n : mesh.mesh.normals) CHECK(std::abs(glm::length(n) - 1.0) < 1e-9);
  }
}

} // namespace

TEST_CASE("Rounding: closed meshes without cracks at every tessellation depth") {
  for (std::string name : kRoundable) {
    CAPTURE(name);
    const MarkedPolyhedron poly = readShape(name);
    checkClosedAtEveryDepth(poly, roundMarkedEdges(poly, 0.25));
  }
}

TEST_CASE("Rounding: the L at its largest radius, where faces one cube wide are used up, is closed") {
  const MarkedPolyhedron l = readShape("l_block.wings");
  REQUIRE(maximumRoundingRadius(l) == 0.375);
  const RoundedSurface s = roundMarkedEdges(l, 0.375);
  checkRadius(s);
  for (int depth : {0, 3, 5}) {
    CAPTURE(depth);
    AdaptiveOptions options;
    options.criterion = ObjectSpaceTolerance{1e-6};
    options.maxDepth = depth;
    CHECK(checkWatertight(tessellateRounded(l, s, options)) > 0);
  }
}

TEST_CASE("Rounding: the Ls at R = 0.5, where faces one cube wide are used up, are closed at every depth") {
  // Every side face of concave_l.wings is one cube wide: at R = 0.5 the strips along its two
  // rims meet with nothing between them; with one rim edge sharp, the cap's sides meet the
  // strips of the edges beyond the used-up faces directly.
  for (std::string name : {"concave_l.wings", "concave_l_one_sharp.wings"}) {
    const MarkedPolyhedron l = readShape(name);
    REQUIRE(maximumRoundingRadius(l) == 0.5);
    CAPTURE(name);
    const RoundedSurface s = roundMarkedEdges(l, 0.5);
    checkRadius(s);
    checkClosedAtEveryDepth(l, s);
  }
}

TEST_CASE("Rounding: the corner kinds, and R = 0 gives the sharp object") {
  auto count = [](const RoundedSurface &s, bool rounded) {
    std::size_t n = 0;
    for (const auto &info : s.info) n += info.rounded == rounded ? 1 : 0;
    return n;
  };
  const MarkedPolyhedron cube = readShape("cube_all_hard.wings");
  // 12 strips of two halves, 8 sphere corners of four pieces.
  CHECK(count(roundMarkedEdges(cube, 0.1), true) == 12 * 2 + 8 * 4);
  // The top ring and one upright: 5 strips, one sphere corner; the other top corners are mitres
  // and the upright's foot is a corner of the front and left faces cut by a quarter arc.
  const MarkedPolyhedron ring = readShape("cube_top_ring.wings");
  CHECK(count(roundMarkedEdges(ring, 0.1), true) == 5 * 2 + 4);
  const RoundedSurface sharp = roundMarkedEdges(cube, 0.0);
  CHECK(sharp.patches.empty());
  const RoundedMesh mesh = tessellateRounded(cube, sharp, {});
  CHECK(mesh.mesh.triangleCount() == 12);
  checkWatertight(mesh);
}

TEST_CASE("Rounding: texture coordinates run on through a strip by arc length") {
  // The front (z = 1) and top (y = 1) faces of a unit cube, charted so that the texture runs on
  // across their edge: t = y on the front, t = 2 - z on top.
  MarkedPolyhedron cube = readShape("cube_top_ring.wings");
  for (auto &face : cube.faces) {
    const glm::dvec3 a = cube.vertices[face.vertices[0]], b = cube.vertices[face.vertices[1]], c = cube.vertices[face.vertices[2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    face.uvs.clear();
    for (std::uint32_t v : face.vertices) {
      const glm::dvec3 p = cube.vertices[v];
      if (n.z > 0.5) face.uvs.emplace_back(p.x, p.y);
      else if (n.y > 0.5) face.uvs.emplace_back(p.x, 2.0 - p.z);
    }
  }
  const double radius = 0.2;
  const RoundedSurface s = roundMarkedEdges(cube, radius);
  bool found = false;
  for (std::size_t p = 0; p < s.patches.size(); ++p) {
    const RoundedPatchInfo &info = s.info[p];
    if (!info.alongAxis || info.axis.y != 0.0 || info.axis.z != 0.0) continue;
    if (glm::length(info.faceNormal - glm::dvec3(0, 0, 1)) > 1e-12 && glm::length(info.faceNormal - glm::dvec3(0, 1, 0)) > 1e-12) continue;
    // The strip along the top front edge, whose axis runs through y = z = 1 - R.
    if (std::abs(info.centre.y - (1.0 - radius)) > 1e-12 || std::abs(info.centre.z - (1.0 - radius)) > 1e-12) continue;
    const FaceChart chart = faceChart(cube, static_cast<std::size_t>(info.face));
    // The strip along the top front edge: points at angle a from the front face.
    const glm::dvec3 centre(0.5, 1.0 - radius, 1.0 - radius);
    for (double degrees : {0.0, 22.5, 45.0, 67.5, 90.0}) {
      const double a = degrees * std::numbers::pi / 180.0;
      const glm::dvec3 point = centre + radius * glm::dvec3(0.0, std::sin(a), std::cos(a));
      const bool nearFront = info.faceNormal.z > 0.5;
      if ((nearFront && degrees > 45.0) || (!nearFront && degrees < 45.0)) continue;
      const glm::dvec2 st = roundedTexCoord(info, chart, radius, point);
      // From t = 1 - R at the front face to 1 + R on top, in proportion to the angle.
      CHECK(st.y == doctest::Approx(1.0 - radius + 2.0 * radius * degrees / 90.0).epsilon(1e-12));
      CHECK(st.x == doctest::Approx(0.5).epsilon(1e-12));
      found = true;
    }
  }
  CHECK(found);
}

TEST_CASE("Rounding: radius limits and unsupported objects are refused with a reason") {
  const MarkedPolyhedron cube = readShape("cube_all_hard.wings");
  std::string limit;
  CHECK(maximumRoundingRadius(cube, &limit) == 0.5);
  CHECK(limit.find("half the side") != std::string::npos);
  CHECK_NOTHROW(roundMarkedEdges(cube, 0.5));
  CHECK_THROWS_WITH_AS(roundMarkedEdges(cube, 0.6), doctest::Contains("radius 0.6 is too large: the largest is 0.5"),
                       RoundingError);
  CHECK_THROWS_AS(roundMarkedEdges(cube, -1.0), RoundingError);
  const MarkedPolyhedron block = readShape("block.wings");
  CHECK(maximumRoundingRadius(block) == 0.375);
  // Two layers of cubes: the upper cube's uprights end on the lower layer's top, between two
  // concave edges, a corner the rounding has no patch for; the message names the vertex.
  const MarkedPolyhedron steps = readShape("two_layers.wings");
  CHECK_NOTHROW(roundMarkedEdges(steps, 0.0));
  try {
    roundMarkedEdges(steps, 0.1);
    FAIL("two layers were rounded");
  } catch (const RoundingError &error) {
    CHECK(std::string(error.what()).find("vertex ") == 0);
    CHECK(std::string(error.what()).find("creases meet there: concave rounded edge") != std::string::npos);
  }
  // The Wings3D file's object has slanted edges.
  const MarkedPolyhedron axes = readShape("wings3d_axes.wings");
  CHECK_NOTHROW(roundMarkedEdges(axes, 0.0));
  CHECK_THROWS_AS(roundMarkedEdges(axes, 0.01), RoundingError);
}

TEST_CASE("Rounding: a cube saved by Wings3D itself, each face cut 14 x 14, its twelve edges hard") {
  // wings3d_material_box.wings (Wings3D's icons/orig/outliner-material-box.wings): the cube
  // [-1, 1]^3, each face cut into 14 x 14 squares, the 168 edges along the cube's edges marked
  // hard. The largest radius is half a square's side: a rounded strip may not pass the next cut.
  const MarkedPolyhedron box = readShape("wings3d_material_box.wings");
  CHECK(box.vertices.size() == 1178);
  CHECK(box.faces.size() == 1176);
  std::string limit;
  const double largest = maximumRoundingRadius(box, &limit);
  CHECK(largest == doctest::Approx(1.0 / 14.0).epsilon(1e-6));
  CHECK(limit.find("half the side") != std::string::npos);
  CHECK_THROWS_AS(roundMarkedEdges(box, 0.1), RoundingError);
  for (double radius : {0.03, largest}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(box, radius);
    checkSeams(box, s);
    checkRadius(s);
    // Closed, and holding the rounded cube's volume: the cube less a strip along each edge
    // (R^2 (1 - pi/4) times its straight length) and a corner piece at each corner
    // (R^3 (1 - pi/6)). The tessellation's chords lie inside the arcs, within its tolerance
    // (1e-4: about 2e-4 of volume over the rounded area of 2.5).
    AdaptiveOptions options;
    options.criterion = ObjectSpaceTolerance{1e-4};
    const RoundedMesh mesh = tessellateRounded(box, s, options);
    checkWatertight(mesh);
    const double pi = std::numbers::pi;
    const double expected = 8.0 - 12.0 * (2.0 - 2.0 * radius) * radius * radius * (1.0 - pi / 4.0) -
                            8.0 * radius * radius * radius * (1.0 - pi / 6.0);
    const double volume = meshVolume(mesh);
    CHECK(volume == doctest::Approx(expected).epsilon(1e-4));
    CHECK(volume <= expected);
  }
}

TEST_CASE("Rounding: a concave edge becomes a fillet outside the faces, ending in flat webs") {
  // The L of unit cubes (x, z in [0, 2], y in [0, 1]) with its uprights marked: the inner one, at
  // x = z = 1, is concave between the faces z = 1 (x in [1, 2], normal +z) and x = 1 (z in
  // [1, 2], normal +x).
  const MarkedPolyhedron l = readShape("l_uprights.wings");
  for (double radius : {0.05, 0.2, 0.5}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(l, radius);
    int fillets = 0, webs = 0;
    for (std::size_t p = 0; p < s.patches.size(); ++p) {
      const RoundedPatchInfo &info = s.info[p];
      const glm::dvec3 middle = s.patches[p].evaluate(0.5, 0.5);
      const bool web = !info.rounded && middle.x > 1.0 && middle.z > 1.0 && middle.x < 1.0 + radius && middle.z < 1.0 + radius;
      for (double u : kSamples)
        for (double v : kSamples) {
          const glm::dvec3 point = s.patches[p].evaluate(u, v);
          const double x = point.x - 1.0, z = point.z - 1.0;
          if (info.concave) {
            // At distance R from both faces' planes moved out by R (the axis x = z = 1 + R), and
            // in the inner corner, outside both faces: filling it.
            CHECK(std::hypot(x - radius, z - radius) == doctest::Approx(radius).epsilon(1e-12));
            CHECK(x >= -1e-15);
            CHECK(z >= -1e-15);
            CHECK(x <= radius + 1e-15);
            CHECK(z <= radius + 1e-15);
            CHECK(info.centre.x == doctest::Approx(1.0 + radius).epsilon(1e-15));
            CHECK(info.centre.z == doctest::Approx(1.0 + radius).epsilon(1e-15));
            // Its normals point out of the solid, into the corner's opening.
            const glm::dvec3 n = s.patches[p].normal(u, v);
            CHECK(n.x + n.z > 0.0);
          } else if (web) {
            // A web: in the top or bottom plane, between the two sharp edges and the fillet's arc.
            CHECK((point.y == 0.0 || point.y == 1.0));
            CHECK(std::hypot(x - radius, z - radius) >= radius * (1.0 - 1e-12));
            CHECK(x <= radius + 1e-15);
            CHECK(z <= radius + 1e-15);
          }
        }
      if (info.concave) ++fillets;
      if (web) ++webs;
    }
    // The fillet's two halves; a web of two halves at each end.
    CHECK(fillets == 2);
    CHECK(webs == 4);
  }
  // The fillet at its touching lines: its normal is the face's, and it is tangent to the face.
  const RoundedSurface s = roundMarkedEdges(l, 0.25);
  for (std::size_t p = 0; p < s.patches.size(); ++p) {
    if (!s.info[p].concave) continue;
    for (double v : kSamples) {
      const glm::dvec3 touching[] = {s.patches[p].evaluate(0.0, v), s.patches[p].evaluate(1.0, v)};
      const glm::dvec3 normals[] = {s.patches[p].normal(0.0, v), s.patches[p].normal(1.0, v)};
      int onFace = 0;
      for (int k = 0; k < 2; ++k) {
        if (std::abs(touching[k].z - 1.0) < 1e-15 && std::abs(touching[k].x - 1.25) < 1e-15) {
          CHECK(glm::length(normals[k] - glm::dvec3(0.0, 0.0, 1.0)) < 1e-12);
          ++onFace;
        }
        if (std::abs(touching[k].x - 1.0) < 1e-15 && std::abs(touching[k].z - 1.25) < 1e-15) {
          CHECK(glm::length(normals[k] - glm::dvec3(1.0, 0.0, 0.0)) < 1e-12);
          ++onFace;
        }
      }
      CHECK(onFace == 1);
    }
  }
  // The rounded mesh holds more volume than the sharp L: the fillet fills (1 - pi / 4) R^2 of
  // the corner over the height 1, and each convex upright takes as much away.
  auto volume = [&](double radius) {
    return meshVolume(tessellateRounded(l, roundMarkedEdges(l, radius), {ObjectSpaceTolerance{1e-7}, 8}));
  };
  const double corner = (1.0 - std::numbers::pi / 4.0) * 0.25 * 0.25;
  // Five convex uprights (at x, z = (0, 0), (2, 0), (2, 1), (1, 2), (0, 2)) and one concave.
  CHECK(volume(0.25) == doctest::Approx(3.0 - 5.0 * corner + corner).epsilon(1e-6));
  CHECK(volume(0.0) == doctest::Approx(3.0).epsilon(1e-12));
}

namespace {


// Integrals over the depth d in [0, R] below a face of the inset delta(d) = R - sqrt(R^2 - (R - d)^2)
// by which a rounded edge along that face moves the solid's outline in: of delta and of delta^2.
double insetIntegral(double r) { return (1.0 - std::numbers::pi / 4.0) * r * r; }
double insetSquaredIntegral(double r) { return (5.0 / 3.0 - std::numbers::pi / 2.0) * r * r * r; }

} // namespace

TEST_CASE("Rounding: where a concave edge meets rounded convex ones, a torus piece joins them") {
  // The L of unit cubes (cells (0, 0), (1, 0), (0, 1) in x, y; z in [0, 1]) with every edge
  // marked. Its concave edge runs along z at x = y = 1; at z = 0 and z = 1 it meets the rounded
  // edges of the end faces. The torus piece there turns around the fillet's axis x = y = 1 + R, its
  // tube (radius R) centred on the circle of radius 2 R at z = 1 - R (or R).
  const MarkedPolyhedron l = readShape("concave_l.wings");
  for (double radius : {0.05, 0.25, 0.5}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(l, radius);
    int pieces = 0, nearEndFace = 0;
    for (std::size_t p = 0; p < s.patches.size(); ++p) {
      if (!s.info[p].torus) continue;
      ++pieces;
      const glm::dvec3 middle = s.patches[p].evaluate(0.5, 0.5);
      const double tubeHeight = middle.z > 0.5 ? 1.0 - radius : radius;
      const double outward = middle.z > 0.5 ? 1.0 : -1.0;
      bool touchesEndFace = false;
      for (double u : kSamples)
        for (double v : kSamples) {
          const glm::dvec3 point = s.patches[p].evaluate(u, v);
          const double fromAxis = std::hypot(point.x - (1.0 + radius), point.y - (1.0 + radius));
          CHECK(std::hypot(fromAxis - 2.0 * radius, point.z - tubeHeight) == doctest::Approx(radius).epsilon(1e-12));
          // Between the fillet (R from the axis) and the end face (at most 2 R), in the quarter
          // between the two strips' ends (the planes x = 1 + R and y = 1 + R), on the solid's side
          // of the tube's centre height.
          CHECK(fromAxis >= radius * (1.0 - 1e-12));
          CHECK(fromAxis <= 2.0 * radius * (1.0 + 1e-12));
          CHECK(point.x <= 1.0 + radius + 1e-12);
          CHECK(point.y <= 1.0 + radius + 1e-12);
          CHECK(outward * (point.z - tubeHeight) >= -1e-12);
          // On the end face's plane the normal is the face's; on the fillet's end it points to the
          // axis, as the fillet's does.
          const glm::dvec3 n = s.patches[p].normal(u, v);
          if (std::abs(point.z - (outward > 0.0 ? 1.0 : 0.0)) < 1e-12) {
            CHECK(glm::length(n - glm::dvec3(0.0, 0.0, outward)) < 1e-9);
            CHECK(fromAxis == doctest::Approx(2.0 * radius).epsilon(1e-12));
            touchesEndFace = true;
          }
          if (std::abs(fromAxis - radius) < 1e-12) {
            const glm::dvec3 toAxis = glm::normalize(glm::dvec3(1.0 + radius - point.x, 1.0 + radius - point.y, 0.0));
            CHECK(glm::length(n - toAxis) < 1e-9);
          }
        }
      if (touchesEndFace) ++nearEndFace;
    }
    // Two corners, each cut at 30, 45 and 60 degrees around the axis and in the middle of the tube.
    CHECK(pieces == 2 * 8);
    CHECK(nearEndFace == 2 * 4);
  }
  // The rounded L is the L whose outline in x, y (rounded at its five convex corners and its
  // concave one) moves in by delta(d) at depth d below the end faces; by Steiner's formula for
  // inner parallel sets its area there is A - P delta + pi delta^2.
  for (double radius : {0.1, 0.25}) {
    CAPTURE(radius);
    const double corner = 1.0 - std::numbers::pi / 4.0;
    const double area = 3.0 - 5.0 * corner * radius * radius + corner * radius * radius;
    const double perimeter = 8.0 + 6.0 * (std::numbers::pi / 2.0 - 2.0) * radius;
    const double expected = area - 2.0 * perimeter * insetIntegral(radius) + 2.0 * std::numbers::pi * insetSquaredIntegral(radius);
    // Cells of at most 1/64 of a patch: the chords move the volume by a few 1e-6 of it.
    const RoundedMesh mesh = tessellateRounded(l, roundMarkedEdges(l, radius), {ObjectSpaceTolerance{1e-7}, 6});
    checkWatertight(mesh);
    CHECK(meshVolume(mesh) == doctest::Approx(expected).epsilon(2e-5));
  }
}

TEST_CASE("Rounding: two rounded edges meet in a mitre, the rounded solid's own crease") {
  // A unit cube with its top ring and the upright at x = z = 0 marked: at the three other top
  // corners two rounded edges meet and the upright below is sharp. The solid with both edges
  // rounded is the intersection of the two rounded slabs: their cylinders cross in the corner's
  // bisecting plane, where the strips end.
  const MarkedPolyhedron cube = readShape("cube_top_ring.wings");
  for (double radius : {0.1, 0.25, 0.4}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(cube, radius);
    int mitres = 0;
    double lowest = 1.0, highest = 0.0;
    const SideSamples samples(s);
    for (std::size_t p = 0; p < s.patches.size(); ++p) {
      const RoundedPatchInfo &a = s.info[p];
      if (!a.alongAxis) continue;
      for (PatchSide side : kSides)
        for (const SideMatch &m : neighboursOf(samples, p, side, 1e-12)) {
          const RoundedPatchInfo &b = s.info[m.patch];
          if (m.patch < p || !b.alongAxis || glm::length(glm::cross(a.axis, b.axis)) < 0.5) continue;
          ++mitres;
          for (double t : kSamples) {
            const glm::dvec2 ua = onSide(side, t), ub = onSide(m.side, m.reversed ? 1.0 - t : t);
            const glm::dvec3 point = s.patches[p].evaluate(ua.x, ua.y);
            // On both cylinders (the seam is continuous: neighboursOf matched it to 1e-12) and
            // in the bisecting plane of the corner's upright.
            CHECK(glm::length(point - roundingCentre(a, point)) == doctest::Approx(radius).epsilon(1e-12));
            CHECK(glm::length(point - roundingCentre(b, point)) == doctest::Approx(radius).epsilon(1e-12));
            const double fromX = point.x < 0.5 ? point.x : 1.0 - point.x, fromZ = point.z < 0.5 ? point.z : 1.0 - point.z;
            CHECK(fromX == doctest::Approx(fromZ).epsilon(1e-12));
            // The normals' jump is the intersection's crease: cos = (h / R)^2 at height h above
            // the strips' lower touching lines, a right angle where it continues the sharp
            // upright, nothing where it reaches the top face.
            const double h = point.y - (1.0 - radius);
            const glm::dvec3 na = s.patches[p].normal(ua.x, ua.y), nb = s.patches[m.patch].normal(ub.x, ub.y);
            const double cosine = glm::dot(na, nb);
            CHECK(cosine == doctest::Approx(h * h / (radius * radius)).epsilon(1e-9));
            lowest = std::min(lowest, cosine);
            highest = std::max(highest, cosine);
          }
        }
    }
    // Three mitred corners, each where two strips' halves meet two others'.
    CHECK(mitres == 3 * 2);
    CHECK(lowest == doctest::Approx(0.0));
    CHECK(highest == doctest::Approx(1.0));
  }
  // And the volume is the intersection's: the square outline (one corner rounded by the upright)
  // moves in by delta(d) at depth d below the top, mitred at its three sharp corners, so by
  // Steiner's formula its area there is A - P delta + (pi / 4 + 3) delta^2.
  for (double radius : {0.1, 0.25}) {
    CAPTURE(radius);
    const double area = 1.0 - (1.0 - std::numbers::pi / 4.0) * radius * radius;
    const double perimeter = 4.0 + (std::numbers::pi / 2.0 - 2.0) * radius;
    const double expected = area - perimeter * insetIntegral(radius) + (std::numbers::pi / 4.0 + 3.0) * insetSquaredIntegral(radius);
    const RoundedMesh mesh = tessellateRounded(cube, roundMarkedEdges(cube, radius), {ObjectSpaceTolerance{1e-7}, 6});
    CHECK(meshVolume(mesh) == doctest::Approx(expected).epsilon(2e-5));
  }
}

TEST_CASE("Rounding: a torus piece that ends at a sharp crease closes in a flat cap") {
  // The L of concave_l.wings with its rim edge (1, 1, 1)-(2, 1, 1) left sharp: at the top of the
  // concave edge the rounded rim along x = 1 still turns round the fillet in a torus piece, up
  // to the sharp edge's line x = 1 + R, where a quarter-moon cap in that plane (facing -x) closes
  // it against the sharp corner beyond.
  const MarkedPolyhedron l = readShape("concave_l_one_sharp.wings");
  REQUIRE(l.markedEdges.size() == readShape("concave_l.wings").markedEdges.size() - 1);
  CHECK_NOTHROW(roundMarkedEdges(l, 0.0));
  for (double radius : {0.05, 0.25, 0.5}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(l, radius);
    int caps = 0, torusPieces = 0;
    for (std::size_t p = 0; p < s.patches.size(); ++p) {
      if (s.info[p].torus) ++torusPieces;
      if (s.info[p].capNormal == glm::dvec3(0.0)) continue;
      ++caps;
      CHECK(s.info[p].capNormal == glm::dvec3(-1.0, 0.0, 0.0));
      for (double u : kSamples)
        for (double v : kSamples) {
          const glm::dvec3 point = s.patches[p].evaluate(u, v);
          // In the plane x = 1 + R, between the rim's quarter circle (centre y = z = 1 - R) and
          // the sharp corner y = z = 1.
          CHECK(std::abs(point.x - (1.0 + radius)) < 1e-12);
          CHECK(std::hypot(point.y - (1.0 - radius), point.z - (1.0 - radius)) >= radius * (1.0 - 1e-12));
          CHECK(point.y <= 1.0 + 1e-12);
          CHECK(point.z <= 1.0 + 1e-12);
          CHECK(point.y >= 1.0 - radius - 1e-12);
          CHECK(point.z >= 1.0 - radius - 1e-12);
        }
      // Its texture is the face's chart with the cap turned flat onto the face: lengths kept
      // (the file has no UVs, so the chart is an orthonormal frame), not squeezed onto a line.
      const FaceChart chart = faceChart(l, static_cast<std::size_t>(s.info[p].face));
      for (double u : kSamples)
        for (double v : kSamples) {
          const glm::dvec3 a = s.patches[p].evaluate(u, v), b = s.patches[p].evaluate(1.0 - v, u);
          const glm::dvec2 ta = roundedTexCoord(s.info[p], chart, radius, a);
          const glm::dvec2 tb = roundedTexCoord(s.info[p], chart, radius, b);
          CHECK(std::abs(glm::length(ta - tb) - glm::length(a - b)) < 1e-12);
        }
    }
    // Two cap halves; the torus pieces at both ends of the concave edge, whole.
    CHECK(caps == 2);
    CHECK(torusPieces == 2 * 8);
    // The closed mesh holds the volume of the fully rounded L and what the sharp edge keeps: the
    // strip's (1 - pi / 4) R^2 per length where the rounded L has a plain strip (x in
    // [1 + R, 2 - R]; the torus pieces and caps are the same in both), and at most the R^3 box
    // at its far end, where a mitre replaces the sphere corner.
    const MarkedPolyhedron full = readShape("concave_l.wings");
    const AdaptiveOptions fine{ObjectSpaceTolerance{1e-7}, 6};
    const double fullyRounded = meshVolume(tessellateRounded(full, roundMarkedEdges(full, radius), fine));
    const RoundedMesh mesh = tessellateRounded(l, s, fine);
    checkWatertight(mesh);
    // The drawn caps' triangles (in the plane x = 1 + R, facing -x) keep their lengths in the
    // texture too.
    std::size_t capTriangles = 0;
    for (std::size_t t = 0; t < mesh.mesh.indices.size(); t += 3) {
      const std::uint32_t *corner = &mesh.mesh.indices[t];
      if (mesh.mesh.normals[corner[0]] != glm::dvec3(-1.0, 0.0, 0.0)) continue;
      if (std::abs(mesh.mesh.positions[corner[0]].x - (1.0 + radius)) > 1e-12) continue;
      ++capTriangles;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t i = corner[k], j = corner[(k + 1) % 3];
        CHECK(std::abs(glm::length(mesh.mesh.texCoords[i] - mesh.mesh.texCoords[j]) -
                       glm::length(mesh.mesh.positions[i] - mesh.mesh.positions[j])) < 1e-9);
      }
    }
    CHECK(capTriangles > 0);
    const double kept = meshVolume(mesh) - fullyRounded;
    const double strip = (1.0 - std::numbers::pi / 4.0) * radius * radius * (1.0 - 2.0 * radius);
    CHECK(kept >= strip - 1e-6);
    CHECK(kept <= strip + radius * radius * radius + 1e-6);
  }
}

TEST_CASE("Rounding: a cube standing on a layer's top, its uprights ending in concave torus pieces") {
  // A unit cube on a slab of unit cubes (its top at y = 1), every edge marked. At the foot of each
  // upright that stands on the slab's top (not above the slab's side), the upright's quarter
  // cylinder (axis x = X - R sx, z = Z - R sz) meets the fillets along the cube's foot in a torus
  // piece turned around that axis: its tube (radius R) centred on the circle of radius 2 R at
  // y = 1 + R, below the tube's centre and between the cylinder and the slab's top, normals
  // towards the tube's centre (the solid lies outside it).
  struct Case {
    std::string name;
    glm::dvec2 cube;  // the cube's x and z extent starts here
    int standing;     // uprights whose foot is a standing corner
  };
  for (const Case &c : {Case{"slab_corner_cube.wings", {0.0, 0.0}, 1}, Case{"slab_middle_cube.wings", {1.0, 1.0}, 4}}) {
    const MarkedPolyhedron poly = readShape(c.name);
    for (double radius : {0.05, 0.25, 0.4}) {
      CAPTURE(c.name);
      CAPTURE(radius);
      const RoundedSurface s = roundMarkedEdges(poly, radius);
      int pieces = 0;
      for (std::size_t p = 0; p < s.patches.size(); ++p) {
        if (!s.info[p].torus || !s.info[p].concave) continue;
        ++pieces;
        const glm::dvec3 middle = s.patches[p].evaluate(0.5, 0.5);
        // The upright's axis: R inside the cube from its nearest corner.
        const double cornerX = middle.x > c.cube.x + 0.5 ? c.cube.x + 1.0 : c.cube.x;
        const double cornerZ = middle.z > c.cube.y + 0.5 ? c.cube.y + 1.0 : c.cube.y;
        const double axisX = cornerX + (cornerX > c.cube.x + 0.5 ? -radius : radius);
        const double axisZ = cornerZ + (cornerZ > c.cube.y + 0.5 ? -radius : radius);
        for (double u : kSamples)
          for (double v : kSamples) {
            const glm::dvec3 point = s.patches[p].evaluate(u, v);
            const double fromAxis = std::hypot(point.x - axisX, point.z - axisZ);
            const double tubeHeight = 1.0 + radius;
            CHECK(std::abs(std::hypot(fromAxis - 2.0 * radius, point.y - tubeHeight) - radius) < 1e-9);
            CHECK(fromAxis >= radius * (1.0 - 1e-12));
            CHECK(fromAxis <= 2.0 * radius * (1.0 + 1e-12));
            CHECK(point.y <= tubeHeight + 1e-12);
            CHECK(point.y >= 1.0 - 1e-12);
            // In the quarter around the axis that faces out of the cube's corner.
            CHECK((point.x - axisX) * (cornerX - axisX) >= -1e-12);
            CHECK((point.z - axisZ) * (cornerZ - axisZ) >= -1e-12);
            const glm::dvec3 n = s.patches[p].normal(u, v);
            const glm::dvec3 radial = glm::normalize(glm::dvec3(point.x - axisX, 0.0, point.z - axisZ));
            const glm::dvec3 tube(axisX + 2.0 * radius * radial.x, tubeHeight, axisZ + 2.0 * radius * radial.z);
            CHECK(glm::length(n - (tube - point) / radius) < 1e-9);
            // On the slab's top the normal is the top's (up); on the cylinder's foot it points
            // away from the upright's axis, as the cylinder's does.
            if (std::abs(point.y - 1.0) < 1e-12) CHECK(glm::length(n - glm::dvec3(0.0, 1.0, 0.0)) < 1e-9);
            if (std::abs(fromAxis - radius) < 1e-12) CHECK(glm::length(n - radial) < 1e-9);
          }
      }
      // Each standing corner: cut at 30, 45 and 60 degrees around the axis and in the middle of
      // the tube, and where the fillets are split at 30 and 60 degrees (slab_corner_cube: they
      // meet a fillet's torus piece at their other ends), at those angles along the tube too.
      CHECK(pieces == c.standing * (c.standing == 1 ? 16 : 8));
      checkSeams(poly, s);
      checkRadius(s);
      checkClosedAtEveryDepth(poly, s);
    }
  }
  // A cube on an L's corner cube makes the L's inner upright end at the foot of the cube's inner
  // upright, where convex and concave creases alternate around the vertex (three of each): no
  // patch is built for that kind, and the message names it.
  const MarkedPolyhedron steps = readShape("two_layers.wings");
  CHECK_THROWS_WITH_AS(roundMarkedEdges(steps, 0.1), doctest::Contains("6 creases meet there"), RoundingError);
}

TEST_CASE("Rounding: a cube's sharp upright standing on a layer's top, its fillets meeting in a horn piece") {
  // The cube in the middle of the slab of 3 x 3 cubes (x, z in [1, 2], y in [1, 2]) with its
  // uprights left sharp. Round the foot of each, the fillets along the foot meet in a piece of the
  // horn torus about the upright's line: its tube (radius R) centred on the circle of radius R at
  // y = 1 + R, between the slab's top and the point R up the upright, outside the cube.
  const MarkedPolyhedron poly = readShape("slab_middle_cube_sharp_uprights.wings");
  for (double radius : {0.05, 0.25, 0.4}) {
    CAPTURE(radius);
    const RoundedSurface s = roundMarkedEdges(poly, radius);
    int pieces = 0, touchingTop = 0;
    for (std::size_t p = 0; p < s.patches.size(); ++p) {
      if (!s.info[p].torus) continue;
      ++pieces;
      const glm::dvec3 middle = s.patches[p].evaluate(0.5, 0.5);
      const double edgeX = middle.x > 1.5 ? 2.0 : 1.0, edgeZ = middle.z > 1.5 ? 2.0 : 1.0;
      const double outX = edgeX > 1.5 ? 1.0 : -1.0, outZ = edgeZ > 1.5 ? 1.0 : -1.0;
      bool touches = false;
      for (double u : kSamples)
        for (double v : kSamples) {
          const glm::dvec3 point = s.patches[p].evaluate(u, v);
          const double fromEdge = std::hypot(point.x - edgeX, point.z - edgeZ);
          CHECK(std::abs(std::hypot(fromEdge - radius, point.y - (1.0 + radius)) - radius) < 1e-9);
          CHECK(fromEdge <= radius * (1.0 + 1e-12));
          CHECK(point.y >= 1.0 - 1e-12);
          CHECK(point.y <= 1.0 + radius + 1e-12);
          CHECK((point.x - edgeX) * outX >= -1e-12);
          CHECK((point.z - edgeZ) * outZ >= -1e-12);
          if (fromEdge < 1e-12) continue;  // the cusp on the upright
          const glm::dvec3 radial = glm::normalize(glm::dvec3(point.x - edgeX, 0.0, point.z - edgeZ));
          const glm::dvec3 tube(edgeX + radius * radial.x, 1.0 + radius, edgeZ + radius * radial.z);
          const glm::dvec3 n = s.patches[p].normal(u, v);
          CHECK(glm::length(n - (tube - point) / radius) < 1e-9);
          if (std::abs(point.y - 1.0) < 1e-12) {
            CHECK(glm::length(n - glm::dvec3(0.0, 1.0, 0.0)) < 1e-9);
            touches = true;
          }
        }
      if (touches) ++touchingTop;
    }
    // Four feet, each in four pieces (split in the middle both ways), two on the slab's top.
    CHECK(pieces == 4 * 4);
    CHECK(touchingTop == 4 * 2);
  }
}
