// Homework 3: the rebuild's base polyhedron read from an OBJ file (`base "model.obj"` in .ifs3),
// through the scene library's OBJ reader, with its errors at the line and column of the name.
#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <string>

#include <glass/scene/ifs3_base_model.h>

#include "glass/geometry/ifs3d.h"
#include "glass/geometry/ifs3d_format.h"

namespace g = glass::geometry;

TEST_CASE("course homework 3: base \"model.obj\" is read, written back and loaded") {
  auto parsed = g::parseIfs3("map scale 0.5\n  base \"../models/octahedron.obj\"\nmap translate 0.5 0 0 scale 0.5\n");
  REQUIRE(parsed.ok());
  CHECK(parsed.ifs.base == g::IfsBase3::Model);
  CHECK(parsed.ifs.baseModelPath == "../models/octahedron.obj");
  CHECK(parsed.ifs.baseModelLine == 2);
  CHECK(parsed.ifs.baseModelColumn == 8);
  // Before loading there is no polyhedron (never a stand-in cube).
  CHECK(g::basePolyhedron(parsed.ifs).empty());
  // formatIfs3 keeps the name, so a fitted or rewritten file still finds its model.
  const auto again = g::parseIfs3(g::formatIfs3(parsed.ifs));
  REQUIRE(again.ok());
  CHECK(again.ifs.baseModelPath == "../models/octahedron.obj");

  // Relative to the .ifs3 file: scenes/ifs/x.ifs3 names scenes/models/octahedron.obj.
  const std::string ifsFile = std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/homework3_octahedra.ifs3";
  CHECK_FALSE(glass::scene::loadIfs3BaseModel(parsed.ifs, ifsFile));
  const std::vector<g::Triangle3> base = g::basePolyhedron(parsed.ifs);
  REQUIRE(base.size() == 8);
  for (const g::Triangle3& t : base) {
    // Outward: the normal points away from the octahedron's centre (0.5, 0.5, 0.5).
    const glm::dvec3 n = glm::cross(t.b - t.a, t.c - t.a);
    CHECK(glm::dot(n, t.a - glm::dvec3(0.5)) > 0.0);
  }
  std::string problem;
  CHECK(g::polyhedralRebuild(parsed.ifs, 2, g::kMaxRebuildTriangles, problem).size() == 8 * 4);

  // The example file loads as a whole.
  auto example = g::loadIfs3File(ifsFile);
  REQUIRE(example.ok());
  CHECK_FALSE(glass::scene::loadIfs3BaseModel(example.ifs, ifsFile));
  CHECK(example.ifs.baseModel.size() == 8);
}

TEST_CASE("course homework 3: a base model that cannot be used is an error at its name") {
  auto parsed = g::parseIfs3("map scale 0.5\nbase \"no_such_model.obj\"\n");
  REQUIRE(parsed.ok());
  const auto error = glass::scene::loadIfs3BaseModel(parsed.ifs, std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/x.ifs3");
  REQUIRE(error);
  CHECK(error->line == 2);
  CHECK(error->column == 6);
  CHECK(error->message.find("no such file") != std::string::npos);
  // A file that is not a model: the .ifs3 file itself has no faces.
  auto notModel = g::parseIfs3("map scale 0.5\nbase \"homework3.ifs3\"\n");
  REQUIRE(notModel.ok());
  const auto noFaces = glass::scene::loadIfs3BaseModel(notModel.ifs, std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/x.ifs3");
  REQUIRE(noFaces);
  CHECK(noFaces->line == 2);
  // An empty name is a parse error.
  const auto empty = g::parseIfs3("map scale 0.5\nbase \"\"\n");
  REQUIRE_FALSE(empty.ok());
  CHECK(empty.errors[0].line == 2);
  CHECK(empty.errors[0].column == 6);
}
