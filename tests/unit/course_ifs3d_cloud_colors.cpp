// Homework 3: the colours of a cloud read from a file in `glass ifs3d view` (each point in the
// colour of the map whose image passes nearest, grey where none does; a height ramp without maps).
#include <doctest/doctest.h>

#include <vector>

#include "glass/course/ifs3d_cloud_colors.h"
#include "glass/geometry/ifs3d.h"
#include "glass/geometry/ifs3d_format.h"

namespace g = glass::geometry;
namespace c = glass::course;

namespace {

// Four maps of ratio 0.4 at four corners of the unit cube: parts with gaps between them, so
// each point has one right part, the map the chaos game applied last.
constexpr const char* kSeparateParts = "map scale 0.4\n"
                                       "map translate 0.6 0 0 rotate 90 0 0 1 translate 0 -0.4 0 scale 0.4\n"
                                       "map translate 0 0.6 0 scale 0.4 0.4 -0.4 translate 0 0 -1\n"
                                       "map translate 0.3 0.3 0.6 rotate 30 1 1 1 scale 0.35\n";

}  // namespace

TEST_CASE("course homework 3: a file's cloud is split into the parts of the maps") {
  const auto parsed = g::parseIfs3(kSeparateParts);
  REQUIRE(parsed.ok());
  const auto probabilities = g::chaosGameProbabilities3(parsed.ifs);
  REQUIRE(probabilities);
  std::vector<glm::dvec3> cloud;
  std::vector<int> truth;
  for (const g::IfsPoint3& p : g::chaosGamePoints3(parsed.ifs, *probabilities, 20000, 3)) {
    cloud.push_back(p.position);
    truth.push_back(static_cast<int>(p.part));
  }
  // Two points far from every part: no map explains them.
  cloud.push_back({3.0, 3.0, 3.0});
  cloud.push_back({-2.0, 0.5, 0.5});
  std::vector<g::Affine3> maps;
  for (const g::IfsMap3& map : parsed.ifs.maps) maps.push_back(map.transform);
  // Fewer images than points, so that the sampling of the images is exercised too.
  const std::vector<int> parts = c::cloudPartsByMaps(cloud, maps, 12000);
  REQUIRE(parts.size() == cloud.size());
  std::size_t agree = 0, unexplained = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    agree += parts[i] == truth[i];
    unexplained += parts[i] == c::kUnexplainedPoint;
  }
  INFO("agree " << agree << " of " << truth.size() << ", unexplained " << unexplained);
  // Separate parts: all but a few points (at most 0.2%) take the part that made them, and
  // no point of the attractor is called unexplained.
  CHECK(agree >= truth.size() * 998 / 1000);
  CHECK(unexplained == 0);
  CHECK(parts[truth.size()] == c::kUnexplainedPoint);
  CHECK(parts[truth.size() + 1] == c::kUnexplainedPoint);
  CHECK(c::cloudPartsByMaps(cloud, {}).empty());
  CHECK(c::cloudPartsByMaps({}, maps).empty());
}

TEST_CASE("course homework 3: the height ramp of a cloud without maps") {
  CHECK(c::heightRampColor(0.0) == glm::vec3(0.25f, 0.45f, 1.0f));
  CHECK(c::heightRampColor(1.0) == glm::vec3(1.0f, 0.35f, 0.2f));
  CHECK(c::heightRampColor(-3.0) == c::heightRampColor(0.0));
  CHECK(c::heightRampColor(7.0) == c::heightRampColor(1.0));
  CHECK(c::heightRampColor(0.5) == glm::vec3(0.35f, 0.9f, 0.3f));
  // Half way between the first two stops.
  const glm::vec3 eighth = c::heightRampColor(0.125);
  CHECK(eighth.r == doctest::Approx(0.175f));
  CHECK(eighth.g == doctest::Approx(0.625f));
  CHECK(eighth.b == doctest::Approx(0.95f));
  // By height (y) over the cloud's own range; a flat cloud is all the middle colour.
  const std::vector<glm::dvec3> cloud{{0.2, 2.0, 0.0}, {0.5, 4.0, 1.0}, {0.9, 3.0, 0.3}};
  const std::vector<glm::vec3> colors = c::heightColors(cloud);
  REQUIRE(colors.size() == 3);
  CHECK(colors[0] == c::heightRampColor(0.0));
  CHECK(colors[1] == c::heightRampColor(1.0));
  CHECK(colors[2] == c::heightRampColor(0.5));
  const std::vector<glm::dvec3> flat{{0.0, 1.0, 0.0}, {1.0, 1.0, 1.0}};
  for (const glm::vec3& color : c::heightColors(flat)) CHECK(color == c::heightRampColor(0.5));
}
