// Homework 2 of the study guide (section 2.2): the IFS model, its file format, the Listing 4
// expansion, the chaos game, Listing 5's window, and the shipped example files.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "glass/geometry/ifs.h"
#include "glass/geometry/ifs_dimension.h"
#include "glass/geometry/ifs_format.h"

namespace g = glass::geometry;
using g::Affine2;

namespace {

std::string exampleFile(const char* name) { return std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/" + name; }

bool near(const Affine2& a, const Affine2& b, double eps = 1e-15) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c)
      if (std::abs(a.m[r][c] - b.m[r][c]) > eps) return false;
  return true;
}

}  // namespace

TEST_CASE("course 2.2: map operations compose left to right like GL calls") {
  const auto result = g::parseIfs(
      "map translate 0.5 0 rotate 90 scale 0.5\n"
      "map scale 2 3 shear 0.5\n"
      "map matrix 1 2 3 4 5 6 color 0.1 0.2 0.3\n");
  REQUIRE(result.ok());
  REQUIRE(result.ifs.maps.size() == 3);
  // T(0.5, 0) R(90) S(0.5): (x, y) -> (0.5 - y/2, x/2), test question 3's third map.
  CHECK(near(result.ifs.maps[0].transform, Affine2::fromRows(0, -0.5, 0.5, 0.5, 0, 0)));
  CHECK(near(result.ifs.maps[1].transform, Affine2::fromRows(2, 1, 0, 0, 3, 0)));
  CHECK(near(result.ifs.maps[2].transform, Affine2::fromRows(1, 2, 3, 4, 5, 6)));
  CHECK(result.ifs.maps[2].color == g::IfsColor{0.1f, 0.2f, 0.3f});
  CHECK_FALSE(result.ifs.maps[2].probability.has_value());
  const auto weighted = g::parseIfs("map scale 0.5 probability 2\nmap rotate 10 probability 0.5\n");
  REQUIRE(weighted.ok());
  CHECK(weighted.ifs.maps[0].probability == 2.0);
  CHECK_FALSE(result.ifs.window.has_value());
  CHECK(result.ifs.base.size() == 4);  // the unit square by default
}

TEST_CASE("course 2.2: IFS file errors carry line and column, several at once") {
  struct Case {
    const char* text;
    int line, column;
    const char* fragment;
  };
  const Case cases[] = {
      {"map scale\n", 1, 10, "expected a scale factor"},
      {"map scale 0.5\nmap wobble 2\n", 2, 5, "unknown map operation 'wobble'"},
      {"map scale x\n", 1, 11, "found 'x'"},
      {"frobnicate\nmap scale 0.5\n", 1, 1, "unknown statement"},
      {"map scale 0.5 0.5 0.5\n", 1, 19, "unexpected '0.5'"},
      {"map color 1 0 0\n", 1, 1, "at least one operation"},
      {"map scale 0.5 color 2 0 0\n", 1, 21, "[0, 1]"},
      {"map scale 0.5 probability -1\n", 1, 27, "negative"},
      {"map scale 0.5 color 1 0 0 translate 1 1\n", 1, 27, "before color"},
      {"map scale 0.5 probability 1\nmap scale 0.5\n", 2, 1, "give all or none"},
      {"window 1 0 0 1\nmap scale 0.5\n", 1, 8, "xmin < xmax"},
      {"base triangle 0 0 1 0\nmap scale 0.5\n", 1, 22, "3 vertices"},
      {"base hexagon\nmap scale 0.5\n", 1, 6, "unknown base"},
      {"name Sierpinski\nmap scale 0.5\n", 1, 6, "quoted name"},
      {"name \"open\nmap scale 0.5\n", 1, 6, "unterminated"},
      {"# nothing\n", 1, 1, "no maps"},
  };
  for (const Case& c : cases) {
    const std::string text = c.text;
    CAPTURE(text);
    const auto result = g::parseIfs(c.text);
    REQUIRE_FALSE(result.ok());
    CHECK(result.errors[0].line == c.line);
    CHECK(result.errors[0].column == c.column);
    CHECK(result.errors[0].message.find(c.fragment) != std::string::npos);
  }
  // Errors on several lines are all reported.
  const auto several = g::parseIfs("map scale a\nmap rotate\nmap scale 0.5\n");
  CHECK(several.errors.size() == 2);
  const std::string formatted = g::formatIfsErrors(several, "f.ifs", "map scale a\nmap rotate\nmap scale 0.5\n");
  CHECK(formatted.find("f.ifs:1:11: error: expected a scale factor, found 'a'\n  map scale a\n            ^\n") == 0);
  CHECK(formatted.find("f.ifs:2:11:") != std::string::npos);
}

TEST_CASE("course 2.2: the shipped example files parse and have the guide's dimensions") {
  const auto sierpinski = g::loadIfsFile(exampleFile("sierpinski.ifs"));
  REQUIRE(sierpinski.ok());
  CHECK(sierpinski.ifs.name == "Sierpinski triangle");
  CHECK(sierpinski.ifs.maps.size() == 3);
  CHECK(sierpinski.ifs.base.size() == 3);
  CHECK(*g::ifsDimension(sierpinski.ifs).moranDimension == doctest::Approx(std::log(3.0) / std::log(2.0)));

  const auto q3 = g::loadIfsFile(exampleFile("test_question_3.ifs"));
  REQUIRE(q3.ok());
  CHECK(*g::ifsDimension(q3.ifs).moranDimension ==
        doctest::Approx(std::log2((3 + std::sqrt(13.0)) / 2)).epsilon(1e-14));

  const auto fern = g::loadIfsFile(exampleFile("fern.ifs"));
  REQUIRE(fern.ok());
  const g::IfsDimensionReport report = g::ifsDimension(fern.ifs, 500'000);
  CHECK_FALSE(report.allSimilarities);
  CHECK_FALSE(report.moranDimension.has_value());
  CHECK(report.ratios[1].has_value());  // the main map turns and shrinks: a similarity
  CHECK_FALSE(report.ratios[0].has_value());  // the stem flattens the plane
  CHECK_FALSE(report.ratios[2].has_value());
  REQUIRE(report.boxCounting.has_value());
  CHECK(report.boxCounting->dimension > 1.4);
  CHECK(report.boxCounting->dimension < 2.0);

  CHECK_FALSE(g::loadIfsFile(exampleFile("no_such_file.ifs")).ok());
}

TEST_CASE("course 2.2: Listing 4's recursion pushes, multiplies, draws and pops in order") {
  const auto sierpinski = g::loadIfsFile(exampleFile("sierpinski.ifs"));
  REQUIRE(sierpinski.ok());
  struct Recorder final : g::IfsMatrixStackVisitor {
    std::string calls;
    int depth = 0, maxDepth = 0;
    void pushMatrix() override {
      calls += '(';
      maxDepth = std::max(maxDepth, ++depth);
    }
    void multiplyMatrix(const Affine2&) override { calls += 'm'; }
    void popMatrix() override {
      calls += ')';
      --depth;
    }
    void drawBase(int part) override { calls += std::to_string(part); }
  } recorder;
  g::expandIfs(sierpinski.ifs, 1, recorder);
  CHECK(recorder.calls == "(m0)(m1)(m2)");
  recorder.calls.clear();
  g::expandIfs(sierpinski.ifs, 0, recorder);
  CHECK(recorder.calls == "-1");
  recorder.calls.clear();
  g::expandIfs(sierpinski.ifs, 5, recorder);
  CHECK(recorder.depth == 0);
  CHECK(recorder.maxDepth == 5);
  CHECK(g::ifsBaseCopies(sierpinski.ifs, 5) == 243);

  // Depth 2: nine composites f_i o f_j, part i, in the order the recursion draws them.
  const auto composites = g::ifsComposites(sierpinski.ifs, 2);
  REQUIRE(composites.size() == 9);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const auto& c = composites[3 * i + j];
      CHECK(c.part == i);
      CHECK(near(c.transform, sierpinski.ifs.maps[i].transform * sierpinski.ifs.maps[j].transform));
    }
  }
  CHECK(g::ifsBaseCopies(sierpinski.ifs, 100) == UINT64_MAX);  // saturates
}

TEST_CASE("course 2.2: the chaos game is deterministic and each point lies in its part") {
  const auto q3 = g::loadIfsFile(exampleFile("test_question_3.ifs"));
  REQUIRE(q3.ok());
  const auto probabilities = g::chaosGameProbabilities(q3.ifs);
  REQUIRE(probabilities.has_value());
  // Proportional to |det|: 1/4, 1/16, 1/4, 1/4 normalised.
  CHECK((*probabilities)[0] == doctest::Approx(4.0 / 13));
  CHECK((*probabilities)[1] == doctest::Approx(1.0 / 13));
  const auto a = g::chaosGamePoints(q3.ifs, *probabilities, 10000, 42);
  const auto b = g::chaosGamePoints(q3.ifs, *probabilities, 10000, 42);
  const auto c = g::chaosGamePoints(q3.ifs, *probabilities, 10000, 43);
  REQUIRE(a.size() == 10000);
  bool same = true, differs = false;
  int counts[4] = {};
  for (std::size_t k = 0; k < a.size(); ++k) {
    same = same && a[k].position == b[k].position && a[k].part == b[k].part;
    differs = differs || a[k].position != c[k].position;
    ++counts[a[k].part];
    // Part i is f_i(unit square): the quadrant of the map.
    const glm::dvec2 p = a[k].position;
    const double eps = 1e-12;
    CHECK(p.x >= -eps);
    CHECK(p.x <= 1 + eps);
    switch (a[k].part) {
      case 0: CHECK((p.x <= 0.5 + eps && p.y >= 0.5 - eps)); break;
      case 1: CHECK((p.x >= 0.75 - eps && p.y >= 0.75 - eps)); break;
      case 2: CHECK((p.x <= 0.5 + eps && p.y <= 0.5 + eps)); break;
      default: CHECK((p.x >= 0.5 - eps && p.y <= 0.5 + eps)); break;
    }
  }
  CHECK(same);
  CHECK(differs);
  CHECK(counts[1] == doctest::Approx(10000.0 / 13).epsilon(0.15));

  // Explicit probabilities are normalised; mixed ones are refused.
  g::IteratedFunctionSystem mixed = q3.ifs;
  mixed.maps[0].probability = 1.0;
  CHECK_FALSE(g::chaosGameProbabilities(mixed).has_value());
  for (auto& map : mixed.maps) map.probability = 3.0;
  CHECK((*g::chaosGameProbabilities(mixed))[2] == 0.25);
}

TEST_CASE("course 2.2: Listing 5's resizeWindow keeps the aspect ratio") {
  const g::IfsWindow listing5;  // [-0.1, 1.1]^2
  // A square viewport keeps the window.
  const g::IfsWindow square = g::fitWindowToAspect(listing5, 500, 500);
  CHECK(square.xMin == doctest::Approx(-0.1));
  CHECK(square.xMax == doctest::Approx(1.1));
  CHECK(square.yMin == doctest::Approx(-0.1));
  CHECK(square.yMax == doctest::Approx(1.1));
  // A wide viewport widens x about its centre 0.5: 1.2 * 2 = 2.4 wide.
  const g::IfsWindow wide = g::fitWindowToAspect(listing5, 1000, 500);
  CHECK(wide.xMin == doctest::Approx(-0.7));
  CHECK(wide.xMax == doctest::Approx(1.7));
  CHECK(wide.yMin == -0.1);
  CHECK(wide.yMax == 1.1);
  const g::IfsWindow tall = g::fitWindowToAspect(listing5, 300, 600);
  CHECK(tall.xMin == -0.1);
  CHECK(tall.yMin == doctest::Approx(-0.7));
  CHECK(tall.yMax == doctest::Approx(1.7));
  // Units per pixel end up equal on both axes.
  CHECK((tall.xMax - tall.xMin) / 300 == doctest::Approx((tall.yMax - tall.yMin) / 600));
}

TEST_CASE("course 2.2: the fitted window surrounds the attractor with a 10% margin") {
  const auto sierpinski = g::loadIfsFile(exampleFile("sierpinski.ifs"));
  REQUIRE(sierpinski.ok());
  // The corners (0,0), (1,0), (0,1) are fixed points of the three maps: Listing 5's window.
  const g::IfsWindow window = g::attractorWindow(sierpinski.ifs);
  CHECK(window.xMin == doctest::Approx(-0.1));
  CHECK(window.xMax == doctest::Approx(1.1));
  CHECK(window.yMin == doctest::Approx(-0.1));
  CHECK(window.yMax == doctest::Approx(1.1));
  const auto fern = g::loadIfsFile(exampleFile("fern.ifs"));
  REQUIRE(fern.ok());
  const g::IfsWindow fernWindow = g::attractorWindow(fern.ifs);
  for (const auto& p : g::chaosGamePoints(fern.ifs, *g::chaosGameProbabilities(fern.ifs), 100000, 9)) {
    CHECK((p.position.x > fernWindow.xMin && p.position.x < fernWindow.xMax &&
           p.position.y > fernWindow.yMin && p.position.y < fernWindow.yMax));
  }
}

TEST_CASE("course 2.2: similarity ratios and the Moran equation") {
  CHECK(*g::similarityRatio(Affine2::rotationDegrees(30) * Affine2::scaling(0.3, 0.3)) == doctest::Approx(0.3));
  CHECK(*g::similarityRatio(Affine2::scaling(-0.5, 0.5)) == 0.5);  // a reflection is allowed
  CHECK_FALSE(g::similarityRatio(Affine2::scaling(0.5, 0.25)).has_value());
  CHECK_FALSE(g::similarityRatio(Affine2::shear(0.1)).has_value());
  CHECK(*g::similarityRatio(Affine2::fromRows(0, 0, 1, 0, 0, 2)) == 0.0);
  // Four halves tile the square: dimension 2; two thirds (Cantor): log 2 / log 3.
  const double halves[] = {0.5, 0.5, 0.5, 0.5};
  CHECK(*g::solveMoranEquation(halves) == doctest::Approx(2.0).epsilon(1e-15));
  const double thirds[] = {1.0 / 3, 1.0 / 3};
  CHECK(*g::solveMoranEquation(thirds) == doctest::Approx(std::log(2.0) / std::log(3.0)).epsilon(1e-15));
  const double single[] = {0.5, 0.0};
  CHECK(*g::solveMoranEquation(single) == 0.0);
  const double expanding[] = {0.5, 1.5};
  CHECK_FALSE(g::solveMoranEquation(expanding).has_value());
}
