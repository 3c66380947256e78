// The GL evaluators (spec 5.1) against the geometry library: evaluated vertices, normals,
// colours and texture coordinates, glGetMap, the grid, errors, display lists, and the teapot.
#include <GL/gl.h>
#include <GL/glut.h>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "glass/geometry/bezier_constructions.h"
#include "glass/geometry/teapot.h"
#include "pipeline_test_support.h"

namespace geo = glass::geometry;
using glass::gl::EvaluatedVertex;

namespace {

glass::gl::Context& current() { return *glass::gl::currentContext(); }

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

glm::dvec3 projected(const EvaluatedVertex& v) { return glm::dvec3(v.object) / v.object.w; }

// A patch's homogeneous control points as glMap2d wants them, u the outer index.
std::vector<double> homogeneousNet(const geo::BezierSurface& s) {
  std::vector<double> values;
  for (const glm::dvec4& h : s.homogeneousControlPoints()) values.insert(values.end(), {h.x, h.y, h.z, h.w});
  return values;
}

}  // namespace

TEST_CASE("evaluators: GL_MAP2_VERTEX_4 with GL_AUTO_NORMAL gives the library's rational patch") {
  glass::test::ScopedContext context;
  const geo::BezierSurface torus = geo::torusSixteenth(3.0, 1.0);
  const std::vector<double> net = homogeneousNet(torus);
  // A domain of its own: u in [2, 5], v in [-1, 1].
  glMap2d(GL_MAP2_VERTEX_4, 2.0, 5.0, 12, 3, -1.0, 1.0, 4, 3, net.data());
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_AUTO_NORMAL);
  CHECK(glGetError() == GL_NO_ERROR);
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) {
      const double s = a / 10.0, t = b / 10.0;
      EvaluatedVertex vertex;
      REQUIRE(glass::gl::evaluateMaps2(current(), 2.0 + 3.0 * s, -1.0 + 2.0 * t, vertex));
      CHECK(distance(projected(vertex), torus.evaluate(s, t)) < 1e-12);
      REQUIRE(vertex.hasNormal);
      // The spec's normal: the derivatives of the projected point, by the quotient rule, crossed.
      const glm::dvec3 n = glm::normalize(glm::cross(torus.derivative(s, t, 1, 0), torus.derivative(s, t, 0, 1)));
      CHECK(distance(vertex.normal, n) < 1e-9);
      // And it is the torus's outward normal.
      const glm::dvec3 p = torus.evaluate(s, t);
      const glm::dvec3 centre = 3.0 * glm::normalize(glm::dvec3(p.x, 0, p.z));
      CHECK(distance(vertex.normal, glm::normalize(p - centre)) < 1e-9);
    }
  // A reversed u domain reverses du, and with it the normal.
  glMap2d(GL_MAP2_VERTEX_4, 5.0, 2.0, 12, 3, -1.0, 1.0, 4, 3, net.data());
  EvaluatedVertex reversed;
  REQUIRE(glass::gl::evaluateMaps2(current(), 3.5, 0.0, reversed));
  CHECK(distance(projected(reversed), torus.evaluate(0.5, 0.5)) < 1e-12);
  CHECK(distance(reversed.normal, -torus.normal(0.5, 0.5)) < 1e-9);
}

TEST_CASE("evaluators: a teapot patch through GL_MAP2_VERTEX_3, float control points") {
  glass::test::ScopedContext context;
  const geo::BezierSurface patch = geo::teapotPatches()[5];
  std::vector<float> points;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      const glm::dvec3 p = patch.controlPoint(i, j);
      points.insert(points.end(), {float(p.x), float(p.y), float(p.z)});
    }
  glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 12, 4, 0.0f, 1.0f, 3, 4, points.data());
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  for (double u : {0.0, 0.3, 0.7, 1.0})
    for (double v : {0.0, 0.45, 1.0}) {
      EvaluatedVertex vertex;
      REQUIRE(glass::gl::evaluateMaps2(current(), u, v, vertex));
      CHECK(vertex.object.w == 1.0);
      // The data's decimals are rounded to float by glMap2f.
      CHECK(distance(glm::dvec3(vertex.object), patch.evaluate(u, v)) < 1e-6);
      CHECK(distance(vertex.normal, patch.normal(u, v)) < 1e-5);
    }
  // Without GL_AUTO_NORMAL (and no normal map) no normal is produced.
  glDisable(GL_AUTO_NORMAL);
  EvaluatedVertex plain;
  REQUIRE(glass::gl::evaluateMaps2(current(), 0.5, 0.5, plain));
  CHECK_FALSE(plain.hasNormal);
  // Without a vertex map, nothing.
  glDisable(GL_MAP2_VERTEX_3);
  CHECK_FALSE(glass::gl::evaluateMaps2(current(), 0.5, 0.5, plain));
}

TEST_CASE("evaluators: one-dimensional maps, colours, texture coordinates, which map wins") {
  glass::test::ScopedContext context;
  const geo::BezierCurve arc = geo::circularArc(0.0, 2.0 * std::numbers::pi / 3.0);
  std::vector<double> arcPoints;
  for (const glm::dvec4& h : arc.homogeneousControlPoints()) arcPoints.insert(arcPoints.end(), {h.x, h.y, h.z, h.w});
  glMap1d(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 3, arcPoints.data());
  const double cubic[4][3] = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 0}};
  glMap1d(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &cubic[0][0]);
  const float colors[2][4] = {{1, 0, 0, 1}, {0, 0, 1, 0.5f}};
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 2.0f, 4, 2, &colors[0][0]);
  const float s1[2] = {0.25f, 0.75f};
  glMap1f(GL_MAP1_TEXTURE_COORD_1, 0.0f, 1.0f, 1, 2, s1);
  const float s3[2][3] = {{0, 0, 0}, {1, 2, 3}};
  glMap1f(GL_MAP1_TEXTURE_COORD_3, 0.0f, 1.0f, 3, 2, &s3[0][0]);
  CHECK(glGetError() == GL_NO_ERROR);

  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glEnable(GL_MAP1_TEXTURE_COORD_1);
  const geo::BezierCurve cubicCurve(std::vector<glm::dvec3>{{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 0}});
  EvaluatedVertex v;
  REQUIRE(glass::gl::evaluateMaps1(current(), 0.5, v));
  CHECK(distance(glm::dvec3(v.object), cubicCurve.evaluate(0.5)) < 1e-15);
  // The colour map's domain is [0, 2]: u = 0.5 is a quarter of the way.
  CHECK(v.hasColor);
  CHECK(glm::length(v.color - glm::dvec4(0.75, 0, 0.25, 0.875)) < 1e-7);
  // TexCoord1: t = r = 0, q = 1.
  CHECK(v.texCoord == glm::dvec4(0.5, 0.0, 0.0, 1.0));
  // With TEXTURE_COORD_3 enabled too, the map with more coordinates is the one evaluated.
  glEnable(GL_MAP1_TEXTURE_COORD_3);
  REQUIRE(glass::gl::evaluateMaps1(current(), 0.5, v));
  CHECK(v.texCoord == glm::dvec4(0.5, 1.0, 1.5, 1.0));
  // VERTEX_4 overrides VERTEX_3: the exam's arc, on the unit circle.
  glEnable(GL_MAP1_VERTEX_4);
  for (int k = 0; k <= 20; ++k) {
    REQUIRE(glass::gl::evaluateMaps1(current(), k / 20.0, v));
    CHECK(std::abs(glm::length(projected(v)) - 1.0) < 1e-12);
    CHECK(distance(projected(v), arc.evaluate(k / 20.0)) < 1e-15);
  }
}

TEST_CASE("evaluators: glEvalCoord does not change the current attributes") {
  glass::test::ScopedContext context;
  const float points[2][3] = {{0, 0, 0}, {1, 1, 0}};
  const float colors[2][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}};
  const float normals[2][3] = {{1, 0, 0}, {0, 1, 0}};
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &points[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &colors[0][0]);
  glMap1f(GL_MAP1_NORMAL, 0.0f, 1.0f, 3, 2, &normals[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glEnable(GL_MAP1_NORMAL);
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glNormal3f(0.0f, 0.0f, -1.0f);
  glTexCoord2f(0.5f, 0.25f);
  glBegin(GL_POINTS);
  glEvalCoord1f(0.3f);
  glEvalPoint1(1);
  glEnd();
  glEvalCoord1f(0.7f);  // outside glBegin/glEnd: no vertex, and no change either
  float color[4], normal[3], tex[4];
  glGetFloatv(GL_CURRENT_COLOR, color);
  glGetFloatv(GL_CURRENT_NORMAL, normal);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tex);
  CHECK(color[0] == 0.1f);
  CHECK(color[3] == 0.4f);
  CHECK(normal[2] == -1.0f);
  CHECK(tex[1] == 0.25f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("evaluators: glGetMap, the initial maps, the grid and the enables") {
  glass::test::ScopedContext context;
  GLint maxOrder = 0;
  glGetIntegerv(GL_MAX_EVAL_ORDER, &maxOrder);
  CHECK(maxOrder >= 8);
  // Initial state (table 6.24): order 1, domain [0, 1], the attribute's initial value.
  GLint order[2] = {0, 0};
  glGetMapiv(GL_MAP2_COLOR_4, GL_ORDER, order);
  CHECK(order[0] == 1);
  CHECK(order[1] == 1);
  float coefficients[4] = {};
  glGetMapfv(GL_MAP1_COLOR_4, GL_COEFF, coefficients);
  CHECK(coefficients[0] == 1.0f);
  CHECK(coefficients[3] == 1.0f);
  glGetMapfv(GL_MAP1_NORMAL, GL_COEFF, coefficients);
  CHECK(coefficients[2] == 1.0f);
  glGetMapfv(GL_MAP2_TEXTURE_COORD_4, GL_COEFF, coefficients);
  CHECK(coefficients[3] == 1.0f);

  const double points[2][3][2] = {{{0, 0}, {1, 0.5}, {2, 0}}, {{0, 1}, {1, 1.5}, {2.6, 1}}};
  glMap2d(GL_MAP2_TEXTURE_COORD_2, -1.0, 1.0, 6, 2, 0.5, 2.5, 2, 3, &points[0][0][0]);
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, order);
  CHECK(order[0] == 2);
  CHECK(order[1] == 3);
  double domain[4] = {};
  glGetMapdv(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN, domain);
  CHECK(domain[0] == -1.0);
  CHECK(domain[1] == 1.0);
  CHECK(domain[2] == 0.5);
  CHECK(domain[3] == 2.5);
  double coeff[12] = {};
  glGetMapdv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, coeff);
  for (int k = 0; k < 12; ++k) CHECK(coeff[k] == (&points[0][0][0])[k]);
  GLint rounded[12] = {};
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, rounded);
  CHECK(rounded[11] == 1);
  CHECK(rounded[10] == 3);  // 2.6 to the nearest integer

  glMapGrid2f(7, 0.25f, 0.75f, 3, 1.0f, 0.0f);
  GLint segments[2] = {};
  float gridDomain[4] = {};
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, gridDomain);
  CHECK(segments[0] == 7);
  CHECK(segments[1] == 3);
  CHECK(gridDomain[1] == 0.75f);
  CHECK(gridDomain[2] == 1.0f);

  CHECK(glIsEnabled(GL_AUTO_NORMAL) == GL_FALSE);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_MAP1_INDEX);
  CHECK(glIsEnabled(GL_AUTO_NORMAL) == GL_TRUE);
  CHECK(glIsEnabled(GL_MAP1_INDEX) == GL_TRUE);
  CHECK(glIsEnabled(GL_MAP2_INDEX) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("evaluators: the errors the specification lists") {
  glass::test::ScopedContext context;
  const float points[4][4] = {};
  glMap1f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 2, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 3, 2, &points[0][0]);  // stride below k = 4
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 0, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_VALUE);
  GLint maxOrder = 0;
  glGetIntegerv(GL_MAX_EVAL_ORDER, &maxOrder);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, maxOrder + 1, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 3, 2, 0.0f, 0.0f, 6, 2, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 2, 2, 0.0f, 1.0f, 6, 2, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMap2f(GL_MAP1_NORMAL, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &points[0][0]);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glMapGrid1f(0, 0.0f, 1.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMapGrid2d(4, 0.0, 1.0, -1, 0.0, 1.0);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glEvalMesh1(GL_FILL, 0, 4);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glEvalMesh2(GL_TRIANGLES, 0, 4, 0, 4);
  CHECK(glGetError() == GL_INVALID_ENUM);
  float value[4];
  glGetMapfv(GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_3, value);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetMapfv(GL_TEXTURE_2D, GL_ORDER, value);
  CHECK(glGetError() == GL_INVALID_ENUM);
  // The rejected calls changed nothing.
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  CHECK(order == 1);

  // Inside glBegin/glEnd only glEvalCoord and glEvalPoint are allowed.
  glBegin(GL_POINTS);
  glEvalCoord1f(0.5f);
  glEvalPoint2(1, 1);
  CHECK(current().errors.error == GL_NO_ERROR);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &points[0][0]);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glEvalMesh2(GL_FILL, 0, 1, 0, 1);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glMapGrid1f(2, 0.0f, 1.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("evaluators: glMap copies its points into a display list when compiled") {
  glass::test::ScopedContext context;
  float points[2][3] = {{0, 0, 0}, {4, 2, 0}};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &points[0][0]);
  glMapGrid1f(5, 0.0f, 1.0f);
  glEndList();
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  CHECK(order == 1);  // compiled, not executed
  points[1][0] = 100.0f;
  glCallList(list);
  float coeff[6] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, coeff);
  CHECK(coeff[3] == 4.0f);  // the value at compile time
  GLint segments = 0;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &segments);
  CHECK(segments == 5);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("evaluators: glEvalMesh2 draws the patch; the teapot draws and leaves the state alone") {
  glass::test::ScopedContext context(32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // A flat bilinear square over the middle of the viewport.
  const float square[2][2][3] = {{{-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}}, {{0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}}};
  glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 6, 2, 0.0f, 1.0f, 3, 2, &square[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid2f(4, 0.0f, 1.0f, 4, 0.0f, 1.0f);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glEvalMesh2(GL_FILL, 0, 4, 0, 4);
  CHECK(glass::test::pixelAt(16, 16) == glass::test::Rgba{255, 255, 255, 255});
  CHECK(glass::test::pixelAt(9, 9) == glass::test::Rgba{255, 255, 255, 255});
  CHECK(glass::test::pixelAt(3, 16) == glass::test::Rgba{0, 0, 0, 255});
  // Half the grid in u: only the left half of the square.
  glClear(GL_COLOR_BUFFER_BIT);
  glEvalMesh2(GL_FILL, 0, 2, 0, 4);
  CHECK(glass::test::pixelAt(12, 16) == glass::test::Rgba{255, 255, 255, 255});
  CHECK(glass::test::pixelAt(20, 16) == glass::test::Rgba{0, 0, 0, 255});

  glClear(GL_COLOR_BUFFER_BIT);
  glutSolidTeapot(1.0);
  CHECK(glass::test::pixelAt(16, 16) == glass::test::Rgba{255, 255, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
  // The program's map, grid and enables are as before.
  GLint order[2] = {};
  glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
  CHECK(order[0] == 2);
  GLint segments[2] = {};
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments);
  CHECK(segments[0] == 4);
  CHECK(glIsEnabled(GL_AUTO_NORMAL) == GL_FALSE);
  CHECK(glIsEnabled(GL_MAP2_TEXTURE_COORD_2) == GL_FALSE);
}
