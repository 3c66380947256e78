#include "glass/geometry/ifs3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "box_counting.h"
#include "chaos_game.h"
#include "glass/geometry/portable_math.h"

namespace glass::geometry {

IfsColor partColor3(const IteratedFunctionSystem3& ifs, std::size_t part) {
  if (part < ifs.maps.size() && ifs.maps[part].color) return *ifs.maps[part].color;
  return partColor(IteratedFunctionSystem{}, part);  // the 2D palette
}

std::optional<std::vector<double>> chaosGameProbabilities3(const IteratedFunctionSystem3& ifs) {
  std::vector<std::optional<double>> given;
  std::vector<double> volumes;
  for (const IfsMap3& map : ifs.maps) {
    given.push_back(map.probability);
    volumes.push_back(std::abs(map.transform.determinant()));
  }
  return chaos::probabilities(given, volumes);
}

std::optional<glm::dvec3> fixedPoint3(const Affine3& map) {
  // (I - L) x = t by Cramer's rule.
  glm::dmat3 a = glm::dmat3(1.0) - map.linearPart();
  const double det = glm::determinant(a);
  if (std::abs(det) < 1e-12) return std::nullopt;
  const glm::dvec3 t = map.translationPart();
  glm::dvec3 x;
  for (int k = 0; k < 3; ++k) {
    glm::dmat3 replaced = a;
    replaced[k] = t;
    x[k] = glm::determinant(replaced) / det;
  }
  return x;
}

std::vector<IfsPoint3> chaosGamePoints3(const IteratedFunctionSystem3& ifs, const std::vector<double>& probabilities,
                                        std::uint64_t count, std::uint64_t seed) {
  std::vector<IfsPoint3> points;
  if (ifs.maps.empty() || probabilities.size() != ifs.maps.size()) return points;
  points.reserve(count);
  glm::dvec3 start(0.0);
  for (const IfsMap3& map : ifs.maps) {
    if (auto fixed = fixedPoint3(map.transform)) {
      start = *fixed;
      break;
    }
  }
  chaos::walk(
      probabilities, start, count, seed,
      [&ifs](std::size_t i, const glm::dvec3& p) { return ifs.maps[i].transform.apply(p); },
      [&points](const glm::dvec3& p, int part) { points.push_back({p, part}); });
  return points;
}

std::uint64_t ifs3BaseCopies(const IteratedFunctionSystem3& ifs, int depth) {
  const std::uint64_t r = ifs.maps.size();
  std::uint64_t copies = 1;
  for (int i = 0; i < depth; ++i) {
    if (r != 0 && copies > std::numeric_limits<std::uint64_t>::max() / r) return std::numeric_limits<std::uint64_t>::max();
    copies *= r;
  }
  return copies;
}

std::vector<IfsComposite3> ifsComposites3(const IteratedFunctionSystem3& ifs, int depth) {
  // Level by level: the composites of depth k + 1 are c o f_i for each composite c of depth k,
  // listed so that the outermost map varies slowest, as the recursion visits them.
  std::vector<IfsComposite3> level{{Affine3::identity(), -1}};
  for (int k = 0; k < depth; ++k) {
    std::vector<IfsComposite3> next;
    next.reserve(level.size() * ifs.maps.size());
    for (const IfsComposite3& c : level) {
      for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
        next.push_back({c.transform * ifs.maps[i].transform, c.part < 0 ? static_cast<int>(i) : c.part});
      }
    }
    level = std::move(next);
  }
  return level;
}

namespace {

std::vector<Triangle3> unitCube() {
  const glm::dvec3 v[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // Each face as a counter-clockwise quad seen from outside, split along a diagonal.
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  std::vector<Triangle3> out;
  for (const auto& q : quads) {
    out.push_back({v[q[0]], v[q[1]], v[q[2]]});
    out.push_back({v[q[0]], v[q[2]], v[q[3]]});
  }
  return out;
}

std::vector<Triangle3> unitTetrahedron() {
  const glm::dvec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  return {{o, y, x}, {o, x, z}, {o, z, y}, {x, y, z}};
}

// Points of the attractor that lie on its convex hull: the extreme ones of a chaos-game sample and
// of the composites' fixed points along 400 directions spread over the sphere (a Fibonacci
// lattice).
std::vector<glm::dvec3> attractorExtremes(const IteratedFunctionSystem3& ifs) {
  std::vector<glm::dvec3> sample;
  int length = 1;
  while (length < 5 && ifs3BaseCopies(ifs, length + 1) <= 4096) ++length;
  for (int depth = 1; depth <= length; ++depth) {
    for (const IfsComposite3& c : ifsComposites3(ifs, depth)) {
      if (auto p = fixedPoint3(c.transform)) sample.push_back(*p);
    }
  }
  if (auto probabilities = chaosGameProbabilities3(ifs)) {
    for (const IfsPoint3& p : chaosGamePoints3(ifs, *probabilities, 50000, 1)) sample.push_back(p.position);
  }
  std::vector<glm::dvec3> extremes;
  if (sample.empty()) return extremes;
  constexpr int kDirections = 400;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::set<std::size_t> chosen;
  for (int k = 0; k < kDirections; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / kDirections, r = std::sqrt(1.0 - z * z);
    const glm::dvec3 d{r * portable::cos(golden * k), r * portable::sin(golden * k), z};
    std::size_t best = 0;
    for (std::size_t i = 1; i < sample.size(); ++i) {
      if (glm::dot(sample[i], d) > glm::dot(sample[best], d)) best = i;
    }
    chosen.insert(best);
  }
  for (std::size_t i : chosen) extremes.push_back(sample[i]);
  return extremes;
}

}  // namespace

std::vector<Triangle3> convexHull(const std::vector<glm::dvec3>& points) {
  if (points.size() < 4) return {};
  double scale = 0.0;
  for (const glm::dvec3& p : points) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const double eps = 1e-10 * std::max(scale, 1e-300);
  // A first tetrahedron: two far points, the farthest from their line, the farthest from their plane.
  std::size_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (glm::distance(points[i], points[i0]) > glm::distance(points[i1], points[i0])) i1 = i;
  }
  const glm::dvec3 line = points[i1] - points[i0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (glm::length(glm::cross(points[i] - points[i0], line)) > glm::length(glm::cross(points[i2] - points[i0], line))) i2 = i;
  }
  const glm::dvec3 planeNormal = glm::cross(line, points[i2] - points[i0]);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::abs(glm::dot(points[i] - points[i0], planeNormal)) > std::abs(glm::dot(points[i3] - points[i0], planeNormal))) i3 = i;
  }
  const double volume = std::abs(glm::dot(points[i3] - points[i0], planeNormal));
  if (!(volume > eps * eps * eps) || glm::length(line) <= eps) return {};

  struct Face {
    std::size_t a, b, c;
  };
  std::vector<Face> faces;
  const glm::dvec3 inside = (points[i0] + points[i1] + points[i2] + points[i3]) / 4.0;
  auto normalOf = [&](const Face& f) { return glm::cross(points[f.b] - points[f.a], points[f.c] - points[f.a]); };
  auto addFace = [&](std::size_t a, std::size_t b, std::size_t c) {
    Face f{a, b, c};
    if (glm::dot(normalOf(f), inside - points[a]) > 0.0) std::swap(f.b, f.c);  // face outward
    faces.push_back(f);
  };
  addFace(i0, i1, i2);
  addFace(i0, i1, i3);
  addFace(i0, i2, i3);
  addFace(i1, i2, i3);

  for (std::size_t p = 0; p < points.size(); ++p) {
    if (p == i0 || p == i1 || p == i2 || p == i3) continue;
    std::vector<bool> visible(faces.size());
    bool any = false;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const glm::dvec3 n = normalOf(faces[f]);
      const double length = glm::length(n);
      visible[f] = length > 0.0 && glm::dot(n / length, points[p] - points[faces[f].a]) > eps;
      any = any || visible[f];
    }
    if (!any) continue;
    std::set<std::pair<std::size_t, std::size_t>> visibleEdges;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!visible[f]) continue;
      visibleEdges.insert({faces[f].a, faces[f].b});
      visibleEdges.insert({faces[f].b, faces[f].c});
      visibleEdges.insert({faces[f].c, faces[f].a});
    }
    std::vector<Face> kept;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!visible[f]) kept.push_back(faces[f]);
    }
    // The horizon: edges of visible faces whose twin belongs to a hidden face. Each makes a new
    // face with p, keeping the visible face's orientation.
    for (const auto& [u, v] : visibleEdges) {
      if (!visibleEdges.contains({v, u})) kept.push_back({u, v, p});
    }
    faces = std::move(kept);
  }
  std::vector<Triangle3> out;
  for (const Face& f : faces) out.push_back({points[f.a], points[f.b], points[f.c]});
  return out;
}

std::vector<Triangle3> basePolyhedron(const IteratedFunctionSystem3& ifs) {
  switch (ifs.base) {
    case IfsBase3::Cube: return unitCube();
    case IfsBase3::Tetrahedron: return unitTetrahedron();
    case IfsBase3::Hull: {
      std::vector<Triangle3> hull = convexHull(attractorExtremes(ifs));
      return hull.empty() ? unitCube() : hull;  // a flat attractor has no hull: the cube stands in
    }
    case IfsBase3::Model: return ifs.baseModel;
  }
  return unitCube();
}

std::vector<RebuildTriangle> polyhedralRebuild(const IteratedFunctionSystem3& ifs, int depth, std::uint64_t limit,
                                               std::string& problem) {
  const std::vector<Triangle3> base = basePolyhedron(ifs);
  const std::uint64_t copies = ifs3BaseCopies(ifs, depth);
  if (depth < 0 || copies > limit / std::max<std::uint64_t>(base.size(), 1)) {
    problem = "depth " + std::to_string(depth) + " would draw " + std::to_string(base.size()) + " x " +
              std::to_string(ifs.maps.size()) + "^" + std::to_string(depth) + " triangles, more than the limit of " +
              std::to_string(limit) + "; lower the depth";
    return {};
  }
  std::vector<RebuildTriangle> out;
  out.reserve(copies * base.size());
  for (const IfsComposite3& c : ifsComposites3(ifs, depth)) {
    const bool reverses = c.transform.determinant() < 0.0;
    for (const Triangle3& t : base) {
      RebuildTriangle r;
      r.part = c.part;
      r.corners = {c.transform.apply(t.a), c.transform.apply(t.b), c.transform.apply(t.c)};
      // A map with negative determinant turns the polyhedron inside out: swap two corners so the
      // triangle is counter-clockwise from outside again.
      if (reverses) std::swap(r.corners.b, r.corners.c);
      const glm::dvec3 n = glm::cross(r.corners.b - r.corners.a, r.corners.c - r.corners.a);
      const double length = glm::length(n);
      if (!(length > 0.0) || !std::isfinite(length)) continue;
      r.normal = n / length;
      out.push_back(r);
    }
  }
  return out;
}

std::optional<double> similarityRatio3(const Affine3& map) {
  const glm::dmat3 l = map.linearPart();
  const glm::dmat3 gram = glm::transpose(l) * l;
  const double r2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.0;
  if (r2 == 0.0) return 0.0;
  constexpr double kTolerance = 1e-9;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (std::abs(gram[i][j] - (i == j ? r2 : 0.0)) > kTolerance * r2) return std::nullopt;
    }
  return std::sqrt(r2);
}

std::optional<BoxCountingEstimate> boxCountingDimension3(std::span<const glm::dvec3> points) {
  if (points.size() < 1000) return std::nullopt;
  glm::dvec3 lo = points[0], hi = points[0];
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(side > 0.0) || !std::isfinite(side)) return std::nullopt;
  return box_counting::estimate(points.size(), side, 21, [&](int level, std::size_t i) {
    const double cells = std::ldexp(1.0, level);
    const std::uint64_t maxCell = (std::uint64_t{1} << level) - 1;
    auto cell = [&](double v, double from) { return std::min(static_cast<std::uint64_t>((v - from) / side * cells), maxCell); };
    return (cell(points[i].x, lo.x) << 42) | (cell(points[i].y, lo.y) << 21) | cell(points[i].z, lo.z);
  });
}

IfsDimensionReport ifsDimension3(const IteratedFunctionSystem3& ifs, std::uint64_t points, std::uint64_t seed) {
  return box_counting::dimensionReport(
      ifs.maps.size(), [&](std::size_t i) { return similarityRatio3(ifs.maps[i].transform); },
      [&](IfsDimensionReport& report) {
        const auto probabilities = chaosGameProbabilities3(ifs);
        if (!probabilities) {
          report.problem = "the maps' probabilities are invalid";
          return;
        }
        std::vector<glm::dvec3> cloud;
        cloud.reserve(points);
        for (const IfsPoint3& p : chaosGamePoints3(ifs, *probabilities, points, seed)) cloud.push_back(p.position);
        report.boxCounting = boxCountingDimension3(cloud);
        if (!report.boxCounting) report.problem = "the attractor is too small or too thin for box counting";
      });
}

}  // namespace glass::geometry
