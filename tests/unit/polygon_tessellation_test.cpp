// The planar polygon tessellation under GLU's tessellator (glass/geometry/polygon_tessellation.h):
// triangles that cover exactly the region the winding rule selects, counter-clockwise, from the
// input vertices and crossings only; boundary loops with the region on their left; edge flags.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "glass/geometry/polygon_tessellation.h"

using glass::geometry::PlanarPoint;
using glass::geometry::PolygonTessellation;
using glass::geometry::tessellatePolygon;
using glass::geometry::WindingRule;
using Contours = std::vector<std::vector<PlanarPoint>>;

namespace {

std::vector<PlanarPoint> allPoints(const Contours& contours, const PolygonTessellation& t) {
  std::vector<PlanarPoint> points;
  for (const auto& c : contours) points.insert(points.end(), c.begin(), c.end());
  for (const auto& v : t.created) points.push_back(v.position);
  return points;
}

double signedArea(const PlanarPoint& a, const PlanarPoint& b, const PlanarPoint& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// The area the triangles cover; every triangle must be counter-clockwise.
double coveredArea(const Contours& contours, WindingRule rule) {
  const PolygonTessellation t = tessellatePolygon(contours, rule, false);
  const auto points = allPoints(contours, t);
  double area = 0.0;
  for (const auto& triangle : t.triangles) {
    const double a = signedArea(points[triangle.vertices[0]], points[triangle.vertices[1]],
                                points[triangle.vertices[2]]);
    CHECK(a >= 0.0);
    area += a;
  }
  return area;
}

// The area the boundary loops enclose (counter-clockwise loops count positive).
double loopArea(const Contours& contours, WindingRule rule) {
  const PolygonTessellation t = tessellatePolygon(contours, rule, true);
  const auto points = allPoints(contours, t);
  double area = 0.0;
  for (const auto& loop : t.boundaryLoops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const PlanarPoint& a = points[loop[k]];
      const PlanarPoint& b = points[loop[(k + 1) % loop.size()]];
      area += 0.5 * (a.x * b.y - b.x * a.y);
    }
  }
  return area;
}

const Contours kNestedSameDirection = {{{0, 0}, {3, 0}, {3, 3}, {0, 3}},
                                       {{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
const Contours kNestedOpposite = {{{0, 0}, {3, 0}, {3, 3}, {0, 3}},
                                  {{1, 1}, {1, 2}, {2, 2}, {2, 1}}};

}  // namespace

TEST_CASE("Simple and concave contours are covered exactly, either orientation") {
  CHECK(coveredArea({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, WindingRule::Odd) == doctest::Approx(1));
  CHECK(coveredArea({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, WindingRule::Odd) == doctest::Approx(1));
  const Contours l = {{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  CHECK(coveredArea(l, WindingRule::NonZero) == doctest::Approx(3));
  // Clockwise contours have winding number -1 inside.
  CHECK(coveredArea({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, WindingRule::Positive) == 0.0);
  CHECK(coveredArea({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, WindingRule::Negative) ==
        doctest::Approx(1));
}

TEST_CASE("Nested contours under each winding rule") {
  // Same direction: winding 1 in the ring, 2 in the middle.
  CHECK(coveredArea(kNestedSameDirection, WindingRule::Odd) == doctest::Approx(8));
  CHECK(coveredArea(kNestedSameDirection, WindingRule::NonZero) == doctest::Approx(9));
  CHECK(coveredArea(kNestedSameDirection, WindingRule::Positive) == doctest::Approx(9));
  CHECK(coveredArea(kNestedSameDirection, WindingRule::Negative) == 0.0);
  CHECK(coveredArea(kNestedSameDirection, WindingRule::AbsGeqTwo) == doctest::Approx(1));
  // Opposite directions: a hole (winding 0) under every rule but NEGATIVE, which selects nothing.
  CHECK(coveredArea(kNestedOpposite, WindingRule::Odd) == doctest::Approx(8));
  CHECK(coveredArea(kNestedOpposite, WindingRule::NonZero) == doctest::Approx(8));
  CHECK(coveredArea(kNestedOpposite, WindingRule::Negative) == 0.0);
  const Contours twoHoles = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                             {{1, 1}, {1, 3}, {3, 3}, {3, 1}},
                             {{5, 5}, {5, 8}, {8, 8}, {8, 5}}};
  CHECK(coveredArea(twoHoles, WindingRule::Odd) == doctest::Approx(100 - 4 - 9));
}

TEST_CASE("Crossing contours: crossings become created vertices with GLU's weights") {
  // A bowtie: two triangles of area 1 meeting at (1, 1), one counter-clockwise, one clockwise.
  const Contours bowtie = {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
  CHECK(coveredArea(bowtie, WindingRule::Odd) == doctest::Approx(2));
  CHECK(coveredArea(bowtie, WindingRule::Positive) == doctest::Approx(1));
  const PolygonTessellation t = tessellatePolygon(bowtie, WindingRule::Odd, false);
  REQUIRE(t.created.size() == 1);
  const auto& crossing = t.created[0];
  CHECK(crossing.isCrossing);
  CHECK(crossing.position == PlanarPoint{1, 1});
  // Edges (0,0)-(2,2) and (2,0)-(0,2), each crossed half way: 1/4 to each end.
  for (int k = 0; k < 4; ++k) CHECK(crossing.weights[k] == doctest::Approx(0.25));

  // A pentagram: NONZERO covers the inner pentagon too, ODD does not.
  Contours star(1);
  for (int i = 0; i < 5; ++i) {
    const double a = M_PI / 2 + i * 4 * M_PI / 5;
    star[0].push_back({std::cos(a), std::sin(a)});
  }
  const double pentagram = 1.1225699414489640;  // area of the star of circumradius 1
  const double inner = 0.3468909321789;           // its inner pentagon
  CHECK(coveredArea(star, WindingRule::NonZero) == doctest::Approx(pentagram));
  CHECK(coveredArea(star, WindingRule::Odd) == doctest::Approx(pentagram - inner));
  CHECK(coveredArea(star, WindingRule::AbsGeqTwo) == doctest::Approx(inner));
}

TEST_CASE("Vertices at the same position merge; shared edges and touching contours") {
  const Contours closedTwice = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}};
  const PolygonTessellation t = tessellatePolygon(closedTwice, WindingRule::Odd, false);
  REQUIRE(t.created.size() == 1);
  CHECK_FALSE(t.created[0].isCrossing);
  CHECK(t.created[0].sources[0] == 0);
  CHECK(t.created[0].sources[1] == 4);
  CHECK(coveredArea(closedTwice, WindingRule::Odd) == doctest::Approx(1));
  const Contours sideBySide = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}};
  CHECK(coveredArea(sideBySide, WindingRule::NonZero) == doctest::Approx(2));
  const Contours holeTouchingOutside = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 0}, {1, 2}, {2, 1}}};
  CHECK(coveredArea(holeTouchingOutside, WindingRule::Odd) == doctest::Approx(14.5));
  // T-junction: a vertex on another contour's edge splits it without a created vertex.
  const Contours tJunction = {{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {{1, 1}, {2, 2}, {0, 2}}};
  CHECK(coveredArea(tJunction, WindingRule::NonZero) == doctest::Approx(3));
  CHECK(tessellatePolygon(tJunction, WindingRule::NonZero, false).created.empty());
}

TEST_CASE("Degenerate input gives no triangles") {
  CHECK(tessellatePolygon({{{0, 0}, {1, 0}, {2, 0}}}, WindingRule::Odd, false).triangles.empty());
  CHECK(tessellatePolygon({{{0, 0}, {1, 1}}}, WindingRule::Odd, false).triangles.empty());
  CHECK(tessellatePolygon({{}}, WindingRule::Odd, false).triangles.empty());
  CHECK(tessellatePolygon({}, WindingRule::Odd, false).triangles.empty());
}

TEST_CASE("Boundary loops enclose the region, counter-clockwise around it") {
  CHECK(loopArea(kNestedOpposite, WindingRule::Odd) == doctest::Approx(8));
  CHECK(loopArea(kNestedSameDirection, WindingRule::NonZero) == doctest::Approx(9));
  CHECK(tessellatePolygon(kNestedSameDirection, WindingRule::NonZero, true).boundaryLoops.size() ==
        1);
  CHECK(tessellatePolygon(kNestedOpposite, WindingRule::Odd, true).boundaryLoops.size() == 2);
  const Contours overlapping = {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
  CHECK(loopArea(overlapping, WindingRule::NonZero) == doctest::Approx(7));
}

TEST_CASE("Edge flags mark the region's boundary, not the diagonals") {
  // A square with a square hole: 8 boundary edges, the rest are diagonals and bridges.
  const PolygonTessellation t = tessellatePolygon(kNestedOpposite, WindingRule::Odd, false);
  int boundary = 0, interior = 0;
  for (const auto& triangle : t.triangles) {
    for (bool flag : triangle.boundaryEdge) (flag ? boundary : interior)++;
  }
  CHECK(boundary == 8);
  CHECK(interior == 3 * static_cast<int>(t.triangles.size()) - 8);
  // Two faces of the same region (NONZERO over nested same-direction squares): the edges
  // between them are inside the region.
  const PolygonTessellation u = tessellatePolygon(kNestedSameDirection, WindingRule::NonZero, false);
  boundary = 0;
  for (const auto& triangle : u.triangles) {
    for (bool flag : triangle.boundaryEdge) boundary += flag ? 1 : 0;
  }
  CHECK(boundary == 4);
}
