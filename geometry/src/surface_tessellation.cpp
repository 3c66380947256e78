// Uniform and adaptive tessellation of Bezier patches (see tessellation.h for the guarantees).
#include "glass/geometry/tessellation.h"

#include "flatness.h"
#include "patch_boundaries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace glass::geometry {

void TriangleMesh::append(const TriangleMesh& other) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  texCoords.insert(texCoords.end(), other.texCoords.begin(), other.texCoords.end());
  for (std::uint32_t index : other.indices) indices.push_back(base + index);
}

namespace {

using detail::PatchBoundaries;
using detail::SidePosition;

// The mesh vertices of one patch, addressed by integer grid coordinates (x, y) with
// u = x / stepsU, v = y / stepsV; each is created once, on first use.
class PatchVertices {
 public:
  PatchVertices(const BezierSurface& patch, std::size_t patchIndex, const PatchBoundaries& boundaries,
                std::int64_t stepsU, std::int64_t stepsV, const TextureRect& texture, TriangleMesh& mesh)
      : patch_(patch), patchIndex_(patchIndex), boundaries_(boundaries), stepsU_(stepsU), stepsV_(stepsV),
        texture_(texture), mesh_(mesh) {}

  std::uint32_t at(std::int64_t x, std::int64_t y) {
    const std::int64_t key = x * (stepsV_ + 1) + y;
    const auto found = indices_.find(key);
    if (found != indices_.end()) return found->second;
    const double u = static_cast<double>(x) / static_cast<double>(stepsU_);
    const double v = static_cast<double>(y) / static_cast<double>(stepsV_);
    const auto index = static_cast<std::uint32_t>(mesh_.positions.size());
    mesh_.positions.push_back(position(x, y, u, v));
    mesh_.normals.push_back(patch_.normal(u, v));
    mesh_.texCoords.push_back(texture_.origin + texture_.size * glm::dvec2(u, v));
    indices_.emplace(key, index);
    return index;
  }

  // A triangle, unless two of its corners coincide (as at a collapsed row of the net).
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto& p = mesh_.positions;
    if (p[a] == p[b] || p[b] == p[c] || p[c] == p[a]) return;
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  // The quad a b c d (counter-clockwise in the parameter plane) as two triangles, split along its
  // shorter diagonal.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    const auto& p = mesh_.positions;
    if (glm::length(p[a] - p[c]) <= glm::length(p[b] - p[d])) {
      triangle(a, b, c);
      triangle(a, c, d);
    } else {
      triangle(a, b, d);
      triangle(b, c, d);
    }
  }

 private:
  // Points on the patch boundary come from the canonical boundary curve, so that a neighbouring
  // patch produces the same bits there; every point of a collapsed side (corners included) is its
  // one point.
  glm::dvec3 position(std::int64_t x, std::int64_t y, double u, double v) const {
    const std::pair<bool, PatchSide> onSides[4] = {
        {x == 0, PatchSide::UMin}, {x == stepsU_, PatchSide::UMax}, {y == 0, PatchSide::VMin}, {y == stepsV_, PatchSide::VMax}};
    for (const auto& [on, side] : onSides)
      if (on && boundaries_.collapsed(patchIndex_, side)) return boundaries_.point(patchIndex_, side, {});
    if (x == 0) return boundaries_.point(patchIndex_, PatchSide::UMin, SidePosition{y, stepsV_});
    if (x == stepsU_) return boundaries_.point(patchIndex_, PatchSide::UMax, SidePosition{y, stepsV_});
    if (y == 0) return boundaries_.point(patchIndex_, PatchSide::VMin, SidePosition{x, stepsU_});
    if (y == stepsV_) return boundaries_.point(patchIndex_, PatchSide::VMax, SidePosition{x, stepsU_});
    return patch_.evaluate(u, v);
  }

  const BezierSurface& patch_;
  std::size_t patchIndex_;
  const PatchBoundaries& boundaries_;
  std::int64_t stepsU_, stepsV_;
  TextureRect texture_;
  TriangleMesh& mesh_;
  std::unordered_map<std::int64_t, std::uint32_t> indices_;
};

TextureRect textureOf(std::span<const TextureRect> textures, std::size_t patch) {
  return patch < textures.size() ? textures[patch] : TextureRect{};
}

// ---- adaptive: a quadtree of parameter cells per patch ----

struct Cell {
  std::int64_t x0, y0, size;
};

// The grid points of one patch that are mesh vertices, searchable along rows and columns.
class VertexSet {
 public:
  void add(std::int64_t x, std::int64_t y) {
    byRow_[y].insert(x);
    byColumn_[x].insert(y);
  }
  // The x of vertices on row y with from <= x <= to, ascending.
  std::vector<std::int64_t> onRow(std::int64_t y, std::int64_t from, std::int64_t to) const {
    return range(byRow_, y, from, to);
  }
  std::vector<std::int64_t> onColumn(std::int64_t x, std::int64_t from, std::int64_t to) const {
    return range(byColumn_, x, from, to);
  }

 private:
  using Lines = std::map<std::int64_t, std::set<std::int64_t>>;
  static std::vector<std::int64_t> range(const Lines& lines, std::int64_t line, std::int64_t from, std::int64_t to) {
    std::vector<std::int64_t> result;
    const auto found = lines.find(line);
    if (found == lines.end()) return result;
    for (auto it = found->second.lower_bound(from); it != found->second.end() && *it <= to; ++it) result.push_back(*it);
    return result;
  }
  Lines byRow_, byColumn_;
};

struct PatchQuadtree {
  std::vector<Cell> leaves;
  VertexSet vertices;
};

void splitUntilFlat(const BezierSurface& piece, Cell cell, int depth, const AdaptiveOptions& options,
                    PatchQuadtree& tree) {
  if (depth >= options.maxDepth || detail::isFlatEnough(piece, options)) {
    tree.leaves.push_back(cell);
    const std::int64_t x1 = cell.x0 + cell.size, y1 = cell.y0 + cell.size;
    tree.vertices.add(cell.x0, cell.y0);
    tree.vertices.add(x1, cell.y0);
    tree.vertices.add(x1, y1);
    tree.vertices.add(cell.x0, y1);
    return;
  }
  const std::int64_t half = cell.size / 2;
  const auto [lowU, highU] = piece.subdivideU(0.5);
  const auto [lowULowV, lowUHighV] = lowU.subdivideV(0.5);
  const auto [highULowV, highUHighV] = highU.subdivideV(0.5);
  splitUntilFlat(lowULowV, {cell.x0, cell.y0, half}, depth + 1, options, tree);
  splitUntilFlat(highULowV, {cell.x0 + half, cell.y0, half}, depth + 1, options, tree);
  splitUntilFlat(lowUHighV, {cell.x0, cell.y0 + half, half}, depth + 1, options, tree);
  splitUntilFlat(highUHighV, {cell.x0 + half, cell.y0 + half, half}, depth + 1, options, tree);
}

// The positions (along the side's own direction) of the vertices a quadtree has on a patch side.
std::vector<std::int64_t> sideVertices(const PatchQuadtree& tree, PatchSide side, std::int64_t steps) {
  switch (side) {
    case PatchSide::UMin: return tree.vertices.onColumn(0, 0, steps);
    case PatchSide::UMax: return tree.vertices.onColumn(steps, 0, steps);
    case PatchSide::VMin: return tree.vertices.onRow(0, 0, steps);
    case PatchSide::VMax: return tree.vertices.onRow(steps, 0, steps);
  }
  return {};
}

void addSideVertex(PatchQuadtree& tree, PatchSide side, std::int64_t position, std::int64_t steps) {
  switch (side) {
    case PatchSide::UMin: tree.vertices.add(0, position); break;
    case PatchSide::UMax: tree.vertices.add(steps, position); break;
    case PatchSide::VMin: tree.vertices.add(position, 0); break;
    case PatchSide::VMax: tree.vertices.add(position, steps); break;
  }
}

// A leaf cell as triangles: two if no neighbour put a vertex on its sides, otherwise a fan around
// its centre through every vertex on its boundary, in counter-clockwise order.
void triangulateLeaf(const Cell& cell, const VertexSet& vertices, PatchVertices& mesh) {
  const std::int64_t x0 = cell.x0, y0 = cell.y0, x1 = cell.x0 + cell.size, y1 = cell.y0 + cell.size;
  std::vector<std::pair<std::int64_t, std::int64_t>> loop;
  for (std::int64_t x : vertices.onRow(y0, x0, x1 - 1)) loop.emplace_back(x, y0);
  for (std::int64_t y : vertices.onColumn(x1, y0, y1 - 1)) loop.emplace_back(x1, y);
  const std::vector<std::int64_t> top = vertices.onRow(y1, x0 + 1, x1);
  for (auto it = top.rbegin(); it != top.rend(); ++it) loop.emplace_back(*it, y1);
  const std::vector<std::int64_t> left = vertices.onColumn(x0, y0 + 1, y1);
  for (auto it = left.rbegin(); it != left.rend(); ++it) loop.emplace_back(x0, *it);

  if (loop.size() == 4) {
    mesh.quad(mesh.at(x0, y0), mesh.at(x1, y0), mesh.at(x1, y1), mesh.at(x0, y1));
    return;
  }
  const std::uint32_t centre = mesh.at(x0 + cell.size / 2, y0 + cell.size / 2);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % loop.size()];
    mesh.triangle(centre, mesh.at(a.first, a.second), mesh.at(b.first, b.second));
  }
}

}  // namespace

TriangleMesh tessellateUniform(std::span<const BezierSurface> patches, int segmentsU, int segmentsV,
                               std::span<const TextureRect> textures) {
  TriangleMesh mesh;
  if (segmentsU < 1 || segmentsV < 1) return mesh;
  const PatchBoundaries boundaries(patches);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].empty()) continue;
    PatchVertices vertices(patches[p], p, boundaries, segmentsU, segmentsV, textureOf(textures, p), mesh);
    for (int i = 0; i < segmentsU; ++i)
      for (int j = 0; j < segmentsV; ++j) {
        const std::uint32_t a = vertices.at(i, j), b = vertices.at(i + 1, j);
        const std::uint32_t c = vertices.at(i + 1, j + 1), d = vertices.at(i, j + 1);
        vertices.triangle(a, b, c);
        vertices.triangle(a, c, d);
      }
  }
  return mesh;
}

TriangleMesh tessellateUniform(const BezierSurface& patch, int segmentsU, int segmentsV, const TextureRect& texture) {
  return tessellateUniform(std::span<const BezierSurface>(&patch, 1), segmentsU, segmentsV,
                           std::span<const TextureRect>(&texture, 1));
}

TriangleMesh tessellateAdaptive(std::span<const BezierSurface> patches, const AdaptiveOptions& requested,
                                std::span<const TextureRect> textures) {
  AdaptiveOptions options = requested;
  options.maxDepth = std::clamp(options.maxDepth, 0, 20);
  // One more binary digit than the deepest cell needs, so that every cell has a centre point.
  const std::int64_t steps = std::int64_t{2} << options.maxDepth;

  std::vector<PatchQuadtree> trees(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p)
    if (!patches[p].empty()) splitUntilFlat(patches[p], {0, 0, steps}, 0, options, trees[p]);

  // Each side of a shared boundary also takes the vertices the other side has there.
  const PatchBoundaries boundaries(patches);
  std::vector<std::array<std::vector<std::int64_t>, 4>> ownSideVertices(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (PatchSide side : detail::kAllSides)
      ownSideVertices[p][detail::sideIndex(side)] = sideVertices(trees[p], side, steps);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].empty()) continue;
    for (PatchSide side : detail::kAllSides) {
      for (const auto& neighbour : boundaries.neighbours(p, side)) {
        if (patches[neighbour.ref.patch].empty()) continue;
        for (std::int64_t position : ownSideVertices[neighbour.ref.patch][detail::sideIndex(neighbour.ref.side)])
          addSideVertex(trees[p], side, neighbour.opposite ? steps - position : position, steps);
      }
    }
  }

  TriangleMesh mesh;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].empty()) continue;
    PatchVertices vertices(patches[p], p, boundaries, steps, steps, textureOf(textures, p), mesh);
    for (const Cell& cell : trees[p].leaves) triangulateLeaf(cell, trees[p].vertices, vertices);
  }
  return mesh;
}

TriangleMesh tessellateAdaptive(const BezierSurface& patch, const AdaptiveOptions& options, const TextureRect& texture) {
  return tessellateAdaptive(std::span<const BezierSurface>(&patch, 1), options,
                            std::span<const TextureRect>(&texture, 1));
}

}  // namespace glass::geometry
