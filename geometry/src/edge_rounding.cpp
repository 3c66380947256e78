// Rounding marked edges with rational Bezier patches (see edge_rounding.h for the construction).
#include "glass/geometry/edge_rounding.h"

#include "glass/geometry/polygon_tessellation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

glm::dvec3 newellNormal(const MarkedPolyhedron& poly, const MarkedPolyhedron::Face& face) {
  glm::dvec3 n(0.0);
  const std::size_t count = face.vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3& a = poly.vertices[face.vertices[i]];
    const glm::dvec3& b = poly.vertices[face.vertices[(i + 1) % count]];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double length = glm::length(n);
  return length > 0.0 ? n / length : n;
}

namespace {

// Directions are unit vectors; dot products below this count as zero (a right angle), above
// 1 - this as parallel. Modelled objects carry rounding noise in their coordinates.
constexpr double kAngleTolerance = 1e-6;

// The middle weight of a quarter circle as a rational quadratic: cos(45 degrees).
double quarterArcWeight() { return std::sqrt(0.5); }

// Where a quarter arc (end weights 1, middle weight cos 45 degrees), split in the middle, has its
// first half split again so that the cut lies at 30 degrees from the start: the parameter on that
// half. The second half's cut at 60 degrees lies at 1 minus it (the arc is symmetric). Found by
// bisection on the half's own control points, the ones every split arc has.
double thirtyDegreeParameter() {
  const double w = quarterArcWeight();
  const glm::dvec3 h0(1.0, 0.0, 1.0), h1(w, w, w), h2(0.0, 1.0, 1.0);
  const glm::dvec3 q0 = h0, q1 = 0.5 * (h0 + h1), q2 = 0.5 * (0.5 * (h0 + h1) + 0.5 * (h1 + h2));
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 200 && low < high; ++i) {
    const double s = 0.5 * (low + high);
    if (s == low || s == high) break;
    const glm::dvec3 p = (1.0 - s) * (1.0 - s) * q0 + 2.0 * s * (1.0 - s) * q1 + s * s * q2;
    if (portable::atan2(p.y, p.x) < std::numbers::pi / 6.0) low = s;
    else high = s;
  }
  return 0.5 * (low + high);
}

std::string describeVertex(std::uint32_t v) { return "vertex " + std::to_string(v); }

struct EdgeRecord {
  std::uint32_t from = 0, to = 0;  // as the left face runs along it
  int left = -1;                   // the face running from -> to
  int right = -1;                  // the face running to -> from
  bool marked = false;
  bool rounded = false;  // marked, at a right angle (flat marked edges are not rounded)
  bool concave = false;  // rounded, and concave: a fillet outside the faces
};

std::string describeEdge(const EdgeRecord& e) {
  return "edge " + std::to_string(e.from) + "-" + std::to_string(e.to);
}

// The topology of the polyhedron: edges with their two faces, edges around each vertex, face
// normals. Built once per rounding.
class Topology {
 public:
  explicit Topology(const MarkedPolyhedron& poly) : poly_(poly), vertexEdges_(poly.vertices.size()) {
    for (std::size_t f = 0; f < poly.faces.size(); ++f) {
      const auto& face = poly.faces[f];
      if (face.vertices.size() < 3)
        throw RoundingError("face " + std::to_string(f) + " has " + std::to_string(face.vertices.size()) +
                            " vertices; a face needs at least 3");
      for (std::uint32_t v : face.vertices)
        if (v >= poly.vertices.size())
          throw RoundingError("face " + std::to_string(f) + " names vertex " + std::to_string(v) + ", but there are " +
                              std::to_string(poly.vertices.size()) + " vertices");
      normals_.push_back(newellNormal(poly, face));
      for (std::size_t i = 0; i < face.vertices.size(); ++i) {
        const std::uint32_t a = face.vertices[i], b = face.vertices[(i + 1) % face.vertices.size()];
        if (a == b) throw RoundingError("face " + std::to_string(f) + " repeats " + describeVertex(a));
        const auto key = std::minmax(a, b);
        auto found = edgeIndex_.find(key);
        if (found == edgeIndex_.end()) {
          edgeIndex_.emplace(key, edges_.size());
          vertexEdges_[a].push_back(edges_.size());
          vertexEdges_[b].push_back(edges_.size());
          edges_.push_back(EdgeRecord{a, b, static_cast<int>(f), -1, false, false});
        } else {
          EdgeRecord& e = edges_[found->second];
          if (e.from == a || e.right >= 0)
            throw RoundingError(describeEdge(e) + " is used by more than two faces or twice in one direction (faces " +
                                std::to_string(e.left) + " and " + std::to_string(f) +
                                "): the faces are not consistently oriented");
          e.right = static_cast<int>(f);
        }
      }
    }
    for (const auto& [a, b] : poly.markedEdges) {
      auto found = edgeIndex_.find(std::minmax(a, b));
      if (found == edgeIndex_.end())
        throw RoundingError("marked edge " + std::to_string(a) + "-" + std::to_string(b) + " is not an edge of any face");
      edges_[found->second].marked = true;
    }
  }

  const MarkedPolyhedron& poly() const { return poly_; }
  std::vector<EdgeRecord>& edges() { return edges_; }
  const std::vector<EdgeRecord>& edges() const { return edges_; }
  const std::vector<std::size_t>& edgesAt(std::uint32_t v) const { return vertexEdges_[v]; }
  const glm::dvec3& normal(std::size_t face) const { return normals_[face]; }
  std::size_t edgeBetween(std::uint32_t a, std::uint32_t b) const { return edgeIndex_.at(std::minmax(a, b)); }
  std::uint32_t otherEnd(std::size_t edge, std::uint32_t v) const {
    return edges_[edge].from == v ? edges_[edge].to : edges_[edge].from;
  }
  // The unit vector from v along the edge. One expression for every use, so that points built
  // from it by different faces and patches agree bit for bit.
  glm::dvec3 direction(std::uint32_t v, std::size_t edge) const {
    return glm::normalize(poly_.vertices[otherEnd(edge, v)] - poly_.vertices[v]);
  }
  glm::dvec3 centroid(std::size_t face) const {
    glm::dvec3 sum(0.0);
    for (std::uint32_t v : poly_.faces[face].vertices) sum += poly_.vertices[v];
    return sum / static_cast<double>(poly_.faces[face].vertices.size());
  }

 private:
  const MarkedPolyhedron& poly_;
  std::vector<EdgeRecord> edges_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edgeIndex_;
  std::vector<std::vector<std::size_t>> vertexEdges_;
  std::vector<glm::dvec3> normals_;
};

enum class Dihedral { Convex, Flat, Concave };

// The sign of the far side of the right face seen from the left face's plane: below it for a
// convex edge. Measured at the right face's centroid, relative to the edge's length.
Dihedral dihedralOf(const Topology& topo, const EdgeRecord& e) {
  const glm::dvec3& origin = topo.poly().vertices[e.from];
  const double scale = glm::length(topo.poly().vertices[e.to] - origin);
  const glm::dvec3 toFar = topo.centroid(static_cast<std::size_t>(e.right)) - origin;
  const double height = glm::dot(topo.normal(static_cast<std::size_t>(e.left)), toFar) / scale;
  if (std::abs(height) < kAngleTolerance) return Dihedral::Flat;
  return height < 0.0 ? Dihedral::Convex : Dihedral::Concave;
}

// Decides which marked edges are rounded and checks every corner a rounded edge ends at.
void classifyForRounding(Topology& topo) {
  for (EdgeRecord& e : topo.edges()) {
    if (!e.marked) continue;
    if (e.right < 0) throw RoundingError("marked " + describeEdge(e) + " borders only face " + std::to_string(e.left) + ": the object is open there");
    const Dihedral dihedral = dihedralOf(topo, e);
    if (dihedral == Dihedral::Flat) continue;  // nothing to round between coplanar faces
    const double cosine = glm::dot(topo.normal(static_cast<std::size_t>(e.left)), topo.normal(static_cast<std::size_t>(e.right)));
    if (std::abs(cosine) > kAngleTolerance) {
      std::ostringstream angle;
      angle.precision(4);
      angle << 180.0 - portable::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
      throw RoundingError("marked " + describeEdge(e) + " joins faces " + std::to_string(e.left) + " and " +
                          std::to_string(e.right) + " at " + angle.str() +
                          " degrees; rounding supports right angles only (an object made of cubes)");
    }
    e.rounded = true;
    e.concave = dihedral == Dihedral::Concave;
  }
}

bool touchesRounding(const Topology& topo, std::uint32_t v) {
  for (std::size_t e : topo.edgesAt(v))
    if (topo.edges()[e].rounded) return true;
  return false;
}

// The concave rounded edge that ends at v, where its web fills the corner; none when v has no
// rounded edge, more than one (a crease running straight through) or a convex one.
std::optional<std::size_t> concaveEndAt(const Topology& topo, std::uint32_t v) {
  std::optional<std::size_t> found;
  for (std::size_t e : topo.edgesAt(v)) {
    if (!topo.edges()[e].rounded) continue;
    if (found || !topo.edges()[e].concave) return std::nullopt;
    found = e;
  }
  return found;
}

bool faceHasEdge(const Topology& topo, std::size_t face, std::size_t edge) {
  return topo.edges()[edge].left == static_cast<int>(face) || topo.edges()[edge].right == static_cast<int>(face);
}

// A corner where a concave rounded edge c ends between two rounded convex edges: a in c's left
// face, b in its right face, the three at right angles, and the end face's two flat edges running
// on from b's and a's lines backwards (flatA along -a, flatB along -b). There a torus piece joins
// the fillet and the two strips (see edge_rounding.h).
// One of a and b may be a sharp crease (sharpA, sharpB): the torus piece then still turns the
// rounded one's quarter circle all the way round to the sharp one's line, and ends there in a flat
// cap (see edge_rounding.h).
// The same corner turned inside out (`standing`): a convex rounded edge c (the upright of a cube
// standing on a layer's top) ends between two rounded concave edges a and b (the fillets along
// the cube's foot), the end face (the layer's top) split by flat edges along -a and -b. The torus
// piece is then the fillets' quarter circle swept around c's axis, concave, with the same net.
struct TorusCorner {
  std::size_t c = 0, a = 0, b = 0, flatA = 0, flatB = 0;
  bool sharpA = false, sharpB = false;
  bool standing = false;
  bool sharpC = false;  // standing only: the upright is sharp (a horn piece, see hornCornerAt)
  // The sharp one of a and b, when there is one.
  std::optional<std::size_t> sharp() const {
    if (sharpA) return a;
    if (sharpB) return b;
    return std::nullopt;
  }
};

std::optional<TorusCorner> creaseCornerAt(const Topology& topo, std::uint32_t v) {
  const auto& all = topo.edgesAt(v);
  if (all.size() != 5) return std::nullopt;
  std::vector<std::size_t> concave, convex, flat;
  for (std::size_t e : all) {
    const EdgeRecord& edge = topo.edges()[e];
    if (edge.right < 0) return std::nullopt;
    const Dihedral dihedral = dihedralOf(topo, edge);
    if (dihedral == Dihedral::Flat) flat.push_back(e);
    else if (dihedral == Dihedral::Concave) concave.push_back(e);
    else convex.push_back(e);
  }
  if (flat.size() != 2) return std::nullopt;
  TorusCorner corner;
  std::vector<std::size_t> sides;
  if (concave.size() == 1 && convex.size() == 2) {
    // The fillet and at least one of the convex creases rounded (both sharp: the fillet's web).
    if (!topo.edges()[concave[0]].rounded || (!topo.edges()[convex[0]].rounded && !topo.edges()[convex[1]].rounded))
      return std::nullopt;
    corner.c = concave[0];
    sides = convex;
  } else if (concave.size() == 2 && convex.size() == 1) {
    // Standing: both fillets rounded (a sharp foot has no patch here); the upright rounded (a
    // torus piece) or sharp (a horn piece).
    if (!topo.edges()[concave[0]].rounded || !topo.edges()[concave[1]].rounded) return std::nullopt;
    corner.c = convex[0];
    corner.standing = true;
    corner.sharpC = !topo.edges()[convex[0]].rounded;
    sides = concave;
  } else {
    return std::nullopt;
  }
  const auto left = static_cast<std::size_t>(topo.edges()[corner.c].left);
  const bool firstOnLeft = faceHasEdge(topo, left, sides[0]);
  corner.a = firstOnLeft ? sides[0] : sides[1];
  corner.b = firstOnLeft ? sides[1] : sides[0];
  if (!faceHasEdge(topo, left, corner.a) || !faceHasEdge(topo, static_cast<std::size_t>(topo.edges()[corner.c].right), corner.b))
    return std::nullopt;
  const glm::dvec3 da = topo.direction(v, corner.a), db = topo.direction(v, corner.b), dc = topo.direction(v, corner.c);
  if (std::abs(glm::dot(da, db)) > kAngleTolerance || std::abs(glm::dot(da, dc)) > kAngleTolerance ||
      std::abs(glm::dot(db, dc)) > kAngleTolerance)
    return std::nullopt;
  auto opposite = [&](std::size_t e, const glm::dvec3& d) { return glm::dot(topo.direction(v, e), d) < -1.0 + kAngleTolerance; };
  for (std::size_t e : flat) {
    if (opposite(e, da)) corner.flatA = e;
    else if (opposite(e, db)) corner.flatB = e;
    else return std::nullopt;
  }
  if (corner.flatA == corner.flatB) return std::nullopt;
  corner.sharpA = !topo.edges()[corner.a].rounded;
  corner.sharpB = !topo.edges()[corner.b].rounded;
  return corner;
}

// A torus corner (see TorusCorner): every kind but the horn's.
std::optional<TorusCorner> torusCornerAt(const Topology& topo, std::uint32_t v) {
  auto corner = creaseCornerAt(topo, v);
  if (corner && corner->sharpC) return std::nullopt;
  return corner;
}

// A standing corner whose upright is left sharp: the two fillets along the cube's foot meet round
// the upright's foot in a piece of the horn torus that a ball of radius R rolling along them
// sweeps as it turns about the sharp edge (its centre R from the edge, R above the layer's top).
std::optional<TorusCorner> hornCornerAt(const Topology& topo, std::uint32_t v) {
  auto corner = creaseCornerAt(topo, v);
  if (corner && !corner->sharpC) return std::nullopt;
  return corner;
}

// At a standing torus corner, turns the records of the fillets a and b round where needed so that
// each runs with the end face on its left: the fillet's arc then runs from the end face to the
// upright's face, as the torus's minor arc does, and a fillet split at 30 and 60 degrees (see
// RoundingBuilder::findTori) is split by the same operations on the same points as the torus.
// A fillet between two standing corners has the same end face (the layer's top) at both.
void orientStandingFillets(Topology& topo) {
  for (std::uint32_t v = 0; v < topo.poly().vertices.size(); ++v) {
    const auto corner = creaseCornerAt(topo, v);
    if (!corner || !corner->standing) continue;
    const EdgeRecord& upright = topo.edges()[corner->c];
    for (const auto& [fillet, wall] : {std::pair{corner->a, upright.left}, std::pair{corner->b, upright.right}}) {
      EdgeRecord& e = topo.edges()[fillet];
      if (e.right != wall) {
        std::swap(e.from, e.to);
        std::swap(e.left, e.right);
      }
    }
  }
}

void checkCorner(const Topology& topo, std::uint32_t v) {
  const auto& all = topo.edgesAt(v);
  std::vector<std::size_t> creases;
  std::vector<std::size_t> concave;
  for (std::size_t e : all) {
    const EdgeRecord& edge = topo.edges()[e];
    if (edge.right < 0)
      throw RoundingError(describeVertex(v) + ", where a rounded edge ends, lies on the open " + describeEdge(edge));
    const Dihedral dihedral = dihedralOf(topo, edge);
    if (dihedral != Dihedral::Flat) creases.push_back(e);
    if (dihedral == Dihedral::Concave) concave.push_back(e);
  }
  auto perpendicular = [&](std::size_t a, std::size_t b) {
    return std::abs(glm::dot(topo.direction(v, a), topo.direction(v, b))) < kAngleTolerance;
  };
  if (creaseCornerAt(topo, v)) return;  // a torus or horn piece
  if (concaveEndAt(topo, v) && concave.size() == 1 && creases.size() == 3) {
    // A concave fillet ending where two sharp convex edges leave at right angles: its web.
    std::vector<std::size_t> others;
    for (std::size_t e : creases)
      if (e != concave[0]) others.push_back(e);
    if (perpendicular(others[0], others[1]) && perpendicular(others[0], concave[0]) &&
        perpendicular(others[1], concave[0]))
      return;
  }
  const bool straight = creases.size() == 2 &&
                        glm::dot(topo.direction(v, creases[0]), topo.direction(v, creases[1])) < -1.0 + kAngleTolerance;
  if (!concave.empty() && !(straight && concave.size() == 2)) {
    const EdgeRecord& edge = topo.edges()[concave[0]];
    // What meets there, so that a corner of a kind the rounding has no patch for (where a layer
    // of cubes stands on another, two concave edges meet a convex one) is plain from the message.
    std::string kinds;
    for (std::size_t e : creases)
      kinds += (kinds.empty() ? "" : ", ") + std::string(dihedralOf(topo, topo.edges()[e]) == Dihedral::Concave ? "concave " : "convex ") +
               (topo.edges()[e].rounded ? "rounded " : "sharp ") + describeEdge(topo.edges()[e]);
    throw RoundingError(describeVertex(v) + ", where a rounded edge ends, has the concave " + describeEdge(edge) +
                        (edge.rounded ? " and other creases that are rounded or not at right angles"
                                      : ", which is not rounded") +
                        " (" + std::to_string(creases.size()) + " creases meet there: " + kinds +
                        "); a rounded concave edge must end where its two other creases are convex and at right "
                        "angles, and where one of them is rounded, the end face must be split by flat edges along "
                        "their continuations");
  }
  if (creases.size() == 3 && all.size() == 3 && perpendicular(creases[0], creases[1]) &&
      perpendicular(creases[1], creases[2]) && perpendicular(creases[0], creases[2]))
    return;  // the corner of a cube
  if (straight) {
    const EdgeRecord& a = topo.edges()[creases[0]];
    const EdgeRecord& b = topo.edges()[creases[1]];
    if (a.rounded != b.rounded)
      throw RoundingError("rounded " + describeEdge(a.rounded ? a : b) + " ends at " + describeVertex(v) +
                          " in the middle of a straight crease; mark " + describeEdge(a.rounded ? b : a) + " too");
    return;  // a crease running straight through, with flat edges across
  }
  throw RoundingError(describeVertex(v) + ", where a rounded edge ends, is not the corner of a cube: it has " +
                      std::to_string(creases.size()) + " creases and " + std::to_string(all.size()) +
                      " edges; rounding supports corners of three edges at right angles");
}

void checkFaceCorners(const Topology& topo, std::size_t f, const std::vector<bool>& touched) {
  const auto& face = topo.poly().faces[f];
  const std::size_t count = face.vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t v = face.vertices[i];
    if (!touched[v]) continue;
    const std::uint32_t previous = face.vertices[(i + count - 1) % count], next = face.vertices[(i + 1) % count];
    const double cosine = glm::dot(topo.direction(v, topo.edgeBetween(v, previous)), topo.direction(v, topo.edgeBetween(v, next)));
    if (std::abs(cosine) > kAngleTolerance) {
      std::ostringstream angle;
      angle.precision(4);
      angle << portable::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
      throw RoundingError("face " + std::to_string(f) + " has an angle of " + angle.str() + " degrees at " +
                          describeVertex(v) + ", where a rounded edge ends; rounding needs right angles there");
    }
  }
}

bool isConvex(const Topology& topo, std::size_t f) {
  const auto& face = topo.poly().faces[f];
  const auto& points = topo.poly().vertices;
  const std::size_t count = face.vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3& a = points[face.vertices[(i + count - 1) % count]];
    const glm::dvec3& b = points[face.vertices[i]];
    const glm::dvec3& c = points[face.vertices[(i + 1) % count]];
    const glm::dvec3 turn = glm::cross(glm::normalize(b - a), glm::normalize(c - b));
    if (glm::dot(turn, topo.normal(f)) < -kAngleTolerance) return false;
  }
  return true;
}

// A piece of the torus's side in the end face's plane, as a rational quadratic (homogeneous
// control points), with the face it lies in and the torus patch it is a side of.
struct TorusArc {
  std::array<glm::dvec4, 3> row;
  std::size_t face = 0;
  PatchSideRef along;
};

glm::dvec3 projected(const glm::dvec4& h) { return glm::dvec3(h) / h.w; }

// A piece of a face's boundary at one of its corners: the corner itself, moved in by the rounding,
// a quarter arc where the face is the end face of a rounded edge, or pieces of a torus's arc.
struct CornerPiece {
  bool arc = false;
  glm::dvec3 start{0.0}, end{0.0}, middle{0.0};  // a point corner has start == end
  std::vector<std::size_t> terms;                  // the edges the point is moved along (point corners)
  // A corner of the end face cut by a torus's arc: its pieces from start to end. `terms` are then
  // the face's two edges there; the point beside a rounded one of them is v moved along both.
  bool torus = false;
  std::vector<TorusArc> torusArcs;
  // The end face beside the sharp crease at a torus corner with one (see TorusCorner): after its
  // arcs (or before them), the segment along the cap's side to the point where its sharp edge
  // starts.
  bool step = false;
  bool stepAtEnd = false;
  glm::dvec3 stepPoint{0.0};
};

class RoundingBuilder {
 public:
  RoundingBuilder(Topology& topo, double radius)
      : topo_(topo), radius_(radius), weight_(quarterArcWeight()), thirty_(thirtyDegreeParameter()) {
    touched_.assign(topo.poly().vertices.size(), false);
    if (radius > 0.0) {
      for (std::uint32_t v = 0; v < touched_.size(); ++v) touched_[v] = touchesRounding(topo, v);
    }
  }

  // Finds the torus corners, and the fillets split at 30 and 60 degrees to meet them: those ending
  // at one, and those joined to them through corners the crease runs straight through.
  void findTori() {
    for (std::uint32_t v = 0; v < touched_.size(); ++v) {
      if (!touched_[v]) continue;
      if (const auto corner = torusCornerAt(topo_, v)) {
        tori_.emplace(v, *corner);
        splitFillets_.insert(corner->c);
      }
      if (const auto corner = hornCornerAt(topo_, v)) horns_.emplace(v, *corner);
    }
    // Two fillets at a vertex are split alike: where the crease runs straight through, and at a
    // standing corner, whose torus piece's minor arcs are split for both or neither. So are two
    // rounded convex edges where their crease runs straight through (an upright two layers high
    // above a standing corner).
    for (bool grown = true; grown;) {
      grown = false;
      for (std::uint32_t v = 0; v < touched_.size(); ++v) {
        std::vector<std::size_t> fillets, convex;
        for (std::size_t e : topo_.edgesAt(v)) {
          if (topo_.edges()[e].concave) fillets.push_back(e);
          else if (dihedralOf(topo_, topo_.edges()[e]) == Dihedral::Convex) convex.push_back(e);
        }
        const bool straightConvex = fillets.empty() && convex.size() == 2 && topo_.edges()[convex[0]].rounded &&
                                    topo_.edges()[convex[1]].rounded &&
                                    glm::dot(topo_.direction(v, convex[0]), topo_.direction(v, convex[1])) < -1.0 + kAngleTolerance;
        for (const auto* pair : {&fillets, &convex}) {
          if (pair->size() != 2 || (pair == &convex && !straightConvex)) continue;
          if (splitFillets_.count((*pair)[0]) == splitFillets_.count((*pair)[1])) continue;
          splitFillets_.insert((*pair)[0]);
          splitFillets_.insert((*pair)[1]);
          grown = true;
        }
      }
    }
    for (std::size_t e : splitFillets_) {
      const EdgeRecord& edge = topo_.edges()[e];
      if (edge.concave) continue;
      for (std::uint32_t end : {edge.from, edge.to}) checkSplitUprightEnd(e, end);
    }
  }

  // A rounded convex edge split at 30 and 60 degrees (an upright above a standing corner) meets,
  // at `end`, a torus piece, its continuation (split alike), a sphere corner (split to match,
  // when it is the corner's only split edge) or the face across its end. Anything else (a mitre,
  // whose other strip would have to be split the other way round) is refused.
  void checkSplitUprightEnd(std::size_t e, std::uint32_t end) const {
    if (tori_.count(end) > 0 && tori_.at(end).c == e) return;
    std::vector<std::size_t> rounded;
    for (std::size_t other : topo_.edgesAt(end))
      if (topo_.edges()[other].rounded) rounded.push_back(other);
    if (rounded.size() == 1) return;  // the strip ends at the face across it
    const auto split = std::count_if(rounded.begin(), rounded.end(), [&](std::size_t r) { return splitFillets_.count(r) > 0; });
    if (rounded.size() == 2 && split == 2 &&
        glm::dot(topo_.direction(end, rounded[0]), topo_.direction(end, rounded[1])) < -1.0 + kAngleTolerance)
      return;
    if (rounded.size() == 3 && topo_.edgesAt(end).size() == 3 && split == 1) return;
    throw RoundingError(describeVertex(end) + ", where the rounded upright " + describeEdge(topo_.edges()[e]) +
                        " above a cube's foot ends, has " + std::to_string(rounded.size()) + " rounded edges, " +
                        std::to_string(split) +
                        " of them split to meet torus pieces; such an upright must end at a sphere corner, the face "
                        "across it or a crease running straight on");
  }

  // The torus piece at v (see edge_rounding.h): a surface of revolution around the fillet's axis,
  // u along the major arc from the strip on a to the strip on b (as the fillet's u runs from its
  // left face to its right face), v along the minor arc from the end face to the fillet. Its net
  // is built from the same offset points as its neighbours' ends: row v = 2 is the fillet's end,
  // column u = 0 strip a's end, column u = 2 strip b's end.
  void addTorus(std::uint32_t v) {
    const TorusCorner& t = tori_.at(v);
    const glm::dvec3 points[] = {offsetPoint(v, {t.a, t.flatB}),     offsetPoint(v, {t.a}), offsetPoint(v, {t.a, t.c}),
                                 offsetPoint(v, {t.flatA, t.flatB}), offsetPoint(v, {}),    offsetPoint(v, {t.c}),
                                 offsetPoint(v, {t.b, t.flatA}),     offsetPoint(v, {t.b}), offsetPoint(v, {t.b, t.c})};
    const double w = weight_;
    const double weights[] = {1.0, w, 1.0, w, w * w, w, 1.0, w, 1.0};
    const EdgeRecord& fillet = topo_.edges()[t.c];
    const auto left = static_cast<std::size_t>(fillet.left), right = static_cast<std::size_t>(fillet.right);
    // The end face's pieces at v: the one beside a, the one between the flat edges, the one beside b.
    std::size_t besideA = 0, between = 0, besideB = 0;
    for (std::size_t f : {topo_.edges()[t.flatA].left, topo_.edges()[t.flatA].right, topo_.edges()[t.flatB].left,
                          topo_.edges()[t.flatB].right}) {
      if (faceHasEdge(topo_, f, t.a)) besideA = f;
      else if (faceHasEdge(topo_, f, t.b)) besideB = f;
      else between = f;
    }
    const glm::dvec3 endNormal = topo_.normal(between);
    // From the tube's centre circle towards the end face: out of the solid for a fillet's end,
    // into it for a standing upright's foot (the tube lies above the layer's top).
    const glm::dvec3 towardsEnd = t.standing ? -endNormal : endNormal;
    // The faces beside c seen from c's axis: their outward normals for a convex upright, reversed
    // for a fillet (see RoundedPatchInfo).
    const double side = t.standing ? 1.0 : -1.0;
    RoundedPatchInfo info;
    info.rounded = true;
    info.torus = true;
    info.concave = t.standing;
    info.centre = offsetPoint(v, {t.a, t.b, t.c});
    info.axis = towardsEnd;
    info.majorRadius = 2.0 * radius_;
    // The same splits as the fillet's: in the middle, then at 30 and 60 degrees.
    const auto [firstHalf, secondHalf] = BezierSurface(2, 2, points, weights).subdivideU(0.5);
    const auto [piece0, piece1] = firstHalf.subdivideU(thirty_);
    const auto [piece2, piece3] = secondHalf.subdivideU(1.0 - thirty_);
    const BezierSurface* pieces[] = {&piece0, &piece1, &piece2, &piece3};
    const std::size_t endFaces[] = {besideA, between, between, besideB};
    // The patches of piece 0 (a's end, u = 0) and piece 3 (b's end, u = 1), for a cap there.
    std::vector<std::size_t> endPatches[2];
    // At a standing corner whose fillets are split at 30 and 60 degrees (they meet a torus piece
    // at their other ends too), the minor arcs are split there as well: v runs from the end face
    // to the upright as the fillets' u does (orientStandingFillets), so the same splits of the
    // same points give the same curves.
    const bool splitMinor = t.standing && splitFillets_.count(t.a) > 0;
    for (int k = 0; k < 4; ++k) {
      const auto [endParts, filletParts] = splitAlongTube(*pieces[k], splitMinor);
      const BezierSurface& nearEnd = endParts.front();
      info.face = static_cast<int>(endFaces[k]);
      info.faceNormal = towardsEnd;
      info.acrossNormals.clear();
      for (std::size_t part = 0; part < endParts.size(); ++part) {
        const bool flipped = add(endParts[part], info);
        if (k == 0 || k == 3) endPatches[k / 3].push_back(surface_.patches.size() - 1);
        if (part != 0) continue;
        TorusArc arc;
        for (int i = 0; i < 3; ++i) arc.row[static_cast<std::size_t>(i)] = nearEnd.homogeneousControlPoint(i, 0);
        arc.face = endFaces[k];
        arc.along = {surface_.patches.size() - 1, flipped ? PatchSide::VMax : PatchSide::VMin};
        torusArcs_[v].push_back(arc);
      }
      const std::size_t face = k < 2 ? left : right, other = k < 2 ? right : left;
      info.face = static_cast<int>(face);
      info.faceNormal = side * topo_.normal(face);
      info.acrossNormals = {side * topo_.normal(other)};
      for (const BezierSurface& part : filletParts) {
        add(part, info);
        if (k == 0 || k == 3) endPatches[k / 3].push_back(surface_.patches.size() - 1);
      }
    }
    if (const auto sharp = t.sharp()) addCap(v, t, *sharp, t.sharpA ? PatchSide::UMin : PatchSide::UMax, endPatches[t.sharpA ? 0 : 1]);
  }

  // A torus or horn piece split along its tube (v) as the strips are: in the middle, and where
  // `atThirty`, at 30 degrees from each end too, as fillets split to meet a torus piece are.
  // The parts at v = 0 come first in the first vector, those at v = 1 in the second.
  std::pair<std::vector<BezierSurface>, std::vector<BezierSurface>> splitAlongTube(const BezierSurface& piece, bool atThirty) const {
    const auto [low, high] = piece.subdivideV(0.5);
    if (!atThirty) return {{low}, {high}};
    const auto [low0, low1] = low.subdivideV(thirty_);
    const auto [high0, high1] = high.subdivideV(1.0 - thirty_);
    return {{low0, low1}, {high0, high1}};
  }

  // The horn piece at v (see hornCornerAt): a surface of revolution about the sharp upright's
  // line, u from fillet a's end to fillet b's (the major arc, radius R in the layer's top), v from
  // the layer's top to the point R up the upright (the fillets' quarter circle, whose middle
  // control point is v itself, on the line). Its first and last rows are the fillets' end arcs,
  // from the same points. Split in the middle both ways (and at 30 and 60 degrees along the tube
  // where the fillets are): the halves at the top take its chart, those at the walls theirs.
  void addHorn(std::uint32_t v) {
    const TorusCorner& t = horns_.at(v);
    const glm::dvec3 top = offsetPoint(v, {t.c}), corner = offsetPoint(v, {});
    const glm::dvec3 points[] = {offsetPoint(v, {t.flatB}),          corner, top,
                                 offsetPoint(v, {t.flatA, t.flatB}), corner, top,
                                 offsetPoint(v, {t.flatA}),          corner, top};
    const double w = weight_;
    const double weights[] = {1.0, w, 1.0, w, w * w, w, 1.0, w, 1.0};
    const EdgeRecord& upright = topo_.edges()[t.c];
    const auto wallA = static_cast<std::size_t>(upright.left), wallB = static_cast<std::size_t>(upright.right);
    std::size_t besideA = 0, besideB = 0;
    for (std::size_t f : {topo_.edges()[t.flatA].left, topo_.edges()[t.flatA].right, topo_.edges()[t.flatB].left,
                          topo_.edges()[t.flatB].right}) {
      if (faceHasEdge(topo_, f, t.a)) besideA = f;
      else if (faceHasEdge(topo_, f, t.b)) besideB = f;
    }
    const glm::dvec3 towardsEnd = -topo_.normal(besideA);
    RoundedPatchInfo info;
    info.rounded = true;
    info.torus = true;
    info.concave = true;
    info.centre = top;
    info.axis = towardsEnd;
    info.majorRadius = radius_;
    const bool splitMinor = splitFillets_.count(t.a) > 0;
    const auto [halfA, halfB] = BezierSurface(2, 2, points, weights).subdivideU(0.5);
    for (const auto& [half, face, wall, along] : {std::tuple{&halfA, besideA, wallA, t.a}, std::tuple{&halfB, besideB, wallB, t.b}}) {
      const auto [topParts, wallParts] = splitAlongTube(*half, splitMinor);
      info.face = static_cast<int>(face);
      info.faceNormal = towardsEnd;
      info.acrossNormals.clear();
      info.hornBeyond = glm::dvec3(0.0);
      for (std::size_t part = 0; part < topParts.size(); ++part) {
        const bool flipped = add(topParts[part], info);
        if (part == 0) hornArcs_[v].push_back({surface_.patches.size() - 1, flipped ? PatchSide::VMax : PatchSide::VMin});
      }
      info.face = static_cast<int>(wall);
      info.faceNormal = -topo_.normal(wall);
      info.acrossNormals = {towardsEnd};
      info.hornBeyond = -topo_.direction(v, along);
      for (const BezierSurface& part : wallParts) add(part, info);
    }
  }

  // The cap where a torus piece ends at a sharp crease s (a or b): the piece of the plane normal
  // to s through the torus's end arc (the rounded crease's quarter circle, turned round to s's
  // line) between that arc and its middle control point, s's end R along it. The solid beyond
  // keeps its sharp crease; the cap is the step between the two, a crease all round. It takes
  // the chart of the face holding s and the fillet.
  void addCap(std::uint32_t v, const TorusCorner& t, std::size_t sharp, PatchSide side, const std::vector<std::size_t>& torusPatches) {
    const std::size_t partner = sharp == t.a ? t.flatB : t.flatA;  // the end face's flat edge across it
    const glm::dvec3 corner = offsetPoint(v, {sharp});
    const glm::dvec3 onFace = offsetPoint(v, {sharp, t.c}), onEnd = offsetPoint(v, {sharp, partner});
    const glm::dvec3 normal = -topo_.direction(v, sharp);
    const EdgeRecord& fillet = topo_.edges()[t.c];
    const auto face = static_cast<std::size_t>(faceHasEdge(topo_, static_cast<std::size_t>(fillet.left), sharp) ? fillet.left : fillet.right);
    RoundedPatchInfo info;
    info.face = static_cast<int>(face);
    info.capNormal = normal;
    FaceOutline outline;
    outline.face = static_cast<int>(face);
    outline.normal = normal;
    std::vector<PatchSideRef> along;
    for (std::size_t patch : torusPatches) along.push_back({patch, side});
    if (glm::dot(glm::cross(onFace - corner, onEnd - corner), normal) > 0.0) {  // counter-clockwise
      outline.pieces = {{corner, onFace, {}}, {onFace, onEnd, along}, {onEnd, corner, {}}};
    } else {
      outline.pieces = {{corner, onEnd, {}}, {onEnd, onFace, along}, {onFace, corner, {}}};
    }
    surface_.outlines.push_back(std::move(outline));
    const auto [nearFace, nearEnd] = quarterMoon(onFace, corner, onEnd);
    add(nearFace, info, normal);
    add(nearEnd, info, normal);
  }

  const std::vector<bool>& touched() const { return touched_; }

  // v moved by `radius` along each listed edge, summed in the order of the edges' numbers.
  glm::dvec3 offsetPoint(std::uint32_t v, std::vector<std::size_t> edges) const {
    std::sort(edges.begin(), edges.end());
    glm::dvec3 p = topo_.poly().vertices[v];
    for (std::size_t e : edges) p = p + radius_ * topo_.direction(v, e);
    return p;
  }

  CornerPiece corner(std::size_t f, std::size_t i) const {
    const auto& face = topo_.poly().faces[f];
    const std::size_t count = face.vertices.size();
    const std::uint32_t v = face.vertices[i];
    const std::size_t previous = topo_.edgeBetween(v, face.vertices[(i + count - 1) % count]);
    const std::size_t next = topo_.edgeBetween(v, face.vertices[(i + 1) % count]);
    const bool previousRounded = topo_.edges()[previous].rounded, nextRounded = topo_.edges()[next].rounded;
    CornerPiece piece;
    const auto torus = tori_.find(v);
    if (torus != tori_.end() && !faceHasEdge(topo_, f, torus->second.c)) {
      // A piece of the end face at a torus corner: it loses its corner to the torus's arcs in it,
      // which run in the torus's u order a, flat edge along -b, flat edge along -a, b.
      const TorusCorner& t = torus->second;
      piece.torus = true;
      piece.terms = {previous, next};
      for (const TorusArc& arc : torusArcs_.at(v))
        if (arc.face == f) piece.torusArcs.push_back(arc);
      auto rank = [&](std::size_t e) { return e == t.a ? 0 : e == t.flatB ? 1 : e == t.flatA ? 2 : 3; };
      if (rank(previous) > rank(next)) {
        std::reverse(piece.torusArcs.begin(), piece.torusArcs.end());
        for (TorusArc& arc : piece.torusArcs) std::reverse(arc.row.begin(), arc.row.end());
      }
      piece.start = projected(piece.torusArcs.front().row[0]);
      piece.end = projected(piece.torusArcs.back().row[2]);
      const auto sharp = t.sharp();
      if (sharp && faceHasEdge(topo_, f, *sharp)) {
        // The sharp crease's end of the arcs: a's comes first in u order, b's last.
        piece.step = true;
        piece.stepAtEnd = t.sharpB != (rank(previous) > rank(next));
        piece.stepPoint = offsetPoint(v, {*sharp});
        (piece.stepAtEnd ? piece.end : piece.start) = piece.stepPoint;
      }
      return piece;
    }
    if (previousRounded || nextRounded) {
      // A rounded edge's line moves into the face by R, along the face's other edge there.
      if (previousRounded) piece.terms.push_back(next);
      if (nextRounded) piece.terms.push_back(previous);
      piece.start = piece.end = offsetPoint(v, piece.terms);
    } else if (horns_.count(v) > 0) {
      // The layer's top at a horn piece loses the quarter disk of radius R round the upright's
      // foot: an arc about v, from R along one flat edge to R along the other.
      piece.arc = true;
      piece.start = offsetPoint(v, {previous});
      piece.middle = offsetPoint(v, {previous, next});
      piece.end = offsetPoint(v, {next});
    } else if (touched_[v] && !concaveEndAt(topo_, v)) {
      // The face across the end of a convex rounded edge loses its corner to the strip's end arc.
      // (At the end of a concave one the corner stays, and the web fills in beside it.)
      piece.arc = true;
      piece.start = offsetPoint(v, {previous});
      piece.middle = offsetPoint(v, {});
      piece.end = offsetPoint(v, {next});
    } else {
      piece.start = piece.end = offsetPoint(v, {});
    }
    return piece;
  }

  CornerPiece cornerAt(std::size_t f, std::uint32_t v) const {
    const auto& vertices = topo_.poly().faces[f].vertices;
    const auto at = std::find(vertices.begin(), vertices.end(), v);
    return corner(f, static_cast<std::size_t>(at - vertices.begin()));
  }

  void addFace(std::size_t f) {
    const auto& face = topo_.poly().faces[f];
    const std::size_t count = face.vertices.size();
    std::vector<CornerPiece> corners;
    for (std::size_t i = 0; i < count; ++i) corners.push_back(corner(f, i));
    // The fan's centre. A face with a cap's step at a corner is not convex there (the torus
    // takes a rounded bite out of it beside the step); the fan then starts from the middle of its
    // other corners, which sees the bite's whole outline.
    const bool stepped = std::any_of(corners.begin(), corners.end(), [](const CornerPiece& c) { return c.step; });
    glm::dvec3 centre(0.0);
    std::size_t summed = 0;
    for (const CornerPiece& c : corners) {
      if (stepped && c.step) continue;
      centre += c.start + c.end;
      summed += 2;
    }
    centre /= static_cast<double>(summed);
    const glm::dvec3 normal = topo_.normal(f);
    RoundedPatchInfo info;
    info.face = static_cast<int>(f);
    FaceOutline outline;
    outline.face = static_cast<int>(f);
    for (std::size_t i = 0; i < count; ++i) {
      const CornerPiece& c = corners[i];
      auto addStepSide = [&](const glm::dvec3& from, const glm::dvec3& to) {
        outline.pieces.push_back({from, to, {}});
        const glm::dvec3 points[] = {from, centre, to, centre};
        add(BezierSurface(1, 1, points), info, normal);
      };
      if (c.step && !c.stepAtEnd) addStepSide(c.stepPoint, projected(c.torusArcs.front().row[0]));
      for (const TorusArc& arc : c.torusArcs) {
        outline.pieces.push_back({projected(arc.row[0]), projected(arc.row[2]), {arc.along}});
        const glm::dvec4 net[] = {arc.row[0], glm::dvec4(centre * arc.row[0].w, arc.row[0].w),
                                  arc.row[1], glm::dvec4(centre * arc.row[1].w, arc.row[1].w),
                                  arc.row[2], glm::dvec4(centre * arc.row[2].w, arc.row[2].w)};
        add(BezierSurface::fromHomogeneous(2, 1, std::vector<glm::dvec4>(std::begin(net), std::end(net))), info, normal);
      }
      if (c.step && c.stepAtEnd) addStepSide(projected(c.torusArcs.back().row[2]), c.stepPoint);
      if (c.arc) {
        const std::uint32_t v = face.vertices[i];
        outline.pieces.push_back({c.start, c.end, {}});
        pendingArcs_.push_back({surface_.outlines.size(), outline.pieces.size() - 1, v, roundedEdgeAt(v)});
        const glm::dvec3 points[] = {c.start, centre, c.middle, centre, c.end, centre};
        const double weights[] = {1.0, 1.0, weight_, weight_, 1.0, 1.0};
        const auto [first, second] = BezierSurface(2, 1, points, weights).subdivideU(0.5);
        add(first, info, normal);
        add(second, info, normal);
      }
      const glm::dvec3& a = c.end;
      const glm::dvec3& b = corners[(i + 1) % count].start;
      if (a == b) continue;  // the side is used up by the rounding at both its ends
      const std::uint32_t from = face.vertices[i], to = face.vertices[(i + 1) % count];
      const std::size_t edge = topo_.edgeBetween(from, to);
      // A side along a sharp edge that leaves the end of a concave fillet is split where the web
      // beside it ends, so that the two meet at the same point.
      std::vector<glm::dvec3> stops{a};
      for (std::uint32_t end : {from, to}) {
        // A side along a fillet that ends at a torus corner with a sharp crease in this face: split
        // where the fillet ends and the cap above it begins.
        const auto torus = tori_.find(end);
        if (torus != tori_.end() && edge == torus->second.c) {
          const auto sharp = torus->second.sharp();
          if (sharp && faceHasEdge(topo_, f, *sharp)) stops.push_back(offsetPoint(end, {*sharp, edge}));
          continue;
        }
        const auto concave = concaveEndAt(topo_, end);
        if (!concave || faceHasEdge(topo_, f, *concave) || dihedralOf(topo_, topo_.edges()[edge]) == Dihedral::Flat)
          continue;
        stops.push_back(offsetPoint(end, {edge}));  // from's split first, then to's: in order
      }
      stops.push_back(b);
      for (std::size_t k = 0; k + 1 < stops.size(); ++k) {
        outline.pieces.push_back({stops[k], stops[k + 1], {}});
        if (topo_.edges()[edge].rounded) pendingSides_.push_back({surface_.outlines.size(), outline.pieces.size() - 1, edge, f});
        const glm::dvec3 points[] = {stops[k], centre, stops[k + 1], centre};
        add(BezierSurface(1, 1, points), info, normal);
      }
    }
    surface_.outlines.push_back(std::move(outline));
  }

  // Fills in which rounded patch sides run along each outline piece.
  void linkOutlines() {
    for (const PendingSide& p : pendingSides_) {
      const auto found = stripSides_.find({p.edge, p.face});
      if (found != stripSides_.end()) {
        auto& along = surface_.outlines[p.outline].pieces[p.piece].along;
        along.insert(along.end(), found->second.begin(), found->second.end());
      }
    }
    for (const PendingArc& p : pendingArcs_) {
      const auto horn = hornArcs_.find(p.vertex);
      if (horn != hornArcs_.end()) {
        surface_.outlines[p.outline].pieces[p.piece].along = horn->second;
        continue;
      }
      const auto found = stripEnds_.find({p.edge, p.vertex});
      if (found != stripEnds_.end()) surface_.outlines[p.outline].pieces[p.piece].along = found->second;
    }
  }

  void addStrip(std::size_t edgeIndex) {
    const EdgeRecord& e = topo_.edges()[edgeIndex];
    const auto left = static_cast<std::size_t>(e.left), right = static_cast<std::size_t>(e.right);
    // Whether a face's corner at v moved along this edge.
    auto movedAlong = [&](const CornerPiece& c) { return std::count(c.terms.begin(), c.terms.end(), edgeIndex) > 0; };
    // Where the strip meets a face: its moved corner; at a torus corner, v moved along both of
    // the end face's edges there, as the torus's net has it.
    auto beside = [&](std::uint32_t v, const CornerPiece& c) { return c.torus ? offsetPoint(v, c.terms) : c.start; };
    auto end = [&](std::uint32_t v, glm::dvec3& onLeft, glm::dvec3& middle, glm::dvec3& onRight) {
      const auto torus = tori_.find(v);
      if (torus != tori_.end() && torus->second.c == edgeIndex) {
        // A fillet ends where the torus piece begins, R below the end face, on both faces (the
        // one beside a sharp crease keeps its corner above, beside the cap).
        const TorusCorner& t = torus->second;
        onLeft = offsetPoint(v, {t.a, edgeIndex});
        middle = offsetPoint(v, {edgeIndex});
        onRight = offsetPoint(v, {t.b, edgeIndex});
        return;
      }
      const CornerPiece l = cornerAt(left, v), r = cornerAt(right, v);
      onLeft = beside(v, l);
      onRight = beside(v, r);
      // The arc's middle control point lies on the edge: R in from v where both faces' corners
      // moved along the edge (a sphere corner), at v where the strip ends at a mitre or a face.
      const bool moved = movedAlong(l) && movedAlong(r);
      middle = moved ? offsetPoint(v, {edgeIndex}) : offsetPoint(v, {});
    };
    glm::dvec3 l0, m0, r0, l1, m1, r1;
    end(e.from, l0, m0, r0);
    end(e.to, l1, m1, r1);
    if (l0 == l1 && r0 == r1) return;  // no length left
    const glm::dvec3 points[] = {l0, l1, m0, m1, r0, r1};
    const double weights[] = {1.0, 1.0, weight_, weight_, 1.0, 1.0};
    const auto [nearLeft, nearRight] = BezierSurface(2, 1, points, weights).subdivideU(0.5);
    // The axis: the left face's touching line moved by R into the solid (convex) or out of it
    // (concave), where both faces' planes moved by R meet. The arc's control points are the same
    // for both: the touching lines and the edge's point between them.
    const double side = e.concave ? -1.0 : 1.0;
    const glm::dvec3 axisPoint = l0 - side * radius_ * topo_.normal(left);
    RoundedPatchInfo info;
    info.rounded = true;
    info.concave = e.concave;
    info.alongAxis = true;
    info.centre = axisPoint;
    info.axis = topo_.direction(e.from, edgeIndex);
    // Each half touches its face along u = 0 (nearLeft) or u = 1 (nearRight), and ends at e.from
    // along v = 0, at e.to along v = 1 (swapped when add() turns the patch round).
    auto recordPiece = [&](const BezierSurface& piece, std::optional<PatchSide> faceSide, std::size_t face) {
      const bool flipped = add(piece, info);
      const std::size_t k = surface_.patches.size() - 1;
      if (faceSide) stripSides_[{edgeIndex, face}].push_back(PatchSideRef{k, *faceSide});
      stripEnds_[{edgeIndex, e.from}].push_back({k, flipped ? PatchSide::VMax : PatchSide::VMin});
      stripEnds_[{edgeIndex, e.to}].push_back({k, flipped ? PatchSide::VMin : PatchSide::VMax});
    };
    // A fillet that meets a torus is split again at 30 and 60 degrees, as the torus is.
    const bool split = splitFillets_.count(edgeIndex) > 0;
    auto record = [&](const BezierSurface& half, PatchSide faceSide, std::size_t face) {
      if (!split) return recordPiece(half, faceSide, face);
      const bool first = faceSide == PatchSide::UMin;
      const auto [low, high] = half.subdivideU(first ? thirty_ : 1.0 - thirty_);
      recordPiece(low, first ? std::optional<PatchSide>(faceSide) : std::nullopt, face);
      recordPiece(high, first ? std::nullopt : std::optional<PatchSide>(faceSide), face);
    };
    // A mitre at v: only one of the two faces' corners moved along the edge; the half on that
    // face (which holds the other rounded edge) slides.
    auto mitre = [&](std::uint32_t v, std::size_t face, std::size_t other) {
      const auto torus = tori_.find(v);
      if (torus != tori_.end() && torus->second.c == edgeIndex) return glm::dvec3(0.0);  // a fillet's torus end
      const bool here = movedAlong(cornerAt(face, v)), there = movedAlong(cornerAt(other, v));
      return here && !there ? topo_.direction(v, edgeIndex) : glm::dvec3(0.0);
    };
    info.face = e.left;
    info.faceNormal = side * topo_.normal(left);
    info.acrossNormals = {side * topo_.normal(right)};
    info.lineStart = l0;
    info.lineEnd = l1;
    info.mitreStart = mitre(e.from, left, right);
    info.mitreEnd = mitre(e.to, left, right);
    record(nearLeft, PatchSide::UMin, left);
    info.face = e.right;
    info.faceNormal = side * topo_.normal(right);
    info.acrossNormals = {side * topo_.normal(left)};
    info.lineStart = r0;
    info.lineEnd = r1;
    info.mitreStart = mitre(e.from, right, left);
    info.mitreEnd = mitre(e.to, right, left);
    record(nearRight, PatchSide::UMax, right);
  }

  // The eighth of a sphere where the rounded edges a, b, c (all of v's edges) meet.
  void addSphereCorner(std::uint32_t v) {
    const auto& edges = topo_.edgesAt(v);
    std::size_t a = edges[0], b = edges[1], c = edges[2];
    // An upright split at 30 and 60 degrees (above a standing corner) is c, with a in its left
    // face: the sphere's last row is then that strip's end arc in the strip's own order, and the
    // sphere is split along it by the same operations (the cuts run through the pole).
    const auto split = std::find_if(edges.begin(), edges.end(), [&](std::size_t e) { return splitFillets_.count(e) > 0; });
    const bool splitC = split != edges.end();
    if (splitC) {
      c = *split;
      std::vector<std::size_t> rest;
      for (std::size_t e : edges)
        if (e != c) rest.push_back(e);
      const bool firstOnLeft = faceHasEdge(topo_, static_cast<std::size_t>(topo_.edges()[c].left), rest[0]);
      a = firstOnLeft ? rest[0] : rest[1];
      b = firstOnLeft ? rest[1] : rest[0];
    }
    const std::size_t faceAB = faceWithEdges(v, a, b), faceCA = faceWithEdges(v, c, a), faceBC = faceWithEdges(v, b, c);
    const glm::dvec3 pole = cornerAt(faceAB, v).start;
    const glm::dvec3 points[] = {pole,
                                 pole,
                                 pole,
                                 offsetPoint(v, {a}),
                                 offsetPoint(v, {}),
                                 offsetPoint(v, {b}),
                                 cornerAt(faceCA, v).start,
                                 offsetPoint(v, {c}),
                                 cornerAt(faceBC, v).start};
    const double w = weight_;
    const double weights[] = {1.0, w, 1.0, w, w * w, w, 1.0, w, 1.0};
    const auto [nearPole, nearEquator] = BezierSurface(2, 2, points, weights).subdivideU(0.5);
    const auto [poleA, poleB] = nearPole.subdivideV(0.5);
    const auto [equatorA, equatorB] = nearEquator.subdivideV(0.5);
    RoundedPatchInfo info;
    info.rounded = true;
    info.centre = offsetPoint(v, {a, b, c});
    auto forFace = [&](std::size_t face, std::size_t other1, std::size_t other2) {
      info.face = static_cast<int>(face);
      info.faceNormal = topo_.normal(face);
      info.acrossNormals = {topo_.normal(other1), topo_.normal(other2)};
      return info;
    };
    if (!splitC) {
      add(poleA, forFace(faceAB, faceCA, faceBC));
      add(poleB, forFace(faceAB, faceCA, faceBC));
      add(equatorA, forFace(faceCA, faceAB, faceBC));
      add(equatorB, forFace(faceBC, faceAB, faceCA));
      return;
    }
    // Split at 30 degrees from each touching point, as the strip's halves are (the pole's halves
    // too, which share the cut curves).
    for (const auto& [half, first, face, other1, other2] :
         {std::tuple{&poleA, true, faceAB, faceCA, faceBC}, std::tuple{&poleB, false, faceAB, faceCA, faceBC},
          std::tuple{&equatorA, true, faceCA, faceAB, faceBC}, std::tuple{&equatorB, false, faceBC, faceAB, faceCA}}) {
      const auto [low, high] = half->subdivideV(first ? thirty_ : 1.0 - thirty_);
      add(low, forFace(face, other1, other2));
      add(high, forFace(face, other1, other2));
    }
  }

  // The flat piece of a plane between a quarter arc (from a to b, its middle control point
  // `corner`) and the two segments from its ends to `corner`, in two halves as the arc is split
  // (first the one at a). Each half is ruled between its arc half and the segment from its cusp
  // to the corner (a fan from the corner would have its rulings along the arc's tangents at both
  // ends, the cusps, and no normal along them). The segment is a rational quadratic with the
  // arc's end weights w0, w2, middle weight (w0 + w2) / 2 and middle point
  // (w2 P0 + w0 P2) / (w0 + w2): then its denominator is linear and the point moves along the
  // segment in proportion to u, as the neighbouring face's side does.
  std::pair<BezierSurface, BezierSurface> quarterMoon(const glm::dvec3& a, const glm::dvec3& corner, const glm::dvec3& b) const {
    const glm::dvec3 points[] = {a, corner, corner, corner, b, corner};
    const double weights[] = {1.0, 1.0, weight_, weight_, 1.0, 1.0};
    const auto [nearA, nearB] = BezierSurface(2, 1, points, weights).subdivideU(0.5);
    // Row v = 1 of each half: from its cusp (a at u = 0, b at u = 1) along the segment to the
    // corner. The arc half's middle control point lies on that segment (the arc's tangent at the
    // cusp).
    auto ruled = [&](const BezierSurface& half, int cusp) {
      const glm::dvec4 first = half.homogeneousControlPoint(0, 0), last = half.homogeneousControlPoint(2, 0);
      const double w0 = first.w, w2 = last.w;
      const glm::dvec3 p0 = cusp == 0 ? glm::dvec3(first) / w0 : corner;
      const glm::dvec3 p2 = cusp == 0 ? corner : glm::dvec3(last) / w2;
      const double middleWeight = (w0 + w2) / 2.0;
      const glm::dvec3 middle = (w2 * p0 + w0 * p2) / (w0 + w2);
      const glm::dvec4 edgeRow[] = {glm::dvec4(p0 * w0, w0), glm::dvec4(middle * middleWeight, middleWeight),
                                    glm::dvec4(p2 * w2, w2)};
      std::vector<glm::dvec4> net;
      for (int i = 0; i < 3; ++i) {
        net.push_back(half.homogeneousControlPoint(i, 0));
        net.push_back(edgeRow[i]);
      }
      return BezierSurface::fromHomogeneous(2, 1, std::move(net));
    };
    return {ruled(nearA, 0), ruled(nearB, 2)};
  }

  // The flat web at v, where the concave rounded edge c ends between two sharp edges: the piece
  // of the end plane between those edges and the strip's end arc (whose middle control point is
  // v itself), split in the middle as the strip is (a quarter moon, above). It belongs to a face
  // of that plane beside it (for its chart and material).
  void addWeb(std::uint32_t v) {
    const std::size_t c = *concaveEndAt(topo_, v);
    std::vector<std::size_t> sharp;
    for (std::size_t e : topo_.edgesAt(v))
      if (e != c && dihedralOf(topo_, topo_.edges()[e]) != Dihedral::Flat) sharp.push_back(e);
    const EdgeRecord& first = topo_.edges()[sharp[0]];
    const auto face = static_cast<std::size_t>(faceHasEdge(topo_, static_cast<std::size_t>(first.left), c) ? first.right : first.left);
    const glm::dvec3 normal = topo_.normal(face);
    const glm::dvec3 corner = offsetPoint(v, {});
    glm::dvec3 a = offsetPoint(v, {sharp[0]}), b = offsetPoint(v, {sharp[1]});
    if (glm::dot(glm::cross(a - corner, b - corner), normal) < 0.0) std::swap(a, b);  // counter-clockwise
    RoundedPatchInfo info;
    info.face = static_cast<int>(face);
    FaceOutline outline;
    outline.face = static_cast<int>(face);
    outline.pieces.push_back({corner, a, {}});
    outline.pieces.push_back({a, b, {}});
    pendingArcs_.push_back({surface_.outlines.size(), 1, v, c});
    outline.pieces.push_back({b, corner, {}});
    surface_.outlines.push_back(std::move(outline));
    const auto [nearA, nearB] = quarterMoon(a, corner, b);
    if (splitFillets_.count(c) == 0) {
      add(nearA, info, normal);
      add(nearB, info, normal);
      return;
    }
    // Split as the fillet is: each half starts (nearA) or ends (nearB) at a touching point, so its
    // cut lies at 30 degrees from there, as the fillet's halves' cuts do.
    const auto [a0, a1] = nearA.subdivideU(thirty_);
    const auto [b0, b1] = nearB.subdivideU(1.0 - thirty_);
    for (const BezierSurface* piece : {&a0, &a1, &b0, &b1}) add(*piece, info, normal);
  }

  RoundedSurface take() { return std::move(surface_); }

 private:
  std::size_t faceWithEdges(std::uint32_t v, std::size_t e1, std::size_t e2) const {
    for (std::size_t f : {topo_.edges()[e1].left, topo_.edges()[e1].right}) {
      const EdgeRecord& other = topo_.edges()[e2];
      if (static_cast<int>(f) == other.left || static_cast<int>(f) == other.right) return f;
    }
    throw RoundingError(describeVertex(v) + ": no face holds both of two of its edges");
  }

  // Adds a patch whose normals point away from the solid: for a rounded piece, away from its
  // centre (line); for a flat one, along the face's normal. A patch that comes out the other way
  // round has its v direction reversed (its boundary curves are unchanged).
  // Returns whether the patch was turned round.
  bool add(const BezierSurface& patch, const RoundedPatchInfo& info, const glm::dvec3& flatNormal = {}) {
    const glm::dvec3 probe = patch.evaluate(0.5, 0.5);
    glm::dvec3 outward = flatNormal;
    if (info.rounded) {
      const glm::dvec3 centre = roundingCentre(info, probe);
      outward = info.concave ? centre - probe : probe - centre;
    }
    BezierSurface oriented = patch;
    const bool flip = glm::dot(patch.normal(0.5, 0.5), outward) < 0.0;
    if (flip) {
      const int rows = patch.degreeU() + 1, columns = patch.degreeV() + 1;
      std::vector<glm::dvec4> net;
      for (int i = 0; i < rows; ++i)
        for (int j = columns - 1; j >= 0; --j) net.push_back(patch.homogeneousControlPoint(i, j));
      oriented = BezierSurface::fromHomogeneous(patch.degreeU(), patch.degreeV(), std::move(net));
    }
    surface_.patches.push_back(std::move(oriented));
    surface_.info.push_back(info);
    return flip;
  }

  // The rounded edge at a corner whose face has an arc there (the corner's third edge).
  std::size_t roundedEdgeAt(std::uint32_t v) const {
    for (std::size_t e : topo_.edgesAt(v))
      if (topo_.edges()[e].rounded) return e;
    return 0;
  }

  struct PendingSide {
    std::size_t outline, piece, edge, face;
  };
  struct PendingArc {
    std::size_t outline, piece;
    std::uint32_t vertex;
    std::size_t edge;
  };
  std::vector<PendingSide> pendingSides_;
  std::vector<PendingArc> pendingArcs_;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<PatchSideRef>> stripSides_;
  std::map<std::uint32_t, TorusCorner> tori_;
  std::map<std::uint32_t, TorusCorner> horns_;
  std::map<std::uint32_t, std::vector<PatchSideRef>> hornArcs_;
  std::map<std::uint32_t, std::vector<TorusArc>> torusArcs_;
  std::set<std::size_t> splitFillets_;
  std::map<std::pair<std::size_t, std::uint32_t>, std::vector<PatchSideRef>> stripEnds_;

  Topology& topo_;
  double radius_;
  double weight_;
  double thirty_;
  std::vector<bool> touched_;
  RoundedSurface surface_;
};

double shortestSideLimit(const Topology& topo, const std::vector<bool>& touched, std::string* limit) {
  double best = std::numeric_limits<double>::infinity();
  const auto& poly = topo.poly();
  for (std::size_t f = 0; f < poly.faces.size(); ++f) {
    const auto& face = poly.faces[f];
    const bool near = std::any_of(face.vertices.begin(), face.vertices.end(), [&](std::uint32_t v) { return touched[v]; });
    if (!near) continue;
    for (std::size_t i = 0; i < face.vertices.size(); ++i) {
      const std::uint32_t a = face.vertices[i], b = face.vertices[(i + 1) % face.vertices.size()];
      const double half = glm::length(poly.vertices[b] - poly.vertices[a]) / 2.0;
      if (half < best) {
        best = half;
        if (limit != nullptr) {
          std::ostringstream text;
          text.precision(6);
          text << "half the side " << a << "-" << b << " (length " << 2.0 * half << ") of face " << f
               << ", next to a rounded edge";
          *limit = text.str();
        }
      }
    }
  }
  return best;
}

}  // namespace

glm::dvec2 FaceChart::at(const glm::dvec3& p) const {
  const glm::dvec3 d = p - origin;
  return atOrigin + glm::dvec2(glm::dot(d, sAxis), glm::dot(d, tAxis));
}

FaceChart faceChart(const MarkedPolyhedron& poly, std::size_t f) {
  const auto& face = poly.faces[f];
  const glm::dvec3 normal = newellNormal(poly, face);
  FaceChart chart;
  chart.origin = poly.vertices[face.vertices[0]];
  // An orthonormal frame (x, y) of the face's plane: y along the world's up direction projected,
  // or along -z for faces that look up or down.
  glm::dvec3 up = std::abs(normal.y) > 0.7071 ? glm::dvec3(0.0, 0.0, normal.y > 0.0 ? -1.0 : 1.0) : glm::dvec3(0.0, 1.0, 0.0);
  glm::dvec3 y = up - normal * glm::dot(up, normal);
  if (glm::length(y) == 0.0) y = glm::dvec3(0.0, 0.0, 1.0);
  y = glm::normalize(y);
  const glm::dvec3 x = glm::cross(y, normal);
  if (face.uvs.size() != face.vertices.size()) {
    chart.sAxis = x;
    chart.tAxis = y;
    chart.atOrigin = glm::dvec2(glm::dot(chart.origin, x), glm::dot(chart.origin, y));
    return chart;
  }
  // Least squares: uv = c + A (px, py) over the face's corners, with (px, py) the corner in the
  // frame; the normal equations of [px py 1] for each of s and t.
  double m[3][3] = {};
  glm::dvec3 rs(0.0), rt(0.0);
  for (std::size_t i = 0; i < face.vertices.size(); ++i) {
    const glm::dvec3 d = poly.vertices[face.vertices[i]] - chart.origin;
    const double row[3] = {glm::dot(d, x), glm::dot(d, y), 1.0};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
      rs[r] += row[r] * face.uvs[i].x;
      rt[r] += row[r] * face.uvs[i].y;
    }
  }
  // Cramer's rule on the 3 x 3 system.
  auto det3 = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double det = det3(m);
  auto solve = [&](const glm::dvec3& rhs) {
    glm::dvec3 out(0.0);
    if (std::abs(det) < 1e-300) return out;
    for (int k = 0; k < 3; ++k) {
      double copy[3][3];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) copy[r][c] = c == k ? rhs[r] : m[r][c];
      out[k] = det3(copy) / det;
    }
    return out;
  };
  const glm::dvec3 s = solve(rs), t = solve(rt);
  chart.sAxis = s.x * x + s.y * y;
  chart.tAxis = t.x * x + t.y * y;
  chart.atOrigin = glm::dvec2(s.z, t.z);
  return chart;
}

glm::dvec3 roundingCentre(const RoundedPatchInfo& info, const glm::dvec3& p) {
  if (info.torus) {
    const glm::dvec3 offset = p - info.centre;
    glm::dvec3 radial = offset - info.axis * glm::dot(offset, info.axis);
    if (radial == glm::dvec3(0.0)) {
      // On the axis: a horn piece's point on its sharp upright, R from every centre on the circle.
      radial = glm::cross(info.axis, std::abs(info.axis.x) < 0.5 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0));
    }
    return info.centre + info.majorRadius * glm::normalize(radial);
  }
  if (info.alongAxis) return info.centre + info.axis * glm::dot(p - info.centre, info.axis);
  return info.centre;
}

namespace {

// (4 / pi) times the arc length from the touching point whose direction is perpendicular to
// `across`, to the point of the circle of radius R in `direction`: the unrolled distance.
double unrolledTowards(const glm::dvec3& direction, const glm::dvec3& across, double radius) {
  return (4.0 / std::numbers::pi) * portable::asin(std::clamp(glm::dot(direction, across), -1.0, 1.0)) * radius;
}

// A torus piece unrolled. Next to the end face, as a strip along its tube: from the tube's
// touching point on that face towards the major axis. Next to the fillet, as the fillet is (from
// the fillet's axis to its touching point on the face, then around the major axis towards the
// other face), and then towards the end face by the tube's arc. Either way it runs on into the
// strips' and the fillet's unrolling at their shared ends.
glm::dvec2 torusTexCoord(const RoundedPatchInfo& info, const FaceChart& chart, double radius, const glm::dvec3& p) {
  const glm::dvec3 tube = roundingCentre(info, p);
  const glm::dvec3 direction = glm::normalize(p - tube);
  const glm::dvec3 inward = glm::normalize(info.centre + info.axis * glm::dot(tube - info.centre, info.axis) - tube);
  if (glm::dot(info.faceNormal, info.axis) > 0.5)
    return chart.at(tube + radius * info.faceNormal + unrolledTowards(direction, inward, radius) * inward);
  if (info.hornBeyond != glm::dvec3(0.0)) {
    // A horn piece next to a wall: as the fillet's end unrolls onto the wall (onto the upright's
    // line), then on beyond that line by the length of the turn about it at this point's distance.
    const glm::dvec3 offset = p - info.centre;
    const glm::dvec3 radial = offset - info.axis * glm::dot(offset, info.axis);
    const double distance = glm::length(radial);
    const double turned = distance > 0.0 ? portable::atan2(glm::dot(radial, info.hornBeyond), -glm::dot(radial, info.faceNormal)) : 0.0;
    glm::dvec3 flat = info.centre + distance * turned * info.hornBeyond;
    for (const glm::dvec3& across : info.acrossNormals) flat += unrolledTowards(direction, across, radius) * across;
    return chart.at(flat);
  }
  glm::dvec3 flat = info.centre + radius * info.faceNormal;
  for (const glm::dvec3& across : info.acrossNormals) flat += unrolledTowards(-inward, across, radius) * across;
  flat += unrolledTowards(direction, info.axis, radius) * info.axis;
  return chart.at(flat);
}

}  // namespace

glm::dvec3 capFoldedOntoFace(const FaceChart& chart, const glm::dvec3& capNormal, const glm::dvec3& p) {
  // The cap stands at a right angle to its face (its normal lies along the sharp edge, in the
  // face's plane); projected onto the face it would collapse to a line and the texture stretch
  // across it. Turned about the line where the two planes meet, outwards along the cap's normal
  // (the side of the torus piece it faces), it lies flat on the face: a rigid motion, so the
  // texture keeps its scale and meets the face's own along that line.
  const glm::dvec3 across = glm::cross(chart.sAxis, chart.tAxis);
  if (glm::length(across) == 0.0) return p;  // a face whose texture has no extent: nothing to keep
  const glm::dvec3 normal = glm::normalize(across);
  const double height = glm::dot(p - chart.origin, normal);
  return p - height * normal + std::abs(height) * capNormal;
}

glm::dvec2 roundedTexCoord(const RoundedPatchInfo& info, const FaceChart& chart, double radius, const glm::dvec3& p) {
  if (info.capNormal != glm::dvec3(0.0)) return chart.at(capFoldedOntoFace(chart, info.capNormal, p));
  if (!info.rounded) return chart.at(p);
  if (info.torus) return torusTexCoord(info, chart, radius, p);
  const glm::dvec3 centre = roundingCentre(info, p);
  const glm::dvec3 direction = glm::normalize(p - centre);
  // Unroll onto the face's plane: the touching point (centre + R n_face), then towards each other
  // face of the rounding by 4 / pi times the arc length asin(direction . n) R.
  glm::dvec3 flat = centre + radius * info.faceNormal;
  for (const glm::dvec3& across : info.acrossNormals) {
    const double sine = std::clamp(glm::dot(direction, across), -1.0, 1.0);
    const double unrolled = (4.0 / std::numbers::pi) * portable::asin(sine) * radius;
    flat += unrolled * across;
    if (info.alongAxis) {
      const glm::dvec3 line = info.lineEnd - info.lineStart;
      const double t = std::clamp(glm::dot(p - info.lineStart, line) / glm::dot(line, line), 0.0, 1.0);
      const double slide = radius * sine - unrolled;
      flat += slide * ((1.0 - t) * info.mitreStart + t * info.mitreEnd);
    }
  }
  return chart.at(flat);
}

double maximumRoundingRadius(const MarkedPolyhedron& poly, std::string* limit) {
  Topology topo(poly);
  classifyForRounding(topo);
  std::vector<bool> touched(poly.vertices.size(), false);
  for (std::uint32_t v = 0; v < touched.size(); ++v) touched[v] = touchesRounding(topo, v);
  return shortestSideLimit(topo, touched, limit);
}

RoundedSurface roundMarkedEdges(const MarkedPolyhedron& poly, double radius) {
  if (!(radius >= 0.0) || !std::isfinite(radius)) throw RoundingError("the rounding radius must be 0 or more");
  Topology topo(poly);
  if (radius > 0.0) classifyForRounding(topo);
  RoundingBuilder builder(topo, radius);
  const std::vector<bool>& touched = builder.touched();
  if (radius > 0.0) {
    std::string limit;
    const double largest = shortestSideLimit(topo, touched, &limit);
    if (radius > largest) {
      std::ostringstream text;
      text.precision(6);
      text << "radius " << radius << " is too large: the largest is " << largest << ", " << limit;
      throw RoundingError(text.str());
    }
    orientStandingFillets(topo);
    for (std::uint32_t v = 0; v < touched.size(); ++v)
      if (touched[v]) checkCorner(topo, v);
    // Torus pieces first: the end faces' outlines take their arcs.
    builder.findTori();
    for (std::uint32_t v = 0; v < touched.size(); ++v)
      if (touched[v] && torusCornerAt(topo, v)) builder.addTorus(v);
    for (std::uint32_t v = 0; v < touched.size(); ++v)
      if (touched[v] && hornCornerAt(topo, v)) builder.addHorn(v);
  }
  for (std::size_t f = 0; f < poly.faces.size(); ++f) {
    const auto& face = poly.faces[f];
    const bool near = std::any_of(face.vertices.begin(), face.vertices.end(), [&](std::uint32_t v) { return touched[v]; });
    if (!near) continue;  // drawn as a polygon by tessellateRounded
    checkFaceCorners(topo, f, touched);
    if (!isConvex(topo, f))
      throw RoundingError("face " + std::to_string(f) + ", next to a rounded edge, is not convex");
    builder.addFace(f);
  }
  for (std::size_t e = 0; e < topo.edges().size(); ++e)
    if (topo.edges()[e].rounded) builder.addStrip(e);
  for (std::uint32_t v = 0; v < touched.size(); ++v) {
    if (!touched[v] || topo.edgesAt(v).size() != 3) continue;
    const auto& edges = topo.edgesAt(v);
    if (std::all_of(edges.begin(), edges.end(), [&](std::size_t e) { return topo.edges()[e].rounded; }))
      builder.addSphereCorner(v);
  }
  for (std::uint32_t v = 0; v < touched.size(); ++v)
    if (touched[v] && concaveEndAt(topo, v)) builder.addWeb(v);
  builder.linkOutlines();
  RoundedSurface surface = builder.take();
  surface.radius = radius;
  return surface;
}

namespace {

// A flat face as triangles: the polygon through `contour` (counter-clockwise seen from outside,
// in the face's plane), triangulated in that plane, with the face's normal and chart.
// `planeNormal` is the polygon's plane's normal when it is not the face's (a cap), else zero.
void appendFlatPolygon(const MarkedPolyhedron& poly, std::size_t f, const std::vector<glm::dvec3>& contour, RoundedMesh& out,
                       const glm::dvec3& planeNormal = glm::dvec3(0.0)) {
  if (contour.size() < 3) return;  // a face the rounding used up (R half its width): nothing left of it
  const bool ownPlane = planeNormal != glm::dvec3(0.0);
  const glm::dvec3 normal = ownPlane ? planeNormal : newellNormal(poly, poly.faces[f]);
  const FaceChart chart = faceChart(poly, f);
  const glm::dvec3 origin = contour[0];
  glm::dvec3 x = ownPlane ? contour[1] - contour[0]
                          : poly.vertices[poly.faces[f].vertices[1]] - poly.vertices[poly.faces[f].vertices[0]];
  x = glm::normalize(x - normal * glm::dot(x, normal));
  const glm::dvec3 y = glm::cross(normal, x);
  std::vector<PlanarPoint> planar;
  std::vector<glm::dvec3> points = contour;
  for (const glm::dvec3& p : contour) planar.push_back({glm::dot(p - origin, x), glm::dot(p - origin, y)});
  const PolygonTessellation tess = tessellatePolygon({planar}, WindingRule::NonZero, false);
  for (const CreatedVertex& created : tess.created) {
    glm::dvec3 p(0.0);
    for (int k = 0; k < 4; ++k)
      if (created.sources[k] >= 0) p += created.weights[k] * points[static_cast<std::size_t>(created.sources[k])];
    points.push_back(p);
  }
  const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
  for (const glm::dvec3& p : points) {
    out.mesh.positions.push_back(p);
    out.mesh.normals.push_back(normal);
    out.mesh.texCoords.push_back(chart.at(ownPlane ? capFoldedOntoFace(chart, planeNormal, p) : p));
  }
  for (const TessellatedTriangle& t : tess.triangles) {
    for (int k : t.vertices) out.mesh.indices.push_back(base + static_cast<std::uint32_t>(k));
    out.triangleFaces.push_back(static_cast<int>(f));
  }
}

bool onSide(PatchSide side, const glm::dvec2& uv) {
  switch (side) {
    case PatchSide::UMin: return uv.x == 0.0;
    case PatchSide::UMax: return uv.x == 1.0;
    case PatchSide::VMin: return uv.y == 0.0;
    case PatchSide::VMax: return uv.y == 1.0;
  }
  return false;
}

}  // namespace

RoundedMesh tessellateRounded(const MarkedPolyhedron& poly, const RoundedSurface& surface, const AdaptiveOptions& options) {
  // The rounded patches only: faces are drawn as polygons below. Each patch's parameters come
  // back as texture coordinates offset by 4 x its number among them (s = 4 k + u, t = v, exact
  // binary fractions), so that every vertex can be traced to its patch and place on it.
  std::vector<BezierSurface> rounded;
  std::vector<std::size_t> surfaceIndex;
  std::vector<std::size_t> roundedIndex(surface.patches.size(), 0);
  std::vector<TextureRect> tags;
  for (std::size_t k = 0; k < surface.patches.size(); ++k) {
    if (!surface.info[k].rounded) continue;
    roundedIndex[k] = rounded.size();
    tags.push_back({glm::dvec2(4.0 * static_cast<double>(rounded.size()), 0.0), glm::dvec2(1.0)});
    rounded.push_back(surface.patches[k]);
    surfaceIndex.push_back(k);
  }
  RoundedMesh out;
  out.mesh = tessellateAdaptive(rounded, options, tags);
  const std::size_t meshVertices = out.mesh.positions.size();
  std::vector<std::size_t> vertexPatch(meshVertices);
  std::vector<glm::dvec2> vertexUv(meshVertices);
  std::vector<std::optional<FaceChart>> charts(poly.faces.size());
  for (std::size_t i = 0; i < meshVertices; ++i) {
    const glm::dvec2 tag = out.mesh.texCoords[i];
    const double k = std::floor(tag.x / 4.0);
    vertexPatch[i] = static_cast<std::size_t>(k);
    vertexUv[i] = glm::dvec2(tag.x - 4.0 * k, tag.y);
    const RoundedPatchInfo& info = surface.info[surfaceIndex[vertexPatch[i]]];
    const auto f = static_cast<std::size_t>(info.face);
    if (!charts[f]) charts[f] = faceChart(poly, f);
    out.mesh.texCoords[i] = roundedTexCoord(info, *charts[f], surface.radius, out.mesh.positions[i]);
  }
  for (std::size_t t = 0; t < out.mesh.indices.size(); t += 3)
    out.triangleFaces.push_back(surface.info[surfaceIndex[vertexPatch[out.mesh.indices[t]]]].face);
  // Each rounded patch's vertices, so that an outline looks only at those of its own patches.
  std::vector<std::vector<std::size_t>> patchVertices(rounded.size());
  for (std::size_t i = 0; i < meshVertices; ++i) patchVertices[vertexPatch[i]].push_back(i);

  // Faces next to the rounding: their outlines, with every vertex the rounded patches have there.
  std::vector<bool> outlined(poly.faces.size(), false);
  for (const FaceOutline& outline : surface.outlines) {
    outlined[static_cast<std::size_t>(outline.face)] = true;
    std::vector<glm::dvec3> contour;
    for (const FaceOutline::Piece& piece : outline.pieces) {
      contour.push_back(piece.start);
      std::vector<std::pair<double, glm::dvec3>> inside;
      const glm::dvec3 direction = piece.end - piece.start;
      for (const PatchSideRef& ref : piece.along) {
        for (std::size_t i : patchVertices[roundedIndex[ref.patch]]) {
          if (!onSide(ref.side, vertexUv[i])) continue;
          const glm::dvec3& p = out.mesh.positions[i];
          if (p == piece.start || p == piece.end) continue;
          // Only the part of the patch's side this piece runs along (a fillet's side runs on
          // past a cap's).
          const double along = glm::dot(p - piece.start, direction);
          if (!(along > 0.0 && along < glm::dot(direction, direction))) continue;
          inside.emplace_back(along, p);
        }
      }
      if (piece.along.empty()) {
        // A straight side no patch runs along, which a patch may still reach when the face
        // between them is used up (R half its width): a cap's side then meets a strip's side
        // directly. Its vertices on the segment go into the outline too, so the two share them.
        const double length2 = glm::dot(direction, direction);
        for (std::size_t i = 0; i < meshVertices && length2 > 0.0; ++i) {
          const glm::dvec3& p = out.mesh.positions[i];
          const double along = glm::dot(p - piece.start, direction);
          if (!(along > 0.0 && along < length2)) continue;
          const glm::dvec3 off = p - piece.start - (along / length2) * direction;
          if (glm::dot(off, off) > 1e-24 * length2) continue;
          inside.emplace_back(along, p);
        }
      }
      std::sort(inside.begin(), inside.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t j = 0; j < inside.size(); ++j)
        if (j == 0 || inside[j].second != inside[j - 1].second) contour.push_back(inside[j].second);
    }
    appendFlatPolygon(poly, static_cast<std::size_t>(outline.face), contour, out, outline.normal);
  }
  // The faces no rounding reaches, as they are.
  for (std::size_t f = 0; f < poly.faces.size(); ++f) {
    if (outlined[f]) continue;
    std::vector<glm::dvec3> contour;
    for (std::uint32_t v : poly.faces[f].vertices) contour.push_back(poly.vertices[v]);
    appendFlatPolygon(poly, f, contour, out);
  }
  return out;
}

}  // namespace glass::geometry
