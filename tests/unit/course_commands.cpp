// glass lines, glass ifs and glass math as a user runs them: exit statuses, messages, and the
// pictures they draw through glass's GL, checked pixel by pixel where the answer is known.
#include <doctest/doctest.h>

#include <glass/image.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "glass/course/commands.h"

namespace c = glass::course;

namespace {

struct Run {
  int status = 0;
  std::string out, err;
};

Run run(int (*command)(const std::vector<std::string>&, std::ostream&, std::ostream&),
        const std::vector<std::string>& args) {
  std::ostringstream out, err;
  Run r;
  r.status = command(args, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::string outputPath(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(GLASS_BINARY_DIR) / "test_output" / "course";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::filesystem::remove(path);
  return path.string();
}

std::string example(const std::string& name) { return std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/" + name; }

// The pixel (x, y) counted from the bottom left, as GL counts.
std::array<int, 3> pixel(const glass::Image& image, int x, int y) {
  const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Within one step of 8-bit rounding.
bool near(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(a[i] - b[i]) > 1) return false;
  return true;
}

}  // namespace

TEST_CASE("course command: glass lines draws the grid, the chosen squares and the red segment") {
  const std::string path = outputPath("lines.png");
  const Run r = run(c::runLinesCommand, {"2", "3", "12", "8", "-a", "bresenham", "--grid", "16", "--cell", "10", "-o", path});
  CAPTURE(r.err);
  REQUIRE(r.status == 0);
  CAPTURE(r.out);
  // Slope 1/2: the line passes halfway between two squares at every odd step.
  CHECK(contains(r.out, "bresenham  11 squares: (2,3) "));
  CHECK(contains(r.out, "(4,4) "));
  CHECK(contains(r.out, "(12,8)\n"));
  CHECK(contains(r.out, "(Figure 2.2): (3,3)|(3,4) (5,4)|(5,5) (7,5)|(7,6) (9,6)|(9,7) (11,7)|(11,8)\n"));
  glass::Image image;
  std::string error;
  REQUIRE(glass::loadImageFile(path, image, error));
  CHECK(image.width == 161);
  CHECK(image.height == 161);
  // Square (x, y) covers pixels x*10+1 .. x*10+9. An empty square is white, a chosen one blue,
  // a grid line grey; the segment's end squares have the red segment through their centres.
  CHECK(pixel(image, 5 * 10 + 5, 12 * 10 + 5) == std::array<int, 3>{255, 255, 255});
  CHECK(near(pixel(image, 0, 50), {184, 184, 189}));
  const auto chosen = pixel(image, 4 * 10 + 8, 4 * 10 + 2);  // (4,4) is chosen; this corner is off the segment
  CHECK(chosen[2] > 200);
  CHECK(chosen[0] < 120);
  const auto centre = pixel(image, 2 * 10 + 5, 3 * 10 + 5);
  CHECK(centre[0] > 180);
  CHECK(centre[1] < 60);
}

TEST_CASE("course command: glass lines modes and mistakes") {
  const Run symmetry = run(c::runLinesCommand, {"--symmetry", "--grid", "12"});
  CHECK(symmetry.status == 0);
  CHECK(contains(symmetry.out, "Swapping the endpoints never changes the squares."));
  const Run speed = run(c::runLinesCommand, {"--speed", "--lines", "2000", "--repeat", "1", "--grid", "64"});
  CHECK(speed.status == 0);
  CHECK(contains(speed.out, "ns/square"));
  const Run agreement = run(c::runLinesCommand, {"--agreement", "--lines", "300"});
  CHECK(agreement.status == 0);
  CHECK(contains(agreement.out, "of 300 segments (32 x 32 grid) draw the same squares as glass's GL_LINES"));
  CHECK(run(c::runLinesCommand, {}).status == 2);
  CHECK(run(c::runLinesCommand, {"1", "2", "3"}).status == 2);
  CHECK(run(c::runLinesCommand, {"1", "2", "40", "3"}).status == 2);
  CHECK(run(c::runLinesCommand, {"1", "2", "1", "2"}).status == 2);
  const Run unknown = run(c::runLinesCommand, {"0", "0", "5", "5", "-a", "dda"});
  CHECK(unknown.status == 2);
  CHECK(contains(unknown.err, "unknown algorithm 'dda'"));
  CHECK(contains(run(c::runLinesCommand, {"--help"}).out, "usage: glass lines"));
}

TEST_CASE("course command: glass ifs renders the Sierpinski triangle part by part, in Listing 5's window") {
  const std::string path = outputPath("sierpinski.png");
  const Run r = run(c::runIfsCommand, {example("sierpinski.ifs"), "--depth", "5", "--size", "240x240", "-o", path, "--dimension"});
  CAPTURE(r.err);
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "depth 5, 243 copies of the base figure"));
  CHECK(contains(r.out, "(1/2)^d + (1/2)^d + (1/2)^d = 1"));
  CHECK(contains(r.out, "d = 1.5849625007"));
  glass::Image image;
  std::string error;
  REQUIRE(glass::loadImageFile(path, image, error));
  // The window [-0.1, 1.1]^2 on 240 pixels: x = (px + 0.5) / 200 - 0.1.
  auto at = [&](double x, double y) {
    return pixel(image, static_cast<int>((x + 0.1) * 200), static_cast<int>((y + 0.1) * 200));
  };
  // Points in the smallest triangles at the three corners, one in each part.
  CHECK(near(at(0.01, 0.01), {230, 56, 51}));   // part 1 (f1 = S(1/2)): red
  CHECK(near(at(0.51, 0.01), {51, 179, 77}));   // part 2: green
  CHECK(near(at(0.01, 0.51), {64, 115, 230}));  // part 3: blue
  CHECK(at(0.3, 0.3) == std::array<int, 3>{0, 0, 0});        // the middle hole
  CHECK(at(0.8, 0.8) == std::array<int, 3>{0, 0, 0});        // outside the triangle
}

TEST_CASE("course command: glass ifs draws the same bytes every time, and another seed differently") {
  auto render = [](const std::string& name, const std::string& seed) {
    const std::string path = outputPath(name);
    REQUIRE(run(c::runIfsCommand, {example("fern.ifs"), "--points", "50000", "--seed", seed, "--size", "120x160", "-o", path})
                .status == 0);
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string first = render("fern_a.png", "7"), second = render("fern_b.png", "7"), other = render("fern_c.png", "8");
  CHECK(first.size() > 100);
  CHECK(first == second);
  CHECK(first != other);
}

TEST_CASE("course command: glass ifs keeps the aspect ratio, and its mistakes") {
  const std::string path = outputPath("wide.png");
  const Run wide = run(c::runIfsCommand, {example("test_question_3.ifs"), "--points", "20000", "--size", "300x150", "-o", path});
  REQUIRE(wide.status == 0);
  glass::Image image;
  std::string error;
  REQUIRE(glass::loadImageFile(path, image, error));
  // Listing 5 widens x: [-0.1, 1.1] high is 150 pixels, so the unit square is 125 pixels wide,
  // centred: columns 87.5 .. 212.5. Nothing is drawn left or right of it.
  bool outside = false, inside = false;
  for (int y = 0; y < 150; ++y) {
    for (int x = 0; x < 300; ++x) {
      const auto p = pixel(image, x, y);
      const bool lit = p[0] + p[1] + p[2] > 0;
      if (lit && (x < 86 || x > 214)) outside = true;
      if (lit) inside = true;
    }
  }
  CHECK(inside);
  CHECK_FALSE(outside);

  const std::string broken = outputPath("broken.ifs");
  std::ofstream(broken) << "map scale 0.5\nmap rotate\n";
  const Run bad = run(c::runIfsCommand, {broken, "--dimension"});
  CHECK(bad.status == 1);
  CHECK(contains(bad.err, "broken.ifs:2:11: error: expected an angle in degrees"));
  CHECK(run(c::runIfsCommand, {example("sierpinski.ifs")}).status == 2);
  CHECK(run(c::runIfsCommand, {example("sierpinski.ifs"), "--depth", "3", "--points", "10", "-o", path}).status == 2);
  CHECK(run(c::runIfsCommand, {"no/such.ifs", "--dimension"}).status == 1);
  const Run deep = run(c::runIfsCommand, {example("test_question_3.ifs"), "--depth", "20", "-o", path});
  CHECK(deep.status == 1);
  CHECK(contains(deep.err, "lower the depth"));
}

TEST_CASE("course command: glass math answers the guide's examples without arguments") {
  const Run compose = run(c::runMathCommand, {"rotate-compose"});
  CHECK(compose.status == 0);
  CHECK(contains(compose.out, "Answer: 180 degrees about (1/√2, 0, -1/√2)"));
  CHECK(contains(run(c::runMathCommand, {"decompose"}).out, "A = T(2, -1) R(45 degrees) S(-2√2, √2)"));
  CHECK(contains(run(c::runMathCommand, {"normal"}).out, "(-2, 1, 2)"));
  CHECK(contains(run(c::runMathCommand, {"arc"}).out, "(1, √3)"));
  CHECK(contains(run(c::runMathCommand, {"torus-patch"}).out, "(R+r, -r, R+r)"));
  CHECK(contains(run(c::runMathCommand, {"decompose", "-2", "-1", "2", "-2", "1", "-1", "0", "0", "1"}).out, "S(-2√2, √2)"));
  CHECK(run(c::runMathCommand, {"decompose", "1", "2", "0", "2", "4", "0"}).status == 1);
  CHECK(run(c::runMathCommand, {"rotate-compose", "90", "0", "0"}).status == 2);
  CHECK(run(c::runMathCommand, {"spin"}).status == 2);
  CHECK(run(c::runMathCommand, {}).status == 2);
}

TEST_CASE("course command: glass math view draws its answer, and the sphere fills 2/3 and 1/2") {
  const std::string path = outputPath("view.png");
  const Run r = run(c::runMathCommand, {"view", "-o", path, "--pixels", "300"});
  CAPTURE(r.err);
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "gluPerspective(53.1301, 1.33333, 3, 5);"));
  CHECK(contains(r.out, "the sphere covers 200 of 300 rows (0.666667) and 200 of 400 columns (0.5)"));
  glass::Image image;
  std::string error;
  REQUIRE(glass::loadImageFile(path, image, error));
  CHECK(image.width == 400);
  // The centre shows the inside of the far half (the back material, blue), not the outside.
  const auto centre = pixel(image, 200, 150);
  CHECK(centre[2] > centre[0]);
  // Other shares and parts.
  const Run other = run(c::runMathCommand, {"view", "--height", "1/2", "--width", "1/2", "--visible", "1/4", "-o", path, "--pixels", "200"});
  CHECK(other.status == 0);
  CHECK(contains(other.out, "the sphere covers 100 of 200 rows"));
  CHECK(run(c::runMathCommand, {"view", "--visible", "3/4"}).status == 1);
  CHECK(run(c::runMathCommand, {"view", "--eye", "1", "2"}).status == 2);
}
