// The worked answers of the study guide's section 3.2 (test questions 1 to 4), each reproduced.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "glass/geometry/affine2d.h"
#include "glass/geometry/affine_decomposition.h"
#include "glass/geometry/deterministic_random.h"
#include "glass/geometry/ifs.h"
#include "glass/geometry/ifs_dimension.h"
#include "glass/geometry/quaternion.h"
#include "glass/geometry/rotation.h"

namespace g = glass::geometry;
using g::Affine2;

namespace {

bool near(const Affine2& a, const Affine2& b, double eps = 1e-12) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c)
      if (std::abs(a.m[r][c] - b.m[r][c]) > eps) return false;
  return true;
}
bool near(const glm::dvec2& a, const glm::dvec2& b, double eps = 1e-12) {
  return glm::length(a - b) <= eps;
}

}  // namespace

TEST_CASE("course test 1: the triangles drawn through the matrix stack of Listing 6") {
  // glRotatef(45, z); glTranslatef(2, 0, 0); push; glTranslatef(0, -2, 0); drawTriangle(); pop;
  // glRotatef(180, z); glTranslatef(0, -2, 0); drawTriangle();
  // The modelview matrix multiplies on the right, so each vertex goes through the calls in
  // reverse order. By hand, with c = s = 1/sqrt2:
  //   first triangle  R45 T(2, 0) T(0, -2):        (2 sqrt2, 0), (5/sqrt2, 1/sqrt2), (sqrt2, sqrt2)
  //   second triangle R45 T(2, 0) R180 T(0, -2):   (0, 2 sqrt2), (-1/sqrt2, 3/sqrt2), (sqrt2, sqrt2)
  // The two share the vertex (sqrt2, sqrt2), the image of the third corner (0, 2) in both.
  const Affine2 base = Affine2::rotationDegrees(45) * Affine2::translation(2, 0);
  const Affine2 first = base * Affine2::translation(0, -2);
  const Affine2 second = base * Affine2::rotationDegrees(180) * Affine2::translation(0, -2);
  const glm::dvec2 corners[3] = {{0, 0}, {1, 0}, {0, 2}};
  const double r2 = std::sqrt(2.0);
  const glm::dvec2 expectedFirst[3] = {{2 * r2, 0}, {5 / r2, 1 / r2}, {r2, r2}};
  const glm::dvec2 expectedSecond[3] = {{0, 2 * r2}, {-1 / r2, 3 / r2}, {r2, r2}};
  for (int i = 0; i < 3; ++i) {
    CHECK(near(first.apply(corners[i]), expectedFirst[i]));
    CHECK(near(second.apply(corners[i]), expectedSecond[i]));
  }
  // Both keep the triangle's orientation (rotations and translations only) and its area 1.
  CHECK(first.determinant() == doctest::Approx(1.0));
  CHECK(second.determinant() == doctest::Approx(1.0));
}

TEST_CASE("course test 2: [-2 -1 2; -2 1 -1; 0 0 1] = T(2, -1) R(45 degrees) S(-2 sqrt2, sqrt2)") {
  const Affine2 a = Affine2::fromRows(-2, -1, 2, -2, 1, -1);
  const auto d = g::decomposeAffine(a);
  REQUIRE(d.has_value());
  CHECK_FALSE(d->needsShear);
  CHECK(d->translateX == 2.0);
  CHECK(d->translateY == -1.0);
  CHECK(d->rotationRadians == doctest::Approx(std::numbers::pi / 4).epsilon(1e-15));
  CHECK(d->scaleX == doctest::Approx(-2 * std::sqrt(2.0)).epsilon(1e-15));
  CHECK(d->scaleY == doctest::Approx(std::sqrt(2.0)).epsilon(1e-15));
  CHECK(near(d->product(), a));
  // The guide's factors, multiplied out as printed.
  const double h = 1 / std::sqrt(2.0);
  const Affine2 guide = Affine2::fromRows(1, 0, 2, 0, 1, -1) * Affine2::fromRows(h, -h, 0, h, h, 0) *
                        Affine2::fromRows(-2 * std::sqrt(2.0), 0, 0, 0, std::sqrt(2.0), 0);
  CHECK(near(guide, a));
}

TEST_CASE("course test 2: the general case needs a shear, T R H S") {
  g::SplitMix64 random(3);
  for (int trial = 0; trial < 500; ++trial) {
    const Affine2 a = Affine2::fromRows(4 * random.uniform() - 2, 4 * random.uniform() - 2,
                                        4 * random.uniform() - 2, 4 * random.uniform() - 2,
                                        4 * random.uniform() - 2, 4 * random.uniform() - 2);
    const auto d = g::decomposeAffine(a);
    REQUIRE(d.has_value());
    CHECK(near(d->product(), a, 1e-12));
    CHECK(d->rotationRadians > -std::numbers::pi / 2);
    CHECK(d->rotationRadians <= std::numbers::pi / 2 + 1e-15);
    CHECK(d->needsShear);  // random columns are never exactly orthogonal
  }
  // A shear alone.
  const auto shear = g::decomposeAffine(Affine2::shear(0.5));
  REQUIRE(shear.has_value());
  CHECK(shear->needsShear);
  CHECK(shear->shear == 0.5);
  CHECK(shear->rotationRadians == 0.0);
  CHECK(shear->scaleX == 1.0);
  CHECK(shear->scaleY == 1.0);
  // A reflection is a scaling by -1.
  const auto mirror = g::decomposeAffine(Affine2::scaling(1, -1));
  REQUIRE(mirror.has_value());
  CHECK_FALSE(mirror->needsShear);
  CHECK(mirror->scaleX * mirror->scaleY == -1.0);
  // Singular maps have no decomposition.
  CHECK_FALSE(g::decomposeAffine(Affine2::fromRows(1, 2, 0, 2, 4, 0)).has_value());
  CHECK_FALSE(g::decomposeAffine(Affine2::fromRows(0, 1, 5, 0, 1, 5)).has_value());
}

namespace {

// Test question 3's four maps, in the order of the guide's answer.
g::IteratedFunctionSystem testQuestion3() {
  g::IteratedFunctionSystem ifs;
  ifs.maps = {{Affine2::fromRows(0.5, 0, 0, 0, 0.5, 0.5), {}, {}},
              {Affine2::fromRows(0.25, 0, 0.75, 0, 0.25, 0.75), {}, {}},
              {Affine2::fromRows(0, -0.5, 0.5, 0.5, 0, 0), {}, {}},
              {Affine2::fromRows(0.5, 0, 0.5, 0, 0.5, 0), {}, {}}};
  return ifs;
}

}  // namespace

TEST_CASE("course test 3: four similarities, ratios 1/2, 1/4, 1/2, 1/2, dimension log2((3 + sqrt13)/2)") {
  const g::IteratedFunctionSystem ifs = testQuestion3();
  const double expectedRatios[4] = {0.5, 0.25, 0.5, 0.5};
  for (int i = 0; i < 4; ++i) {
    const auto r = g::similarityRatio(ifs.maps[i].transform);
    REQUIRE(r.has_value());
    CHECK(*r == expectedRatios[i]);
  }
  const g::IfsDimensionReport report = g::ifsDimension(ifs);
  CHECK(report.allSimilarities);
  REQUIRE(report.moranDimension.has_value());
  const double d = *report.moranDimension;
  CHECK(d == doctest::Approx(std::log2((3 + std::sqrt(13.0)) / 2)).epsilon(1e-14));
  CHECK(d == doctest::Approx(1.723678968).epsilon(1e-9));
  // x = 1/2^d is the positive root of x^2 + 3x - 1 = 0, x = (sqrt13 - 3)/2.
  const double x = std::pow(0.5, d);
  CHECK(x * x + 3 * x - 1 == doctest::Approx(0.0));
  CHECK(x == doctest::Approx((std::sqrt(13.0) - 3) / 2));
  // The four maps send the unit square onto its four quadrants (the guide: "visually
  // corresponding to the four quadrants"), the second onto a quarter of the top-right one.
  const glm::dvec2 centre{0.5, 0.5};
  CHECK(near(ifs.maps[0].transform.apply(centre), {0.25, 0.75}));
  CHECK(near(ifs.maps[1].transform.apply(centre), {0.875, 0.875}));
  CHECK(near(ifs.maps[2].transform.apply(centre), {0.25, 0.25}));
  CHECK(near(ifs.maps[3].transform.apply(centre), {0.75, 0.25}));
}

TEST_CASE("course 2.2.2: the Sierpinski triangle has dimension log 3 / log 2") {
  g::IteratedFunctionSystem ifs;
  ifs.maps = {{Affine2::scaling(0.5, 0.5), {}, {}},
              {Affine2::translation(0.5, 0) * Affine2::scaling(0.5, 0.5), {}, {}},
              {Affine2::translation(0, 0.5) * Affine2::scaling(0.5, 0.5), {}, {}}};
  const g::IfsDimensionReport report = g::ifsDimension(ifs);
  REQUIRE(report.moranDimension.has_value());
  CHECK(*report.moranDimension == doctest::Approx(std::log(3.0) / std::log(2.0)).epsilon(1e-14));
  CHECK(*report.moranDimension == doctest::Approx(1.58496).epsilon(1e-5));
  // Box counting on chaos-game points agrees with Moran.
  std::vector<glm::dvec2> points;
  for (const g::IfsPoint& p : g::chaosGamePoints(ifs, *g::chaosGameProbabilities(ifs), 1'000'000, 5)) {
    points.push_back(p.position);
  }
  const auto boxes = g::boxCountingDimension(points);
  REQUIRE(boxes.has_value());
  CHECK(boxes->dimension == doctest::Approx(std::log2(3.0)).epsilon(0.03));
}

TEST_CASE("course test 4: -90 degrees about y, then 180 about x, is 180 degrees about (1/sqrt2, 0, -1/sqrt2)") {
  // (a) by matrices, right to left.
  const glm::dmat3 ry = g::rotationMatrixDegrees({0, 1, 0}, -90);
  const glm::dmat3 rx = g::rotationMatrixDegrees({1, 0, 0}, 180);
  auto rowMajor = [](double a, double b, double c, double d, double e, double f, double gg, double h,
                     double i) { return glm::transpose(glm::dmat3(a, b, c, d, e, f, gg, h, i)); };
  CHECK(ry == rowMajor(0, 0, -1, 0, 1, 0, 1, 0, 0));
  CHECK(rx == rowMajor(1, 0, 0, 0, -1, 0, 0, 0, -1));
  const glm::dmat3 m = g::composeRotations(ry, rx);
  CHECK(m == rowMajor(0, 0, -1, 0, -1, 0, -1, 0, 0));
  // cos(alpha) = (m11 + m22 + m33 - 1) / 2 = -1.
  CHECK((m[0][0] + m[1][1] + m[2][2] - 1) / 2 == -1.0);
  const g::AxisAngle byMatrix = g::axisAngleFromMatrix(m);
  const double h = 1 / std::sqrt(2.0);
  CHECK(byMatrix.angle == doctest::Approx(std::numbers::pi));
  CHECK(byMatrix.axis.x == doctest::Approx(h));
  CHECK(byMatrix.axis.y == doctest::Approx(0.0));
  CHECK(byMatrix.axis.z == doctest::Approx(-h));

  // (b) by quaternions: q1 = (1 - j)/sqrt2, q2 = i, q2 q1 = (i - k)/sqrt2.
  const g::Quaternion q1 = g::rotationQuaternionDegrees({0, 1, 0}, -90);
  const g::Quaternion q2 = g::rotationQuaternionDegrees({1, 0, 0}, 180);
  CHECK(q1.w == doctest::Approx(h));
  CHECK(q1.y == doctest::Approx(-h));
  CHECK(q2 == g::Quaternion{0, 1, 0, 0});
  const g::Quaternion q = g::composeRotations(q1, q2);
  CHECK(q.w == 0.0);
  CHECK(q.x == doctest::Approx(h));
  CHECK(q.y == 0.0);
  CHECK(q.z == doctest::Approx(-h));
  const g::AxisAngle byQuaternion = g::axisAngleFromQuaternion(q);
  CHECK(byQuaternion.angle == std::numbers::pi);
  CHECK(glm::length(byQuaternion.axis - byMatrix.axis) < 1e-12);
  // The two approaches give the same matrix.
  const glm::dmat3 fromQ = g::rotationMatrix(q);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) CHECK(fromQ[c][r] == doctest::Approx(m[c][r]));
}
