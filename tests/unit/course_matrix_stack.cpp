// Test question 1 of the study guide, through glass's own matrix stack: the calls of Listing 6,
// with the modelview matrix read back where drawTriangle() would draw, must send the triangle
// (0,0), (1,0), (0,2) where the hand computation in course_test_answers.cpp says.
#include <doctest/doctest.h>

#include <glass/context.h>

#include <GL/gl.h>

#include <cmath>
#include <initializer_list>
#include <vector>

namespace {

struct Point {
  double x, y;
};

// The triangle's corners through the current modelview matrix (column-major, as glGet returns it).
std::vector<Point> drawTriangle() {
  GLdouble m[16];
  glGetDoublev(GL_MODELVIEW_MATRIX, m);
  std::vector<Point> corners;
  for (const Point& p : {Point{0, 0}, Point{1, 0}, Point{0, 2}}) {
    corners.push_back({m[0] * p.x + m[4] * p.y + m[12], m[1] * p.x + m[5] * p.y + m[13]});
  }
  return corners;
}

}  // namespace

TEST_CASE("course test 1: Listing 6 on glass's matrix stack draws the triangles of the answer") {
  GlassContext* context = glassCreateContext(16, 16);
  REQUIRE(context != nullptr);
  REQUIRE(glassMakeCurrent(context));

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(2.0f, 0.0f, 0.0f);
  glPushMatrix();
  glTranslatef(0.0f, -2.0f, 0.0f);
  const std::vector<Point> first = drawTriangle();
  glPopMatrix();
  glRotatef(180.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(0.0f, -2.0f, 0.0f);
  const std::vector<Point> second = drawTriangle();
  CHECK(glGetError() == GL_NO_ERROR);

  const double r2 = std::sqrt(2.0);
  const Point expectedFirst[3] = {{2 * r2, 0}, {5 / r2, 1 / r2}, {r2, r2}};
  const Point expectedSecond[3] = {{0, 2 * r2}, {-1 / r2, 3 / r2}, {r2, r2}};
  // glRotatef takes floats: agreement to float precision.
  for (int i = 0; i < 3; ++i) {
    CHECK(first[i].x == doctest::Approx(expectedFirst[i].x).epsilon(1e-6));
    CHECK(first[i].y == doctest::Approx(expectedFirst[i].y).epsilon(1e-6));
    CHECK(second[i].x == doctest::Approx(expectedSecond[i].x).epsilon(1e-6));
    CHECK(second[i].y == doctest::Approx(expectedSecond[i].y).epsilon(1e-6));
  }
  glassDestroyContext(context);
}
