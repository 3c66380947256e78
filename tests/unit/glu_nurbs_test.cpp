// GLU NURBS: Bezier decomposition by knot insertion, the interface's errors and properties, the
// tessellation reported in GLU_NURBS_TESSELLATOR mode (sampling, trimming) and drawing.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glu.h>

#include <vector>

#include "glass/geometry/nurbs.h"
#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// de Boor's algorithm for a scalar B-spline: the reference the Bezier pieces must agree with.
double deBoor(int order, const std::vector<float>& t, const std::vector<double>& p, double u) {
  const int n = static_cast<int>(t.size()) - order;
  int s = order - 1;
  for (int i = order - 1; i < n; ++i) {
    if (t[i] <= u && u < t[i + 1]) s = i;
  }
  if (u >= t[n]) s = n - 1;
  const int degree = order - 1;
  std::vector<double> d(order);
  for (int j = 0; j <= degree; ++j) d[j] = p[s - degree + j];
  for (int r = 1; r <= degree; ++r) {
    for (int j = degree; j >= r; --j) {
      const double a = (u - t[s - degree + j]) / (t[s + 1 + j - r] - t[s - degree + j]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  }
  return d[degree];
}

double bezier(std::vector<double> b, double x) {
  for (size_t r = 1; r < b.size(); ++r) {
    for (size_t j = 0; j + r < b.size(); ++j) b[j] = (1 - x) * b[j] + x * b[j + 1];
  }
  return b[0];
}

struct Tessellation {
  std::vector<GLenum> begins;
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::array<float, 3>> normals;
  std::vector<GLenum> errors;
  int ends = 0;
};
Tessellation* out = nullptr;

void GLAPIENTRY onBegin(GLenum type) { out->begins.push_back(type); }
void GLAPIENTRY onVertex(GLfloat* v) { out->vertices.push_back({v[0], v[1], v[2]}); }
void GLAPIENTRY onNormal(GLfloat* n) { out->normals.push_back({n[0], n[1], n[2]}); }
void GLAPIENTRY onEnd() { ++out->ends; }
void GLAPIENTRY onError(GLenum e) { out->errors.push_back(e); }

struct Nurbs {
  GLUnurbs* nurb = gluNewNurbsRenderer();
  Tessellation result;
  explicit Nurbs(bool tessellator) {
    out = &result;
    gluNurbsCallback(nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(onError));
    if (!tessellator) return;
    gluNurbsProperty(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsCallback(nurb, GLU_NURBS_BEGIN, reinterpret_cast<_GLUfuncptr>(onBegin));
    gluNurbsCallback(nurb, GLU_NURBS_VERTEX, reinterpret_cast<_GLUfuncptr>(onVertex));
    gluNurbsCallback(nurb, GLU_NURBS_NORMAL, reinterpret_cast<_GLUfuncptr>(onNormal));
    gluNurbsCallback(nurb, GLU_NURBS_END, reinterpret_cast<_GLUfuncptr>(onEnd));
  }
  ~Nurbs() {
    gluDeleteNurbsRenderer(nurb);
    out = nullptr;
  }
};

// The unit square of the plane z = 0 as a bilinear surface: (u, v) -> (u, v, 0).
GLfloat kSquareKnots[4] = {0, 0, 1, 1};
GLfloat kSquare[2][2][3] = {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}};

void squareSurface(GLUnurbs* nurb) {
  gluNurbsSurface(nurb, 4, kSquareKnots, 4, kSquareKnots, 2 * 3, 3, &kSquare[0][0][0], 2, 2,
                  GL_MAP2_VERTEX_3);
}

double triangleArea(const Tessellation& t) {
  double area = 0.0;
  for (size_t k = 0; k + 2 < t.vertices.size(); k += 3) {
    const auto &a = t.vertices[k], &b = t.vertices[k + 1], &c = t.vertices[k + 2];
    area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  return area;
}

}  // namespace

TEST_CASE("NURBS curves and surfaces split into Bezier pieces that agree with de Boor") {
  const std::vector<float> knots = {0, 0, 0, 0, 0.3f, 0.5f, 0.5f, 1, 1, 1, 1};
  const std::vector<double> points = {1, 2, -1, 3, 0, 2, 5};
  const auto pieces = glass::geometry::bezierPiecesOfCurve(4, knots, 1, points);
  REQUIRE(pieces.size() == 3);
  for (const auto& piece : pieces) {
    for (int k = 0; k <= 8; ++k) {
      const double u = piece.u0 + (piece.u1 - piece.u0) * k / 8;
      CHECK(bezier(piece.points, k / 8.0) == doctest::Approx(deBoor(4, knots, points, u)));
    }
  }
  // Uniform (unclamped) knots: the valid range is [knots[3], knots[6]].
  const std::vector<float> uniform = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::vector<double> six = {0, 3, 1, 4, 1, 5};
  const auto spans = glass::geometry::bezierPiecesOfCurve(4, uniform, 1, six);
  REQUIRE(spans.size() == 3);
  CHECK(spans.front().u0 == 3.0);
  CHECK(spans.back().u1 == 6.0);
  CHECK(bezier(spans[1].points, 0.5) == doctest::Approx(deBoor(4, uniform, six, 4.5)));
  // A surface whose net is the product of two curves' points is the product of the curves.
  const std::vector<float> u = {0, 0, 0, 1, 2, 2, 2}, v = {0, 1, 2, 3, 4, 5, 6};
  const std::vector<double> a = {1, 2, 0, 3}, b = {2, -1, 1, 0.5};
  std::vector<double> net;
  for (double x : a) {
    for (double y : b) net.push_back(x * y);
  }
  const auto patches = glass::geometry::bezierPiecesOfSurface(3, u, 3, v, 1, net);
  REQUIRE(patches.size() == 4);
  const auto& p = patches[3];
  std::vector<double> row(3);
  for (int i = 0; i < 3; ++i) {
    row[i] = bezier({p.points[i * 3], p.points[i * 3 + 1], p.points[i * 3 + 2]}, 0.25);
  }
  const double expected = deBoor(3, u, a, p.u0 + 0.5 * (p.u1 - p.u0)) *
                          deBoor(3, v, b, p.v0 + 0.25 * (p.v1 - p.v0));
  CHECK(bezier(row, 0.5) == doctest::Approx(expected));
}

TEST_CASE("Bad knot vectors and calls out of order go to the error callback") {
  Nurbs n(true);
  GLfloat points[4][3] = {};
  GLfloat decreasing[8] = {0, 0, 0, 0, 1, 0.5f, 1, 1};
  GLfloat tooFew[6] = {0, 0, 0, 1, 1, 1};
  gluBeginCurve(n.nurb);
  gluNurbsCurve(n.nurb, 8, decreasing, 3, &points[0][0], 4, GL_MAP1_VERTEX_3);
  gluNurbsCurve(n.nurb, 6, tooFew, 3, &points[0][0], 4, GL_MAP1_VERTEX_3);
  gluNurbsCurve(n.nurb, 6, tooFew, 3, &points[0][0], 1, GL_MAP1_VERTEX_3);
  gluEndCurve(n.nurb);
  CHECK(n.result.errors ==
        std::vector<GLenum>{GLU_NURBS_ERROR4, GLU_NURBS_ERROR2, GLU_NURBS_ERROR1});
  CHECK(n.result.begins.empty());

  n.result.errors.clear();
  gluEndSurface(n.nurb);
  gluEndTrim(n.nurb);
  gluBeginTrim(n.nurb);
  gluPwlCurve(n.nurb, 0, nullptr, 2, GLU_MAP1_TRIM_2);
  CHECK(n.result.errors == std::vector<GLenum>{GLU_NURBS_ERROR13, GLU_NURBS_ERROR17,
                                               GLU_NURBS_ERROR15, GLU_NURBS_ERROR19});
  n.result.errors.clear();
  gluBeginSurface(n.nurb);
  gluEndSurface(n.nurb);  // no geometry
  CHECK(n.result.errors == std::vector<GLenum>{GLU_NURBS_ERROR8});
}

TEST_CASE("NURBS properties: defaults, changes and bad values") {
  Nurbs n(false);
  GLfloat value = 0;
  gluGetNurbsProperty(n.nurb, GLU_SAMPLING_TOLERANCE, &value);
  CHECK(value == 50.0f);
  gluGetNurbsProperty(n.nurb, GLU_DISPLAY_MODE, &value);
  CHECK(value == static_cast<GLfloat>(GLU_FILL));
  gluGetNurbsProperty(n.nurb, GLU_AUTO_LOAD_MATRIX, &value);
  CHECK(value == 1.0f);
  gluGetNurbsProperty(n.nurb, GLU_NURBS_MODE, &value);
  CHECK(value == static_cast<GLfloat>(GLU_NURBS_RENDERER));
  gluNurbsProperty(n.nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluGetNurbsProperty(n.nurb, GLU_SAMPLING_METHOD, &value);
  CHECK(value == static_cast<GLfloat>(GLU_DOMAIN_DISTANCE));
  gluNurbsProperty(n.nurb, GLU_SAMPLING_TOLERANCE, -1.0f);
  gluNurbsProperty(n.nurb, GLU_DISPLAY_MODE, 3.0f);
  gluNurbsProperty(n.nurb, 12345, 1.0f);
  CHECK(n.result.errors ==
        std::vector<GLenum>{GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_ENUM});
}

TEST_CASE("Tessellator mode: a surface sampled by domain distance, with normals") {
  ScopedContext context;
  Nurbs n(true);
  gluNurbsProperty(n.nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(n.nurb, GLU_U_STEP, 4);
  gluNurbsProperty(n.nurb, GLU_V_STEP, 2);
  gluBeginSurface(n.nurb);
  squareSurface(n.nurb);
  gluEndSurface(n.nurb);
  CHECK(n.result.errors.empty());
  // One quad strip per row of the 4 x 2 grid, as glEvalMesh2(GL_FILL) draws it.
  CHECK(n.result.begins == std::vector<GLenum>{GL_QUAD_STRIP, GL_QUAD_STRIP});
  CHECK(n.result.ends == 2);
  REQUIRE(n.result.vertices.size() == 2 * (4 + 1) * 2);
  CHECK(n.result.normals.size() == n.result.vertices.size());
  // Row j alternates between v = j / 2 and v = (j + 1) / 2, u running from 0 to 1.
  for (size_t k = 0; k < n.result.vertices.size(); ++k) {
    const size_t row = k / 10, column = (k % 10) / 2, upper = k % 2;
    CHECK(n.result.vertices[k][0] == doctest::Approx(column / 4.0));
    CHECK(n.result.vertices[k][1] == doctest::Approx((row + upper) / 2.0));
    CHECK(n.result.vertices[k][2] == 0.0f);
  }
  for (const auto& normal : n.result.normals) {
    CHECK(normal[2] == doctest::Approx(1.0f));
  }
}

TEST_CASE("Tessellator mode: trimming keeps the region left of the loops") {
  ScopedContext context;
  Nurbs n(true);
  gluNurbsProperty(n.nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(n.nurb, GLU_U_STEP, 7);
  gluNurbsProperty(n.nurb, GLU_V_STEP, 5);
  GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  GLfloat hole[5][2] = {{0.3f, 0.3f}, {0.3f, 0.6f}, {0.7f, 0.6f}, {0.7f, 0.3f}, {0.3f, 0.3f}};
  gluBeginSurface(n.nurb);
  squareSurface(n.nurb);
  gluBeginTrim(n.nurb);
  gluPwlCurve(n.nurb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(n.nurb);
  gluBeginTrim(n.nurb);
  gluPwlCurve(n.nurb, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(n.nurb);
  gluEndSurface(n.nurb);
  CHECK(n.result.errors.empty());
  CHECK(triangleArea(n.result) == doctest::Approx(1.0 - 0.4 * 0.3));

  // A clockwise loop alone is a hole in the whole domain; a NURBS trimming curve (a quadratic
  // triangle-like loop) also trims.
  n.result = {};
  gluBeginSurface(n.nurb);
  squareSurface(n.nurb);
  gluBeginTrim(n.nurb);
  gluPwlCurve(n.nurb, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(n.nurb);
  gluEndSurface(n.nurb);
  CHECK(triangleArea(n.result) == doctest::Approx(1.0 - 0.4 * 0.3));
}

TEST_CASE("Tessellator mode: a curve is one line strip along its pieces") {
  ScopedContext context;
  Nurbs n(true);
  gluNurbsProperty(n.nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(n.nurb, GLU_U_STEP, 10);
  GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  GLfloat points[4][3] = {{0, 0, 0}, {1, 2, 0}, {2, -2, 0}, {3, 0, 0}};
  gluBeginCurve(n.nurb);
  gluNurbsCurve(n.nurb, 8, knots, 3, &points[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(n.nurb);
  CHECK(n.result.begins == std::vector<GLenum>{GL_LINE_STRIP});
  REQUIRE(n.result.vertices.size() == 11);
  CHECK(n.result.vertices.front()[0] == 0.0f);
  CHECK(n.result.vertices.back()[0] == doctest::Approx(3.0f));
  // The cubic's midpoint: (P0 + 3 P1 + 3 P2 + P3) / 8.
  CHECK(n.result.vertices[5][0] == doctest::Approx(1.5f));
  CHECK(n.result.vertices[5][1] == doctest::Approx(0.0f));
}

TEST_CASE("Renderer mode draws through the evaluators and leaves their state as it was") {
  ScopedContext context(16, 16);
  Nurbs n(false);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);
  glColor3f(0, 1, 0);
  gluBeginSurface(n.nurb);
  squareSurface(n.nurb);
  gluEndSurface(n.nurb);
  CHECK(pixelAt(8, 8) == Rgba{0, 255, 0, 255});
  CHECK(glIsEnabled(GL_MAP2_VERTEX_3) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(n.result.errors.empty());

  // Compiled into a display list, the surface is drawn when the list is called.
  glClear(GL_COLOR_BUFFER_BIT);
  glNewList(1, GL_COMPILE);
  glColor3f(0, 0, 1);
  gluBeginSurface(n.nurb);
  squareSurface(n.nurb);
  gluEndSurface(n.nurb);
  glEndList();
  CHECK(pixelAt(8, 8) == Rgba{0, 0, 0, 0});
  glCallList(1);
  CHECK(pixelAt(8, 8) == Rgba{0, 0, 255, 255});
}
