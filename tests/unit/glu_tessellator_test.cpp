// The GLU tessellator's interface (GLU 1.3, chapter 5): callbacks and what they receive, the
// fan that SGI's GLU outputs for simple polygons, the state machine's errors, properties.
#include <doctest/doctest.h>

#include <GL/glu.h>

#include <vector>

namespace {

// Everything the callbacks saw, as text-like events.
struct Recording {
  std::vector<GLenum> begins;
  std::vector<int> vertices;  // the ints the vertex data points at
  std::vector<GLboolean> flags;
  std::vector<GLenum> errors;
  int ends = 0;
  int combines = 0;
  void* polygonData = nullptr;
};
Recording* recording = nullptr;
std::vector<int> createdIds;  // storage for vertices made by the combine callback

void GLAPIENTRY onBegin(GLenum type) { recording->begins.push_back(type); }
void GLAPIENTRY onVertex(void* data) { recording->vertices.push_back(*static_cast<int*>(data)); }
void GLAPIENTRY onEnd() { ++recording->ends; }
void GLAPIENTRY onError(GLenum error) { recording->errors.push_back(error); }
void GLAPIENTRY onEdgeFlag(GLboolean flag) { recording->flags.push_back(flag); }
void GLAPIENTRY onBeginData(GLenum type, void* polygon) {
  recording->begins.push_back(type);
  recording->polygonData = polygon;
}
void GLAPIENTRY onCombine(GLdouble[3], void*[4], GLfloat[4], void** out) {
  ++recording->combines;
  *out = &createdIds.at(recording->combines - 1);
}

struct Tessellator {
  GLUtesselator* tess = gluNewTess();
  Recording events;
  Tessellator() {
    recording = &events;
    createdIds.assign(16, 100);
    for (int i = 0; i < 16; ++i) createdIds[i] = 100 + i;
    gluTessCallback(tess, GLU_TESS_BEGIN, reinterpret_cast<_GLUfuncptr>(onBegin));
    gluTessCallback(tess, GLU_TESS_VERTEX, reinterpret_cast<_GLUfuncptr>(onVertex));
    gluTessCallback(tess, GLU_TESS_END, reinterpret_cast<_GLUfuncptr>(onEnd));
    gluTessCallback(tess, GLU_TESS_ERROR, reinterpret_cast<_GLUfuncptr>(onError));
  }
  ~Tessellator() {
    gluDeleteTess(tess);
    recording = nullptr;
  }
};

struct Point {
  GLdouble xyz[3];
  int id;
};

void contour(GLUtesselator* tess, std::vector<Point>& points) {
  gluTessBeginContour(tess);
  for (Point& p : points) gluTessVertex(tess, p.xyz, &p.id);
  gluTessEndContour(tess);
}

std::vector<Point> square(double x0, double y0, double size, int firstId, bool clockwise) {
  std::vector<Point> p = {{{x0, y0, 0}, firstId},
                          {{x0 + size, y0, 0}, firstId + 1},
                          {{x0 + size, y0 + size, 0}, firstId + 2},
                          {{x0, y0 + size, 0}, firstId + 3}};
  if (clockwise) std::swap(p[1], p[3]);
  return p;
}

}  // namespace

TEST_CASE("A convex contour comes out as SGI's fan, in the input order") {
  Tessellator t;
  auto quad = square(0, 0, 1, 0, false);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, quad);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins == std::vector<GLenum>{GL_TRIANGLE_FAN});
  CHECK(t.events.vertices == std::vector<int>{0, 1, 2, 3});
  CHECK(t.events.ends == 1);
  CHECK(t.events.errors.empty());

  // Against a given normal the fan is reversed after its first vertex; a triangle stays
  // GL_TRIANGLES.
  t.events = {};
  gluTessNormal(t.tess, 0, 0, -1);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, quad);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.vertices == std::vector<int>{0, 3, 2, 1});
  t.events = {};
  std::vector<Point> triangle(quad.begin(), quad.begin() + 3);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, triangle);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins == std::vector<GLenum>{GL_TRIANGLES});

  // GLU_TESS_WINDING_POSITIVE drops a fan that turns against the normal.
  t.events = {};
  gluTessProperty(t.tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, quad);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins.empty());
}

TEST_CASE("A square with a hole: GL_TRIANGLES from the eight input vertices") {
  Tessellator t;
  auto outer = square(0, 0, 3, 0, false);
  auto hole = square(1, 1, 1, 4, true);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, outer);
  contour(t.tess, hole);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins == std::vector<GLenum>{GL_TRIANGLES});
  CHECK(t.events.vertices.size() == 8 * 3);  // 8 triangles
  for (int v : t.events.vertices) CHECK((v >= 0 && v < 8));
  CHECK(t.events.errors.empty());
}

TEST_CASE("The edge flag callback turns the fan off and flags boundary edges") {
  Tessellator t;
  gluTessCallback(t.tess, GLU_TESS_EDGE_FLAG, reinterpret_cast<_GLUfuncptr>(onEdgeFlag));
  auto quad = square(0, 0, 1, 0, false);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, quad);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins == std::vector<GLenum>{GL_TRIANGLES});
  CHECK(t.events.vertices.size() == 6);
  // Flags are reported when they change: the two triangles have one diagonal each.
  REQUIRE_FALSE(t.events.flags.empty());
  int changes = static_cast<int>(t.events.flags.size());
  CHECK(changes >= 2);
  CHECK(changes <= 5);
}

TEST_CASE("Crossings need the combine callback") {
  Tessellator t;
  std::vector<Point> bowtie = {{{0, 0, 0}, 0}, {{2, 2, 0}, 1}, {{2, 0, 0}, 2}, {{0, 2, 0}, 3},
                               {{-1, 1, 0}, 4}};
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, bowtie);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.errors == std::vector<GLenum>{GLU_TESS_NEED_COMBINE_CALLBACK});
  CHECK(t.events.begins.empty());

  t.events = {};
  gluTessCallback(t.tess, GLU_TESS_COMBINE, reinterpret_cast<_GLUfuncptr>(onCombine));
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, bowtie);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.errors.empty());
  CHECK(t.events.combines == 1);
  bool usesCrossing = false;
  for (int v : t.events.vertices) usesCrossing |= v == 100;
  CHECK(usesCrossing);
}

TEST_CASE("GLU_TESS_BOUNDARY_ONLY gives one line loop per boundary") {
  Tessellator t;
  gluTessProperty(t.tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
  auto outer = square(0, 0, 3, 0, false);
  auto hole = square(1, 1, 1, 4, true);
  gluTessBeginPolygon(t.tess, nullptr);
  contour(t.tess, outer);
  contour(t.tess, hole);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.begins == std::vector<GLenum>{GL_LINE_LOOP, GL_LINE_LOOP});
  CHECK(t.events.vertices.size() == 8);
  CHECK(t.events.ends == 2);
}

TEST_CASE("Calls out of order are reported and made good, as in SGI's GLU") {
  Tessellator t;
  auto quad = square(0, 0, 1, 0, false);
  for (Point& p : quad) gluTessVertex(t.tess, p.xyz, &p.id);  // no begin at all
  gluTessEndPolygon(t.tess);                                   // no end of contour
  CHECK(t.events.errors == std::vector<GLenum>{GLU_TESS_MISSING_BEGIN_POLYGON,
                                               GLU_TESS_MISSING_BEGIN_CONTOUR,
                                               GLU_TESS_MISSING_END_CONTOUR});
  CHECK(t.events.vertices == std::vector<int>{0, 1, 2, 3});

  t.events = {};
  gluTessBeginPolygon(t.tess, nullptr);
  gluTessBeginPolygon(t.tess, nullptr);  // the first polygon is dropped
  CHECK(t.events.errors == std::vector<GLenum>{GLU_TESS_MISSING_END_POLYGON});
  gluTessEndPolygon(t.tess);

  t.events = {};
  GLdouble huge[3] = {1e200, 0, 0};
  int id = 9;
  gluTessBeginPolygon(t.tess, nullptr);
  gluTessBeginContour(t.tess);
  gluTessVertex(t.tess, huge, &id);
  gluTessEndContour(t.tess);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.errors == std::vector<GLenum>{GLU_TESS_COORD_TOO_LARGE});
}

TEST_CASE("GLU 1.0 polygons, _DATA callbacks and properties") {
  Tessellator t;
  gluTessCallback(t.tess, GLU_TESS_BEGIN_DATA, reinterpret_cast<_GLUfuncptr>(onBeginData));
  auto outer = square(0, 0, 3, 0, false);
  auto hole = square(1, 1, 1, 4, true);
  gluBeginPolygon(t.tess);
  for (Point& p : outer) gluTessVertex(t.tess, p.xyz, &p.id);
  gluNextContour(t.tess, GLU_INTERIOR);
  for (Point& p : hole) gluTessVertex(t.tess, p.xyz, &p.id);
  gluEndPolygon(t.tess);
  CHECK(t.events.vertices.size() == 24);
  CHECK(t.events.polygonData == nullptr);

  int polygon = 0;
  t.events = {};
  gluTessBeginPolygon(t.tess, &polygon);
  contour(t.tess, outer);
  gluTessEndPolygon(t.tess);
  CHECK(t.events.polygonData == &polygon);

  GLdouble value = -1;
  gluGetTessProperty(t.tess, GLU_TESS_WINDING_RULE, &value);
  CHECK(value == GLU_TESS_WINDING_ODD);
  gluTessProperty(t.tess, GLU_TESS_WINDING_RULE, 12345);
  CHECK(t.events.errors == std::vector<GLenum>{GLU_INVALID_VALUE});
  gluTessProperty(t.tess, GLU_TESS_TOLERANCE, 0.5);
  gluGetTessProperty(t.tess, GLU_TESS_TOLERANCE, &value);
  CHECK(value == 0.5);
  gluGetTessProperty(t.tess, GLU_TESS_BOUNDARY_ONLY, &value);
  CHECK(value == 0.0);
  t.events.errors.clear();
  gluGetTessProperty(t.tess, 42, &value);
  gluTessCallback(t.tess, 42, nullptr);
  CHECK(t.events.errors == std::vector<GLenum>{GLU_INVALID_ENUM, GLU_INVALID_ENUM});
  CHECK(value == 0.0);
}
