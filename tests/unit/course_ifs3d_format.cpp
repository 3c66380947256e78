// Homework 3 of the study guide: the .ifs3 format (shared with the 2D .ifs reader), clouds of
// points, the k-d tree, the polyhedral rebuild and the dimension.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "glass/course/point_cloud.h"
#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/ifs3d.h"
#include "glass/geometry/ifs3d_format.h"
#include "glass/geometry/kd_tree.h"

namespace g = glass::geometry;
namespace c = glass::course;

namespace {

std::string exampleFile(const char* name) { return std::string(GLASS_SOURCE_DIR) + "/scenes/ifs/" + name; }

}  // namespace

TEST_CASE("course homework 3: .ifs3 operations compose left to right like GL calls") {
  const auto result = g::parseIfs3(
      "name \"test\"\n"
      "map translate 0.5 0 0 rotate 90 0 0 1 scale 0.5 0.25 0.5 color 1 0 0 probability 2\n"
      "map matrix 0.5 0 0 0.1  0 0.5 0 0.2  0 0 0.5 0.3 probability 1\n"
      "map rotate quaternion 0 0 0 2 scale 0.5 probability 1   # a half turn about z\n");
  REQUIRE(result.ok());
  REQUIRE(result.ifs.maps.size() == 3);
  // T(0.5,0,0) Rz(90) S(0.5,0.25,0.5): x' = 0.5 - 0.25 y, y' = 0.5 x, z' = 0.5 z.
  const g::Affine3 expected = g::Affine3::fromRows({0, -0.25, 0, 0.5, 0.5, 0, 0, 0, 0, 0, 0.5, 0});
  CHECK(g::Affine3::maxDifference(result.ifs.maps[0].transform, expected) == 0.0);
  CHECK(result.ifs.maps[0].color == g::IfsColor{1, 0, 0});
  CHECK(*result.ifs.maps[1].probability == 1.0);
  CHECK(result.ifs.maps[1].transform.m[2][3] == 0.3);
  const g::Affine3 halfTurn = g::Affine3::fromRows({-0.5, 0, 0, 0, 0, -0.5, 0, 0, 0, 0, 0.5, 0});
  CHECK(g::Affine3::maxDifference(result.ifs.maps[2].transform, halfTurn) < 1e-15);
}

TEST_CASE("course homework 3: .ifs3 errors give line and column, as the 2D format does") {
  auto first = [](const char* text) {
    const auto r = g::parseIfs3(text);
    REQUIRE_FALSE(r.ok());
    return r.errors.front();
  };
  auto e = first("map scale 0.5\nmap translate 1 2\n");
  CHECK(e.line == 2);
  CHECK(e.message.find("translate x y z") != std::string::npos);
  e = first("map rotate 30 0 0 0\n");
  CHECK(e.column == 15);
  CHECK(e.message.find("axis cannot be 0 0 0") != std::string::npos);
  e = first("map scale 0.5 0.5\n");
  CHECK(e.message.find("scale y z") != std::string::npos);
  e = first("map shear 1\n");
  CHECK(e.message.find("unknown map operation 'shear'") != std::string::npos);
  e = first("map scale 0.5 probability 1\nmap scale 0.25\n");
  CHECK(e.line == 2);
  CHECK(e.message.find("give all or none") != std::string::npos);
  e = first("base sphere\nmap scale 0.5\n");
  CHECK(e.message.find("cube, tetrahedron, hull or \"model.obj\"") != std::string::npos);
  e = first("map rotate quaternion 0 0 0 0\n");
  CHECK(e.message.find("zero quaternion") != std::string::npos);
  e = first("# nothing\n");
  CHECK(e.message.find("no maps") != std::string::npos);
  const std::string text = "map scale 0.5 color 2 0 0\n";
  const auto r = g::parseIfs3(text);
  CHECK(g::formatIfsErrors(r.errors, "x.ifs3", text) ==
        "x.ifs3:1:21: error: colour components must lie in [0, 1]\n  map scale 0.5 color 2 0 0\n                      ^\n");
}

TEST_CASE("course homework 3: a byte order mark before an .ifs or .ifs3 file is skipped") {
  const std::string bom = "\xEF\xBB\xBF";
  const auto with = g::parseIfs3(bom + "map scale 0.5\nmap translate 0.5 0 0 scale 0.5\n");
  const auto without = g::parseIfs3("map scale 0.5\nmap translate 0.5 0 0 scale 0.5\n");
  REQUIRE(with.ok());
  REQUIRE(with.ifs.maps.size() == without.ifs.maps.size());
  CHECK(g::formatIfs3(with.ifs) == g::formatIfs3(without.ifs));
  // Columns of the first line count from after the mark, as an editor shows them.
  const auto bad = g::parseIfs3(bom + "map rotate 30 0 0 0\n");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.errors.front().column == 15);
  REQUIRE(g::parseIfs(bom + "map scale 0.5\nmap translate 0.5 0 scale 0.5\n").ok());
  // Only at the start of the file.
  CHECK_FALSE(g::parseIfs3("map scale 0.5\n" + bom + "map scale 0.5\n").ok());
}

TEST_CASE("course homework 3: formatIfs3 writes what parseIfs3 reads back exactly") {
  const auto loaded = g::loadIfs3File(exampleFile("homework3.ifs3"));
  REQUIRE(loaded.ok());
  const auto again = g::parseIfs3(g::formatIfs3(loaded.ifs));
  REQUIRE(again.ok());
  REQUIRE(again.ifs.maps.size() == loaded.ifs.maps.size());
  for (std::size_t i = 0; i < loaded.ifs.maps.size(); ++i) {
    CHECK(again.ifs.maps[i].transform == loaded.ifs.maps[i].transform);
    CHECK(again.ifs.maps[i].color == loaded.ifs.maps[i].color);
  }
  CHECK(again.ifs.name == loaded.ifs.name);
}

TEST_CASE("course homework 3: the 2D format still reads through the shared line reader") {
  const auto r = g::parseIfs("map scale 0.5 color 0.2 0.3 0.4 probability 0.5\nmap translate 0.5 0 scale 0.5 probability 0.5\n");
  REQUIRE(r.ok());
  CHECK(r.ifs.maps[0].color == g::IfsColor{0.2f, 0.3f, 0.4f});
  const auto bad = g::parseIfs("map scale 0.5 probability -1\n");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.errors.front().column == 27);
}

TEST_CASE("course homework 3: clouds of points read with counts, commas, comments; errors and warnings") {
  const auto cloud = c::parsePointCloud("3\n0 0 0\n0.5,0.5,0.5 # a comment\n\t1\t1\t1\n");
  REQUIRE(cloud.ok());
  REQUIRE(cloud.points.size() == 3);
  CHECK(cloud.points[1] == glm::dvec3(0.5));
  // 3 points: too few for a fit.
  REQUIRE(cloud.warnings.size() == 1);
  CHECK(cloud.warnings[0].message.find("only 3 points") != std::string::npos);

  const auto bad = c::parsePointCloud("0 0 0\n0 0\n1 x 1\n1 1 1 1\n");
  REQUIRE(bad.errors.size() == 3);
  CHECK(bad.errors[0].line == 2);
  CHECK(bad.errors[1].line == 3);
  CHECK(bad.errors[1].column == 3);
  CHECK(bad.errors[2].column == 7);
  CHECK(c::formatCloudMessages(bad, "c.txt").rfind("c.txt:2:1: error: a point is three numbers x y z; this line has 2\n", 0) == 0);

  std::string many = "10\n";
  for (int i = 0; i < 600; ++i) many += std::to_string(i) + " 0 0\n";
  const auto far = c::parsePointCloud(many);
  REQUIRE(far.ok());
  REQUIRE(far.warnings.size() == 2);
  CHECK(far.warnings[0].message == "the first line says 10 points, but the file has 600");
  CHECK(far.warnings[1].message.find("not in the unit cube") != std::string::npos);
  CHECK_FALSE(c::parsePointCloud("# empty\n").ok());
  CHECK_FALSE(c::parsePointCloud("1 2 inf\n").ok());
}

TEST_CASE("course homework 3: clouds from other tools: byte order mark, CR line ends, column names") {
  // A spreadsheet's export: a byte order mark, a line of column names, CR LF.
  const auto csv = c::parsePointCloud("\xEF\xBB\xBFx,y,z\r\n0,0,0\r\n0.25,0.5,1\r\n");
  REQUIRE(csv.ok());
  REQUIRE(csv.points.size() == 2);
  CHECK(csv.points[1] == glm::dvec3(0.25, 0.5, 1));
  // Lines ending in a lone CR; an error names the right line and column.
  const auto mac = c::parsePointCloud("2\r0 0 0\r1 1 q\r");
  REQUIRE(mac.errors.size() == 1);
  CHECK(mac.errors[0].line == 3);
  CHECK(mac.errors[0].column == 5);
  // Column names are taken only before the points, and only as a whole line of names.
  const auto late = c::parsePointCloud("0 0 0\nx y z\n");
  REQUIRE(late.errors.size() == 1);
  CHECK(late.errors[0].line == 2);
  CHECK(c::parsePointCloud("x 1 z\n0 0 0\n").errors.size() == 1);
  // A byte order mark anywhere else is not skipped.
  CHECK_FALSE(c::parsePointCloud("0 0 0\n\xEF\xBB\xBF1 1 1\n").ok());
}

namespace {

// The k-d tree's nearest point to p against a search of every point: the same index (the least
// on ties) and the same squared distance.
void checkNearestAgainstEveryPoint(const g::KdTree3& tree, const std::vector<glm::dvec3>& points, const glm::dvec3& p) {
  std::uint32_t best = 0;
  double bestD = INFINITY;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const glm::dvec3 d = points[i] - p;
    const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
    if (d2 < bestD) {
      bestD = d2;
      best = i;
    }
  }
  const auto found = tree.nearest(p);
  CHECK(found.index == best);
  CHECK(found.distanceSquared == bestD);
}

}  // namespace

TEST_CASE("course homework 3: the k-d tree finds the same nearest point as a search of all") {
  g::SplitMix64 random(3);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 3000; ++i) points.push_back({random.uniform(), random.uniform(), std::floor(random.uniform() * 4) / 4});
  points.push_back(points[17]);  // a duplicate: the lower index wins
  const g::KdTree3 tree(points);
  for (int q = 0; q < 500; ++q) {
    const glm::dvec3 p{random.uniform() * 3 - 1, random.uniform() * 3 - 1, random.uniform() * 3 - 1};
    checkNearestAgainstEveryPoint(tree, points, p);
  }
  CHECK(tree.nearest(points[17]).index == 17);
}

TEST_CASE("course homework 3: the k-d tree prunes by its points' boxes and stays exact in hollows and on ties") {
  // The search skips a subtree when the bounding box of its points is farther than the best point
  // so far. A hollow cloud (the lattice points on the faces of a cube) queried from inside, where
  // the boxes and the split cells differ most, and lattice queries with many points at exactly the
  // same distance (the centre is equidistant from the six face centres): the nearest point of
  // least index, as a search of all points finds it.
  std::vector<glm::dvec3> points;
  for (int z = 0; z <= 8; ++z)
    for (int y = 0; y <= 8; ++y)
      for (int x = 0; x <= 8; ++x)
        if (x == 0 || x == 8 || y == 0 || y == 8 || z == 0 || z == 8) points.push_back(glm::dvec3(x, y, z) / 8.0);
  g::SplitMix64 random(11);
  std::vector<glm::dvec3> queries{{0.5, 0.5, 0.5}};
  for (int q = 0; q < 400; ++q) queries.push_back(glm::dvec3(random.below(33), random.below(33), random.below(33)) / 16.0 - 0.5);
  for (int q = 0; q < 400; ++q) queries.push_back({0.2 + 0.6 * random.uniform(), 0.2 + 0.6 * random.uniform(), 0.2 + 0.6 * random.uniform()});
  const g::KdTree3 tree(points);
  for (const glm::dvec3& p : queries) {
    checkNearestAgainstEveryPoint(tree, points, p);
  }
}

TEST_CASE("course homework 3: the polyhedral rebuild: counts, outward normals, the limit") {
  auto loaded = g::loadIfs3File(exampleFile("homework3.ifs3"));
  REQUIRE(loaded.ok());
  std::string problem;
  const auto depth0 = g::polyhedralRebuild(loaded.ifs, 0, g::kMaxRebuildTriangles, problem);
  REQUIRE(depth0.size() == 12);
  for (const auto& t : depth0) {
    const glm::dvec3 centroid = (t.corners.a + t.corners.b + t.corners.c) / 3.0;
    CHECK(glm::dot(t.normal, centroid - glm::dvec3(0.5)) > 0.0);
  }
  const auto depth2 = g::polyhedralRebuild(loaded.ifs, 2, g::kMaxRebuildTriangles, problem);
  REQUIRE(depth2.size() == 12 * 16);
  // Map 4 reflects: its copies are turned inside out and back, so normals still point out of each
  // copy (away from the copy's centre).
  for (std::size_t copy = 0; copy < 16; ++copy) {
    glm::dvec3 centre(0.0);
    for (int k = 0; k < 12; ++k) centre += depth2[copy * 12 + k].corners.a + depth2[copy * 12 + k].corners.b + depth2[copy * 12 + k].corners.c;
    centre /= 36.0;
    for (int k = 0; k < 12; ++k) {
      const auto& t = depth2[copy * 12 + k];
      CHECK(glm::dot(t.normal, (t.corners.a + t.corners.b + t.corners.c) / 3.0 - centre) > 0.0);
    }
  }
  CHECK(depth2[4 * 12 * 3].part == 3);
  const auto tooMany = g::polyhedralRebuild(loaded.ifs, 11, g::kMaxRebuildTriangles, problem);
  CHECK(tooMany.empty());
  CHECK(problem == "depth 11 would draw 12 x 4^11 triangles, more than the limit of 2000000; lower the depth");
}

TEST_CASE("course homework 3: convex hull base and dimensions") {
  auto tetra = g::loadIfs3File(exampleFile("sierpinski_tetrahedron.ifs3"));
  REQUIRE(tetra.ok());
  const auto report = g::ifsDimension3(tetra.ifs);
  REQUIRE(report.moranDimension);
  CHECK(*report.moranDimension == doctest::Approx(2.0).epsilon(1e-12));
  // The hull of the Sierpinski tetrahedron is the tetrahedron: 4 faces.
  tetra.ifs.base = g::IfsBase3::Hull;
  CHECK(g::basePolyhedron(tetra.ifs).size() == 4);
  // Maps that are not similarities: the square z = 0 filled by four maps that also flatten z.
  const auto flat = g::parseIfs3(
      "map scale 0.5 0.5 0.3\nmap translate 0.5 0 0 scale 0.5 0.5 0.3\n"
      "map translate 0 0.5 0 scale 0.5 0.5 0.3\nmap translate 0.5 0.5 0 scale 0.5 0.5 0.3\n");
  REQUIRE(flat.ok());
  const auto box = g::ifsDimension3(flat.ifs, 400000, 1);
  CHECK_FALSE(box.allSimilarities);
  REQUIRE(box.boxCounting);
  CHECK(box.boxCounting->dimension == doctest::Approx(2.0).epsilon(0.05));
}
