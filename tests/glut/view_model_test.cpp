// glass view's scene model without a window (tools/glass/view/): walking with collisions, the
// obstacles a scene gives, and the menu's changes to a scene; glass ifs3d view's trackball.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "view/scene_obstacles.h"
#include "view/scene_overrides.h"
#include "view/trackball.h"
#include "view/walk_collision.h"

#include <GL/gl.h>
#include <glass/scene/parser.h>

#include <cmath>
#include <cstdint>
#include <string>

using namespace glass;
using cli::view::Footprint;
using cli::view::GroundPoint;
using cli::view::slideMove;

namespace {

constexpr double kRadius = 0.3;
// The room of scenes/room.scene: the back wall on z = -3 and the left wall on x = -3, both 6 long.
const Footprint kBackWall{-3, -3, 3, -3};
const Footprint kLeftWall{-3, -3, -3, 3};

bool strictlyInside(GroundPoint p, const Footprint &f, double radius) {
  return p.x > f.minX - radius && p.x < f.maxX + radius && p.z > f.minZ - radius && p.z < f.maxZ + radius;
}

scene::Program parse(const std::string &text) {
  scene::Diagnostics diagnostics;
  scene::Program program = scene::parseSceneText("test.scene", text, diagnostics);
  REQUIRE_FALSE(diagnostics.hasErrors());
  return program;
}

} // namespace

TEST_CASE("walking head-on into a wall stops at the walker's radius from it") {
  const GroundPoint at = slideMove({0, 0}, {0, -5}, kRadius, {kBackWall});
  CHECK(at.x == 0.0);
  CHECK(at.z == doctest::Approx(-2.7).epsilon(1e-12));
  // Pressing on does not move it, and backing away is free.
  const GroundPoint again = slideMove(at, {0, -1}, kRadius, {kBackWall});
  CHECK(again.x == at.x);
  CHECK(again.z == at.z);
  const GroundPoint back = slideMove(at, {0, 1}, kRadius, {kBackWall});
  CHECK(back.z == doctest::Approx(at.z + 1));
}

TEST_CASE("walking diagonally into a wall slides along it, keeping the motion along the wall") {
  const GroundPoint at = slideMove({0, 0}, {1, -5}, kRadius, {kBackWall});
  CHECK(at.z == doctest::Approx(-2.7).epsilon(1e-12));
  CHECK(at.x == doctest::Approx(1.0).epsilon(1e-12));
  // Standing at the wall, a step along it goes its whole length.
  const GroundPoint along = slideMove(at, {-2, -0.5}, kRadius, {kBackWall});
  CHECK(along.x == doctest::Approx(-1.0).epsilon(1e-12));
  CHECK(along.z == at.z);
}

TEST_CASE("a concave corner stops the walker at the radius from both walls") {
  const GroundPoint at = slideMove({0, 0}, {-10, -7}, kRadius, {kBackWall, kLeftWall});
  CHECK(at.x == doctest::Approx(-2.7).epsilon(1e-12));
  CHECK(at.z == doctest::Approx(-2.7).epsilon(1e-12));
  // Sliding along the back wall into the corner ends there too.
  const GroundPoint slid = slideMove({2, -2.7}, {-10, -1}, kRadius, {kBackWall, kLeftWall});
  CHECK(slid.x == doctest::Approx(-2.7).epsilon(1e-12));
  CHECK(slid.z == doctest::Approx(-2.7).epsilon(1e-12));
}

TEST_CASE("a gap narrower than the walker does not let it through, nor does a corner") {
  // Two blocks with a gap of 0.5 < 2 * 0.3 between them.
  const std::vector<Footprint> blocks{{0, -5, 1, 0}, {0, 0.5, 1, 5}};
  const GroundPoint at = slideMove({-2, 0.25}, {10, 0}, kRadius, blocks);
  CHECK(at.x == doctest::Approx(-0.3).epsilon(1e-12));
  CHECK(at.z == 0.25);
  // Straight at a block's corner, diagonally: stopped outside it.
  const Footprint block{0, 0, 1, 1};
  const GroundPoint corner = slideMove({-1, -1}, {3, 3}, kRadius, {block});
  CHECK_FALSE(strictlyInside(corner, block, kRadius));
  CHECK(((corner.x == -0.3 && corner.z > -1) || (corner.z == -0.3 && corner.x > -1)));
}

TEST_CASE("a long step does not tunnel through a thin wall") {
  const Footprint thin{-5, 0, 5, 0};
  const GroundPoint at = slideMove({0, 10}, {0, -1000}, kRadius, {thin});
  CHECK(at.z == doctest::Approx(0.3).epsilon(1e-12));
  const GroundPoint diagonal = slideMove({0, 10}, {3, -1000}, kRadius, {thin});
  CHECK(diagonal.z == doctest::Approx(0.3).epsilon(1e-12));
  CHECK(diagonal.x == doctest::Approx(3.0).epsilon(1e-12));
}

TEST_CASE("a walker inside an obstacle can walk out by its nearest side, not further in") {
  const Footprint block{0, 0, 4, 4};
  // At (0.5, 2): the nearest side of the grown block is x = -0.3.
  const GroundPoint out = slideMove({0.5, 2}, {-2, 0}, kRadius, {block});
  CHECK(out.x == doctest::Approx(-1.5));
  const GroundPoint deeper = slideMove({0.5, 2}, {2, 0}, kRadius, {block});
  CHECK(deeper.x == 0.5);
  const GroundPoint along = slideMove({0.5, 2}, {0, 1}, kRadius, {block});
  CHECK(along.z == doctest::Approx(3.0));
}

TEST_CASE("random walks among random blocks never end inside one") {
  std::uint64_t state = 12345;
  auto next = [&state] {  // a 64-bit LCG (Knuth's MMIX constants), for repeatable inputs
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53);
  };
  std::vector<Footprint> blocks;
  for (int i = 0; i < 12; ++i) {
    const double x = next() * 20 - 10, z = next() * 20 - 10;
    blocks.push_back({x, z, x + next() * 3, z + next() * 3});
  }
  blocks.push_back({-12, -12, 12, -12});
  blocks.push_back({-12, 12, 12, 12});
  blocks.push_back({-12, -12, -12, 12});
  blocks.push_back({12, -12, 12, 12});
  GroundPoint at{-11, -11};
  for (const Footprint &b : blocks) REQUIRE_FALSE(strictlyInside(at, b, kRadius));
  for (int step = 0; step < 5000; ++step) {
    const double length = step % 7 == 0 ? 30 : next() * 2;
    const double angle = next() * 6.283185307179586;
    at = slideMove(at, {length * std::cos(angle), length * std::sin(angle)}, kRadius, blocks);
    for (const Footprint &b : blocks) {
      INFO("step " << step << " at " << at.x << ", " << at.z);
      REQUIRE_FALSE(strictlyInside(at, b, kRadius));
    }
  }
}

TEST_CASE("obstacles are the world boxes of what a scene draws, after its transforms") {
  const scene::Program program = parse(R"(
lookat 0 2 10  0 0 0  0 1 0
push
  translate 1 0 0
  rotate 90 0 1 0
  solid_cube 2
pop
begin quads
  vertex -3 0 3
  vertex 3 0 3
  vertex 3 0 -3
  vertex -3 0 -3
  vertex -3 0 -3
  vertex 3 0 -3
  vertex 3 4 -3
  vertex -3 4 -3
end
push
  shadow_matrix plane 0 1 0 0 light 2 5 3 1
  solid_cube 2
pop
begin lines
  vertex 0 0 0
  vertex 9 9 9
end
)");
  const std::vector<geometry::AxisAlignedBox> boxes = cli::view::sceneBoxes(program, 0);
  REQUIRE(boxes.size() == 3); // the cube, the floor and the wall; no shadow, no lines
  CHECK(boxes[0].min.x == doctest::Approx(0.0));
  CHECK(boxes[0].max.x == doctest::Approx(2.0));
  CHECK(boxes[0].min.y == doctest::Approx(-1.0));
  CHECK(boxes[0].max.z == doctest::Approx(1.0));
  CHECK(boxes[1].max.y == 0.0);
  CHECK(boxes[2].min.z == -3.0);
  CHECK(boxes[2].max.y == 4.0);

  const cli::view::WalkGround ground = cli::view::walkGround(boxes, cli::view::WalkerBody{});
  CHECK(ground.groundY == -1.0); // the cube's bottom is the lowest point
  // The floor at y = 0 is 1 above that ground, more than the walker steps over: the cube, the
  // floor and the wall all stand in the way.
  CHECK(ground.obstacles.size() == 3);
}

TEST_CASE("the room: its walls and block stand in the way, its floor and lamp do not") {
  scene::Diagnostics diagnostics;
  const scene::Program room = scene::parseSceneFile(GLASS_SOURCE_DIR "/scenes/room.scene", diagnostics);
  REQUIRE_FALSE(diagnostics.hasErrors());
  const cli::view::WalkGround ground =
      cli::view::walkGround(cli::view::sceneBoxes(room, 0), cli::view::WalkerBody{});
  CHECK(ground.groundY == 0.0);
  // The back wall, the left wall and the block (one box for the model).
  REQUIRE(ground.obstacles.size() == 3);
  CHECK(ground.obstacles[0].minZ == -3.0);
  CHECK(ground.obstacles[0].maxZ == -3.0);
  CHECK(ground.obstacles[1].minX == -3.0);
  CHECK(ground.obstacles[1].maxX == -3.0);
  const Footprint &block = ground.obstacles[2];
  CHECK(block.minX < 0.0);
  CHECK(block.maxX > 0.0);
  CHECK(block.minX > -3.0);
  CHECK(block.maxX < 3.0);
}

TEST_CASE("the room's lights, and the menu's changes to a scene") {
  scene::Diagnostics diagnostics;
  const scene::Program room = scene::parseSceneFile(GLASS_SOURCE_DIR "/scenes/room.scene", diagnostics);
  REQUIRE_FALSE(diagnostics.hasErrors());
  const std::vector<cli::view::SceneLight> lights = cli::view::sceneLights(room);
  REQUIRE(lights.size() == 3);
  CHECK(lights[0].kind == "directional");
  CHECK(lights[1].kind == "point");
  CHECK(lights[2].kind == "spot");
  CHECK(cli::view::hasRoundedModels(room));

  cli::view::SceneOverrides overrides;
  CHECK_FALSE(overrides.any());
  overrides.shade = cli::view::ShadeChoice::Flat;
  overrides.wireframe = true;
  overrides.lightsOff = {1};
  overrides.roundingChange = 0.04;
  const scene::Program changed = cli::view::withOverrides(room, overrides, 0);
  REQUIRE(changed.statements.size() == room.statements.size() + 2);
  const auto *shade = std::get_if<scene::ShadeModel>(&changed.statements[0].body);
  REQUIRE(shade != nullptr);
  CHECK(shade->mode == GL_FLAT);
  const auto *mode = std::get_if<scene::PolygonMode>(&changed.statements[1].body);
  REQUIRE(mode != nullptr);
  CHECK(mode->mode == GL_LINE);
  int lightEnables = 0, roundedModels = 0;
  for (const scene::Statement &statement : changed.statements) {
    if (const auto *enable = std::get_if<scene::Enable>(&statement.body)) {
      for (scene::GLenumValue cap : enable->caps) {
        CHECK(cap != GL_LIGHT1);
        lightEnables += cap == GL_LIGHT0 || cap == GL_LIGHT2;
      }
    }
  }
  for (const scene::Definition &definition : changed.definitions) {
    for (const scene::Statement &statement : definition.body) {
      if (const auto *model = std::get_if<scene::DrawModel>(&statement.body); model && model->round) {
        CHECK(model->round->isConstant());
        CHECK(model->round->constant == doctest::Approx(0.24));
        ++roundedModels;
      }
    }
  }
  CHECK(lightEnables == 2);
  CHECK(roundedModels == 2);
}

TEST_CASE("trackball: the ball's points, on the sphere near the centre and on the sheet beyond") {
  const glm::dvec3 centre = cli::view::trackballPoint(100, 50, 200, 100);
  CHECK(centre.x == 0.0);
  CHECK(centre.y == 0.0);
  CHECK(centre.z == 1.0);
  // Half the radius right and up (y grows downwards in the window): on the unit sphere.
  const glm::dvec3 p = cli::view::trackballPoint(125, 25, 200, 100);
  CHECK(p.x == doctest::Approx(0.5));
  CHECK(p.y == doctest::Approx(0.5));
  CHECK(p.x * p.x + p.y * p.y + p.z * p.z == doctest::Approx(1.0));
  // At the window's edge, beyond 1/sqrt(2): the sheet z = 1 / (2 d).
  const glm::dvec3 edge = cli::view::trackballPoint(200, 50, 200, 100);
  CHECK(edge.x == doctest::Approx(2.0));
  CHECK(edge.z == doctest::Approx(0.25));
}

TEST_CASE("trackball: a drag turns by the angle between the ball's points, about their common normal") {
  // From the centre to half the radius right: 30 degrees about the eye's up axis.
  const geometry::Quaternion q = cli::view::trackballDrag(100, 100, 150, 100, 200, 200);
  const double half = 15.0 * 3.14159265358979323846 / 180.0;
  CHECK(q.w == doctest::Approx(std::cos(half)).epsilon(1e-12));
  CHECK(q.x == doctest::Approx(0.0));
  CHECK(q.y == doctest::Approx(std::sin(half)).epsilon(1e-12));
  CHECK(q.z == doctest::Approx(0.0));
  // The point under the pointer follows it: the turn takes the first point to the second.
  const glm::dvec3 from = cli::view::trackballPoint(100, 100, 200, 200);
  const glm::dvec3 moved = geometry::rotate(q, from);
  const glm::dvec3 to = cli::view::trackballPoint(150, 100, 200, 200);
  CHECK(moved.x == doctest::Approx(to.x));
  CHECK(moved.y == doctest::Approx(to.y));
  CHECK(moved.z == doctest::Approx(to.z));
  // No drag, no turn.
  CHECK(cli::view::trackballDrag(30, 40, 30, 40, 200, 200) == geometry::Quaternion{});
}

TEST_CASE("trackball: a turn about the eye's axes becomes a turn about the world's through the camera") {
  // The camera on the +x axis looking at the origin: the eye's right is -z, its up +y, its back +x.
  const glm::dvec3 eye(5, 0, 0), centre(0, 0, 0), up(0, 1, 0);
  const geometry::Quaternion aboutEyeUp = cli::view::trackballDrag(100, 100, 150, 100, 200, 200);
  const geometry::Quaternion turned = cli::view::turnByDrag(geometry::Quaternion{}, aboutEyeUp, eye, centre, up);
  CHECK(turned.y == doctest::Approx(aboutEyeUp.y));  // up is up in both
  const geometry::Quaternion aboutEyeRight = cli::view::trackballDrag(100, 100, 100, 50, 200, 200);
  const geometry::Quaternion tilted = cli::view::turnByDrag(geometry::Quaternion{}, aboutEyeRight, eye, centre, up);
  // A drag upwards turns about the eye's -x (its right, -z in the world): the world's front
  // (+x, towards the eye) goes up.
  const glm::dvec3 front = geometry::rotate(tilted, glm::dvec3(1, 0, 0));
  CHECK(front.y > 0.4);
  CHECK(std::abs(front.z) < 1e-12);
  // Turns compose, and stay of unit length.
  const geometry::Quaternion both = cli::view::turnByDrag(turned, aboutEyeRight, eye, centre, up);
  CHECK(geometry::norm(both) == doctest::Approx(1.0).epsilon(1e-15));
}
