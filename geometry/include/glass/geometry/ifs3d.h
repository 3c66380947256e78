// Iterated function systems of space: the 3D counterpart of ifs.h (study guide, homework 3).
// r affine maps f_i(x) = L_i x + t_i of space; their attractor F = f_1(F) u ... u f_r(F) is a 3D
// fractal. As in the plane, it is drawn either by the chaos game (a cloud of points) or as the
// "polyhedral rebuild": a base polyhedron mapped through all r^n composites f_i1 o ... o f_in.
// Part i of F is f_i(F), the points (or polyhedra) that went through map i last, i.e. outermost.
//
// The file format is in ifs3d_format.h; the tool is `glass ifs3d`; the scene statement `ifs3d`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "glass/geometry/affine3d.h"
#include "glass/geometry/ifs.h"
#include "glass/geometry/ifs_dimension.h"

namespace glass::geometry {

struct IfsMap3 {
  Affine3 transform;
  std::optional<double> probability;  // none: see chaosGameProbabilities3
  std::optional<IfsColor> color;      // none: partColor's palette
};

struct Triangle3 {
  glm::dvec3 a, b, c;  // counter-clockwise seen from outside
};

// The step-0 polyhedron of the rebuild.
enum class IfsBase3 {
  Cube,         // the unit cube [0, 1]^3 (the default: homework clouds live in the unit cube)
  Tetrahedron,  // (0,0,0), (1,0,0), (0,1,0), (0,0,1)
  Hull,         // the convex hull of the attractor (of points sampled from it)
  Model,        // the triangles of an OBJ file (base "model.obj"), read by the scene library's
                // loadIfs3BaseModel (glass/scene/ifs3_base_model.h), which fills baseModel
};

struct IteratedFunctionSystem3 {
  std::string name;
  std::vector<IfsMap3> maps;
  IfsBase3 base = IfsBase3::Cube;
  // base "model.obj": the file name as written (relative to the .ifs3 file), where it was
  // written (1-based line and column of the quoted name, for file:line:col errors), and the
  // model's triangles once loaded.
  std::string baseModelPath;
  int baseModelLine = 0, baseModelColumn = 0;
  std::vector<Triangle3> baseModel;
};

// The colour of part i (the map's own, else the 2D palette's entry i).
IfsColor partColor3(const IteratedFunctionSystem3& ifs, std::size_t part);

// As chaosGameProbabilities in 2D, with |det L_i| the share of volume map i keeps.
std::optional<std::vector<double>> chaosGameProbabilities3(const IteratedFunctionSystem3& ifs);

struct IfsPoint3 {
  glm::dvec3 position;
  int part = 0;
};

// `count` points of the attractor by the seeded chaos game, starting at the fixed point of the
// first map that has a unique one and forgetting the start over 100 unrecorded steps.
std::vector<IfsPoint3> chaosGamePoints3(const IteratedFunctionSystem3& ifs, const std::vector<double>& probabilities,
                                        std::uint64_t count, std::uint64_t seed);

// The fixed point x = f(x), when I - L is invertible.
std::optional<glm::dvec3> fixedPoint3(const Affine3& map);

// r^depth saturated at UINT64_MAX.
std::uint64_t ifs3BaseCopies(const IteratedFunctionSystem3& ifs, int depth);

struct IfsComposite3 {
  Affine3 transform;
  int part = -1;  // the outermost map; -1 at depth 0
};
// The r^depth composites f_i1 o ... o f_in in the order of the guide's Listing 4 recursion.
// The caller checks ifs3BaseCopies first.
std::vector<IfsComposite3> ifsComposites3(const IteratedFunctionSystem3& ifs, int depth);

// The base polyhedron's faces as triangles, outward-facing. For the hull: the convex hull of
// the attractor, from its extreme points in many directions; for a model, its loaded triangles
// (none before loadIfs3BaseModel).
std::vector<Triangle3> basePolyhedron(const IteratedFunctionSystem3& ifs);

// The convex hull of points as outward, counter-clockwise triangles (an incremental hull); empty
// when the points span no volume.
std::vector<Triangle3> convexHull(const std::vector<glm::dvec3>& points);

struct RebuildTriangle {
  Triangle3 corners;
  glm::dvec3 normal;  // unit, outward (the composite's orientation taken into account)
  int part = -1;
};
inline constexpr std::uint64_t kMaxRebuildTriangles = 2'000'000;
// The polyhedral rebuild at `depth`: the base polyhedron through every composite, each triangle
// with its flat normal. Triangles that a flattening composite collapses to zero area are left out.
// Empty with `problem` set when the count would pass `limit`.
std::vector<RebuildTriangle> polyhedralRebuild(const IteratedFunctionSystem3& ifs, int depth, std::uint64_t limit,
                                               std::string& problem);

// The similarity ratio of a map (L^T L = r^2 I within 1e-9 relative), or nothing.
std::optional<double> similarityRatio3(const Affine3& map);

// Moran's equation when every map is a similarity with ratio < 1, else box counting of `points`
// chaos-game points (cubes of side / 2^level).
IfsDimensionReport ifsDimension3(const IteratedFunctionSystem3& ifs, std::uint64_t points = 1'000'000,
                                 std::uint64_t seed = 1);
std::optional<BoxCountingEstimate> boxCountingDimension3(std::span<const glm::dvec3> points);

}  // namespace glass::geometry
