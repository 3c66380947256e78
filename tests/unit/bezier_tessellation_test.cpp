// Tessellation: mesh structure, orientation, accuracy of the adaptive criteria, and no cracks
// between adaptive neighbours inside a patch and across patches.
#include "glass/geometry/bezier_constructions.h"
#include "glass/geometry/tessellation.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

namespace geo = glass::geometry;

namespace {

constexpr double kPi = std::numbers::pi;

using PositionKey = std::array<double, 3>;
using EdgeKey = std::pair<PositionKey, PositionKey>;

PositionKey keyOf(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

// How often each directed edge occurs, by the exact positions of its ends.
std::map<EdgeKey, int> directedEdges(const geo::TriangleMesh& mesh) {
  std::map<EdgeKey, int> edges;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3& a = mesh.positions[mesh.indices[3 * t + k]];
      const glm::dvec3& b = mesh.positions[mesh.indices[3 * t + (k + 1) % 3]];
      ++edges[{keyOf(a), keyOf(b)}];
    }
  return edges;
}

// A closed, consistently oriented surface without cracks: every edge appears exactly once in each
// direction.
void checkWatertight(const geo::TriangleMesh& mesh) {
  const auto edges = directedEdges(mesh);
  int unmatched = 0;
  for (const auto& [edge, count] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (count != 1 || back == edges.end() || back->second != 1) ++unmatched;
  }
  CHECK(unmatched == 0);
}

// For an open single patch: interior edges are used by two triangles (once each way), and the
// only edges used once are on the patch boundary.
void checkConforming(const geo::TriangleMesh& mesh) {
  const auto edges = directedEdges(mesh);
  std::map<EdgeKey, std::pair<std::uint32_t, std::uint32_t>> indicesOf;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
      indicesOf[{keyOf(mesh.positions[a]), keyOf(mesh.positions[b])}] = {a, b};
    }
  int inner = 0, bad = 0;
  for (const auto& [edge, count] : edges) {
    if (count != 1) ++bad;
    if (edges.count({edge.second, edge.first})) {
      ++inner;
      continue;
    }
    const auto [a, b] = indicesOf[edge];
    const glm::dvec2 ta = mesh.texCoords[a], tb = mesh.texCoords[b];
    const bool onSide = (ta.x == tb.x && (ta.x == 0.0 || ta.x == 1.0)) || (ta.y == tb.y && (ta.y == 0.0 || ta.y == 1.0));
    if (!onSide) ++bad;
  }
  CHECK(inner > 0);
  CHECK(bad == 0);
}

// The largest distance between mesh points and the surface at the same parameters (the texture
// coordinates are the parameters), sampled inside every triangle.
double parametricError(const geo::TriangleMesh& mesh, const geo::BezierSurface& patch) {
  double worst = 0.0;
  static constexpr double kBary[][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5},
                                        {0.7, 0.2, 0.1}, {0.1, 0.7, 0.2}, {0.2, 0.1, 0.7}};
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1], i2 = mesh.indices[3 * t + 2];
    for (const auto& b : kBary) {
      const glm::dvec3 p = b[0] * mesh.positions[i0] + b[1] * mesh.positions[i1] + b[2] * mesh.positions[i2];
      const glm::dvec2 uv = b[0] * mesh.texCoords[i0] + b[1] * mesh.texCoords[i1] + b[2] * mesh.texCoords[i2];
      worst = std::max(worst, glm::length(p - patch.evaluate(uv.x, uv.y)));
    }
  }
  return worst;
}

geo::BezierSurface bumpyBicubic() {
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) points.emplace_back(i, j, (i == 1 || i == 2) && (j == 1 || j == 2) ? 2.5 : 0.3 * i);
  return geo::BezierSurface(3, 3, points);
}

}  // namespace

TEST_CASE("tessellation: a uniform grid, oriented with its normals") {
  const geo::BezierSurface patch = bumpyBicubic();
  const geo::TriangleMesh mesh = geo::tessellateUniform(patch, 6, 4);
  CHECK(mesh.positions.size() == 7 * 5);
  CHECK(mesh.triangleCount() == 2 * 6 * 4);
  CHECK(mesh.normals.size() == mesh.positions.size());
  CHECK(mesh.texCoords.size() == mesh.positions.size());
  CHECK(mesh.texCoords.front() == glm::dvec2(0, 0));
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                     c = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::dvec3 facet = glm::cross(b - a, c - a);
    CHECK(glm::dot(facet, mesh.normals[mesh.indices[3 * t]]) > 0.0);
  }
  for (const glm::dvec3& n : mesh.normals) CHECK(std::abs(glm::length(n) - 1.0) < 1e-12);
  checkConforming(mesh);
  // Texture rectangles map the parameters.
  const geo::TriangleMesh shifted = geo::tessellateUniform(patch, 2, 2, geo::TextureRect{{0.5, 0.25}, {0.25, 0.5}});
  CHECK(shifted.texCoords.back() == glm::dvec2(0.75, 0.75));
}

TEST_CASE("tessellation: uniform patches of a closed surface meet without cracks") {
  checkWatertight(geo::tessellateUniform(geo::spherePatches(1.0), 5, 5));
  checkWatertight(geo::tessellateUniform(geo::torusPatches(2.0, 0.7), 3, 3));
}

TEST_CASE("tessellation: adaptive to an object-space tolerance, conforming, within the tolerance") {
  const geo::BezierSurface patch = bumpyBicubic();
  std::size_t previousCount = 0;
  for (double tolerance : {0.1, 0.01, 0.001}) {
    geo::AdaptiveOptions options;
    options.criterion = geo::ObjectSpaceTolerance{tolerance};
    options.maxDepth = 10;
    const geo::TriangleMesh mesh = geo::tessellateAdaptive(patch, options);
    checkConforming(mesh);
    CHECK(parametricError(mesh, patch) <= tolerance);
    CHECK(mesh.triangleCount() > previousCount);
    previousCount = mesh.triangleCount();
  }
  // A flat patch needs no subdivision at all.
  std::vector<glm::dvec3> plane;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) plane.emplace_back(i, j, 0.5 * i - 0.25 * j);
  CHECK(geo::tessellateAdaptive(geo::BezierSurface(3, 3, plane), geo::AdaptiveOptions{}).triangleCount() == 2);
}

TEST_CASE("tessellation: adaptive cells of different sizes leave no T-junctions") {
  // A patch flat on one half and curved on the other subdivides unevenly.
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) points.emplace_back(i, j, i == 3 && j == 3 ? 4.0 : 0.0);
  const geo::BezierSurface patch(3, 3, points);
  geo::AdaptiveOptions options;
  options.criterion = geo::ObjectSpaceTolerance{0.002};
  const geo::TriangleMesh mesh = geo::tessellateAdaptive(patch, options);
  checkConforming(mesh);
  // Uneven indeed: some triangles are far larger than others.
  double smallest = 1e9, largest = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec2 a = mesh.texCoords[mesh.indices[3 * t]], b = mesh.texCoords[mesh.indices[3 * t + 1]],
                     c = mesh.texCoords[mesh.indices[3 * t + 2]];
    const double area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    smallest = std::min(smallest, area);
    largest = std::max(largest, area);
  }
  CHECK(largest > 16 * smallest);
}

TEST_CASE("tessellation: adaptive patches of a closed surface meet without cracks") {
  geo::AdaptiveOptions options;
  options.criterion = geo::ObjectSpaceTolerance{1e-3};
  const auto torus = geo::torusPatches(2.0, 0.7);
  const geo::TriangleMesh torusMesh = geo::tessellateAdaptive(torus, options);
  checkWatertight(torusMesh);
  // Rational patches: the estimate keeps mesh points near the torus.
  for (std::size_t t = 0; t < torusMesh.triangleCount(); ++t) {
    const glm::dvec3 centroid = (torusMesh.positions[torusMesh.indices[3 * t]] + torusMesh.positions[torusMesh.indices[3 * t + 1]] +
                                 torusMesh.positions[torusMesh.indices[3 * t + 2]]) / 3.0;
    CHECK(std::abs(std::hypot(std::hypot(centroid.x, centroid.z) - 2.0, centroid.y) - 0.7) <= 1e-3);
  }
  // Patches of unequal size subdivide to different depths, so shared edges get vertices from both
  // sides: a torus cut at uneven angles.
  const std::array<double, 5> cuts = {0.0, 0.5, 2.0, 4.0, 2 * kPi};
  std::vector<geo::BezierSurface> uneven;
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l) uneven.push_back(geo::torusPatch(2.0, 0.7, cuts[k], cuts[k + 1], cuts[l], cuts[l + 1]));
  checkWatertight(geo::tessellateAdaptive(uneven, options));
  // The sphere: rational patches meeting at the poles, subdivided to different depths near the
  // poles and the equator; still crack-free.
  options.criterion = geo::ObjectSpaceTolerance{2e-4};
  checkWatertight(geo::tessellateAdaptive(geo::spherePatches(1.0), options));
}

TEST_CASE("tessellation: adaptive to a size on screen") {
  const geo::BezierSurface patch = bumpyBicubic();
  // An orthographic view, 100 pixels per unit: half a pixel is 0.005 units.
  geo::ScreenSpaceTolerance screen;
  screen.project = [](const glm::dvec3& p) { return glm::dvec2(100.0 * p.x, 100.0 * p.y); };
  screen.maxDeviationPixels = 0.5;
  geo::AdaptiveOptions options;
  options.criterion = screen;
  options.maxDepth = 10;
  const geo::TriangleMesh fine = geo::tessellateAdaptive(patch, options);
  checkConforming(fine);
  // Only x and y are seen on screen: compare the projected error.
  double worst = 0;
  for (std::size_t t = 0; t < fine.triangleCount(); ++t) {
    const std::uint32_t i0 = fine.indices[3 * t], i1 = fine.indices[3 * t + 1], i2 = fine.indices[3 * t + 2];
    const glm::dvec3 p = (fine.positions[i0] + fine.positions[i1] + fine.positions[i2]) / 3.0;
    const glm::dvec2 uv = (fine.texCoords[i0] + fine.texCoords[i1] + fine.texCoords[i2]) / 3.0;
    const glm::dvec3 s = patch.evaluate(uv.x, uv.y);
    worst = std::max(worst, 100.0 * glm::length(glm::dvec2(p - s)));
  }
  CHECK(worst <= 0.5);

  // A size limit: no triangle spans more than 20 pixels.
  screen.maxDeviationPixels = 1e9;
  screen.maxEdgePixels = 20.0;
  options.criterion = screen;
  const geo::TriangleMesh sized = geo::tessellateAdaptive(patch, options);
  for (std::size_t t = 0; t < sized.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 d = sized.positions[sized.indices[3 * t + k]] - sized.positions[sized.indices[3 * t + (k + 1) % 3]];
      CHECK(100.0 * std::max(std::abs(d.x), std::abs(d.y)) <= 20.0 + 1e-9);
    }

  // Perspective: the same patch far away needs fewer triangles.
  const auto perspective = [](double distance) {
    return [distance](const glm::dvec3& p) { return glm::dvec2(500.0 * p.x / (p.z + distance), 500.0 * p.y / (p.z + distance)); };
  };
  screen.maxEdgePixels = 0.0;
  screen.maxDeviationPixels = 0.5;
  screen.project = perspective(10.0);
  options.criterion = screen;
  const std::size_t nearCount = geo::tessellateAdaptive(patch, options).triangleCount();
  screen.project = perspective(200.0);
  options.criterion = screen;
  const std::size_t farCount = geo::tessellateAdaptive(patch, options).triangleCount();
  CHECK(farCount < nearCount);
}

TEST_CASE("tessellation: curves, uniform and adaptive") {
  const geo::BezierCurve arc = geo::circularArc(0.0, 2.5);
  const geo::Polyline uniform = geo::tessellateUniform(arc, 10);
  CHECK(uniform.points.size() == 11);
  CHECK(uniform.parameters.back() == 1.0);
  geo::AdaptiveOptions options;
  options.criterion = geo::ObjectSpaceTolerance{1e-4};
  const geo::Polyline adaptive = geo::tessellateAdaptive(arc, options);
  CHECK(adaptive.points.size() > 10);
  CHECK(adaptive.points.front() == arc.evaluate(0.0));
  CHECK(adaptive.points.back() == arc.evaluate(1.0));
  for (std::size_t k = 0; k + 1 < adaptive.points.size(); ++k) {
    CHECK(adaptive.parameters[k] < adaptive.parameters[k + 1]);
    CHECK(std::abs(glm::length(adaptive.points[k]) - 1.0) < 1e-12);
    // The chord's middle is within the tolerance of the circle.
    CHECK(1.0 - glm::length(0.5 * (adaptive.points[k] + adaptive.points[k + 1])) <= 1e-4);
  }
}
