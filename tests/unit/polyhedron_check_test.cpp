// The solid checks of a polyhedron (geometry/polyhedron_check.h) and the scene language's warnings
// built on them, on meshes built here and on the homework's refused .wings files.
#include <doctest/doctest.h>

#include <glass/geometry/polyhedron_check.h>
#include <glass/scene/parser.h>

#include <algorithm>
#include <string>

using glass::geometry::checkPolyhedron;
using glass::geometry::MarkedPolyhedron;
using glass::geometry::PolyhedronCheck;

namespace {

// The unit cube at `origin` scaled by `size`, its faces counter-clockwise seen from outside, its
// vertices numbered after `shape`'s.
void addCube(MarkedPolyhedron &shape, glm::dvec3 origin, double size = 1.0) {
  const auto first = static_cast<std::uint32_t>(shape.vertices.size());
  for (int i = 0; i < 8; ++i)
    shape.vertices.push_back(origin + size * glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto &face : faces) {
    MarkedPolyhedron::Face f;
    for (const std::uint32_t v : face) f.vertices.push_back(first + v);
    shape.faces.push_back(f);
  }
}

MarkedPolyhedron cube() {
  MarkedPolyhedron shape;
  addCube(shape, glm::dvec3(0.0));
  return shape;
}

} // namespace

TEST_CASE("polyhedron check: a cube is a closed solid facing out, of volume 1") {
  const PolyhedronCheck check = checkPolyhedron(cube());
  CHECK(check.consistent());
  CHECK_FALSE(check.insideOut());
  CHECK(check.volume == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(check.crossingFacePairs == 0);
}

TEST_CASE("polyhedron check: a cube with every face turned round is inside out") {
  MarkedPolyhedron shape = cube();
  for (auto &face : shape.faces) std::reverse(face.vertices.begin(), face.vertices.end());
  const PolyhedronCheck check = checkPolyhedron(shape);
  CHECK(check.consistent());
  CHECK(check.insideOut());
  CHECK(check.volume == doctest::Approx(-1.0).epsilon(1e-12));
}

TEST_CASE("polyhedron check: one face turned round, and one face missing") {
  MarkedPolyhedron turned = cube();
  std::reverse(turned.faces[0].vertices.begin(), turned.faces[0].vertices.end());
  PolyhedronCheck check = checkPolyhedron(turned);
  CHECK(check.closed());
  CHECK(check.reversedEdges == 4);  // the face's four edges
  CHECK_FALSE(check.insideOut());   // not a consistent mesh: no side is called out

  MarkedPolyhedron open = cube();
  open.faces.pop_back();
  check = checkPolyhedron(open);
  CHECK(check.openEdges == 4);
  CHECK_FALSE(check.closed());
  CHECK(check.firstOpenEdge == std::array<std::uint32_t, 2>{4, 5});

  MarkedPolyhedron extra = cube();
  extra.faces.push_back(extra.faces[0]);  // a face twice: its edges belong to three faces
  check = checkPolyhedron(extra);
  CHECK(check.nonManifoldEdges == 4);
}

TEST_CASE("polyhedron check: cubes pushed into each other cross; cubes side by side do not") {
  MarkedPolyhedron pushed;
  addCube(pushed, glm::dvec3(0.0));
  addCube(pushed, glm::dvec3(0.5, 0.25, 0.25));
  PolyhedronCheck check = checkPolyhedron(pushed);
  CHECK(check.consistent());
  CHECK(check.crossingFacePairs > 0);
  CHECK(check.firstCrossing[0] < 6);
  CHECK(check.firstCrossing[1] >= 6);

  // Touching along a whole face (two shells, the shared square in one plane), along an edge,
  // and a small cube resting on a large one's top: faces meet but none cuts through another.
  for (const glm::dvec3 offset : {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(1.0, 1.0, 0.0), glm::dvec3(0.25, 1.0, 0.25)}) {
    MarkedPolyhedron touching;
    addCube(touching, glm::dvec3(0.0));
    addCube(touching, offset, offset.x == 0.25 ? 0.5 : 1.0);
    check = checkPolyhedron(touching);
    CHECK(check.crossingFacePairs == 0);
    CHECK(check.volume == doctest::Approx(offset.x == 0.25 ? 1.125 : 2.0).epsilon(1e-12));
  }

  // A small cube wholly inside a large one: no face crosses another (the volumes add up).
  MarkedPolyhedron inside;
  addCube(inside, glm::dvec3(0.0), 3.0);
  addCube(inside, glm::dvec3(1.0));
  CHECK(checkPolyhedron(inside).crossingFacePairs == 0);
}

TEST_CASE("polyhedron check: faces with a common vertex cross when they cut through each other beyond it") {
  // Two triangles from the origin: one in the plane y = 0, one in the plane z = 0. Both reach out
  // along +x, so they cut through each other along the x axis from the common vertex to x = 2.
  MarkedPolyhedron crossing;
  crossing.vertices = {glm::dvec3(0.0), glm::dvec3(2.0, 0.0, -1.0), glm::dvec3(2.0, 0.0, 1.0),
                       glm::dvec3(2.0, -1.0, 0.0), glm::dvec3(2.0, 1.0, 0.0)};
  crossing.faces.resize(2);
  crossing.faces[0].vertices = {0, 1, 2};
  crossing.faces[1].vertices = {0, 3, 4};
  CHECK(checkPolyhedron(crossing).crossingFacePairs == 1);

  // The second one turned to reach along -x: they meet at the common vertex only.
  MarkedPolyhedron meeting = crossing;
  meeting.vertices[3] = glm::dvec3(-2.0, -1.0, 0.0);
  meeting.vertices[4] = glm::dvec3(-2.0, 1.0, 0.0);
  CHECK(checkPolyhedron(meeting).crossingFacePairs == 0);
}

TEST_CASE("polyhedron check: an L prism with a concave face of six vertices") {
  // The L: (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), one unit high.
  const double plan[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  MarkedPolyhedron shape;
  for (int level = 0; level < 2; ++level)
    for (const auto &p : plan) shape.vertices.push_back(glm::dvec3(p[0], level, p[1]));
  MarkedPolyhedron::Face bottom, top;
  for (std::uint32_t i = 0; i < 6; ++i) {
    bottom.vertices.push_back(i);       // counter-clockwise seen from below (y down)
    top.vertices.push_back(11 - i);     // counter-clockwise seen from above
    MarkedPolyhedron::Face side;
    const std::uint32_t j = (i + 1) % 6;
    side.vertices = {i, i + 6, j + 6, j};
    shape.faces.push_back(side);
  }
  shape.faces.push_back(bottom);
  shape.faces.push_back(top);
  PolyhedronCheck check = checkPolyhedron(shape);
  CHECK(check.consistent());
  CHECK(check.volume == doctest::Approx(3.0).epsilon(1e-12));
  CHECK(check.crossingFacePairs == 0);
  // A small cube in the notch, through the top's plane but outside the L. A fan of triangles
  // from the top's first vertex, (0, 1, 2), would cover the notch and cross the cube's sides;
  // the top's own triangles do not.
  addCube(shape, glm::dvec3(1.25, 0.75, 1.25), 0.5);
  check = checkPolyhedron(shape);
  CHECK(check.volume == doctest::Approx(3.125).epsilon(1e-12));
  CHECK(check.crossingFacePairs == 0);
  // Pushed into the L's arm, it crosses the top.
  for (std::size_t i = 12; i < 20; ++i) shape.vertices[i].x -= 0.5;
  check = checkPolyhedron(shape);
  CHECK(check.crossingFacePairs > 0);
}

TEST_CASE("scene parser: a .wings model that is not a solid draws, with a warning naming what is wrong") {
  const std::string directory = GLASS_SOURCE_DIR "/tests/homework45/";
  const struct {
    const char *file, *message;
  } cases[] = {
      {"refused_inside_out.wings", "object 'Inverted' is inside out: its faces face inwards (volume -1)"},
      {"refused_open_cube.wings", "object 'Open' is open: 4 edges belong to one face only"},
      {"refused_crossing_cubes.wings", "object 'Crossing' crosses itself: "},
      {"refused_no_objects.wings", "the file has no objects: nothing is drawn"},
  };
  for (const auto &c : cases) {
    CAPTURE(c.file);
    glass::scene::Diagnostics diagnostics;
    const std::string text = "size 8 8\nclear\nmodel \"" + directory + c.file + "\"\n";
    glass::scene::parseSceneText("m.scene", text, diagnostics);
    CHECK_FALSE(diagnostics.hasErrors());
    const std::string messages = diagnostics.format();
    CHECK(messages.find("m.scene:3:7: warning: model '" + directory + c.file + "': " + c.message) != std::string::npos);
  }
  // A solid gives no warning.
  glass::scene::Diagnostics diagnostics;
  glass::scene::parseSceneText("m.scene", "model \"" GLASS_SOURCE_DIR "/scenes/models/slab_cube.wings\"\n", diagnostics);
  CHECK(diagnostics.format().empty());
}
