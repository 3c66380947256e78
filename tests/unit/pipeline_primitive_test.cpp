// Primitive assembly and the primitive stages: the provoking vertex of flat shading for each of
// the ten primitive types (spec 2.13.7, table 2.6), facing and culling, polygon modes and edge
// flags, clipping by user planes.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// A distinct colour for vertex i.
Rgba vertexColor(int i) {
  return Rgba{static_cast<uint8_t>(20 + 30 * i), static_cast<uint8_t>(200 - 20 * i),
              static_cast<uint8_t>(i * 17 % 256), 255};
}

struct Point {
  float x, y;
};

void drawFlat(GLenum mode, const std::vector<Point>& vertices) {
  glBegin(mode);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Rgba c = vertexColor(static_cast<int>(i));
    glColor4ub(c.r, c.g, c.b, c.a);
    glVertex2f(vertices[i].x, vertices[i].y);
  }
  glEnd();
}

struct Probe {
  int x, y;
  int vertex;  // the vertex whose colour the pixel must have
};

void checkProvoking(GLenum mode, const std::vector<Point>& vertices, const std::vector<Probe>& probes) {
  glClear(GL_COLOR_BUFFER_BIT);
  drawFlat(mode, vertices);
  for (const Probe& p : probes) {
    CAPTURE(mode);
    CAPTURE(p.x);
    CAPTURE(p.y);
    CHECK(pixelAt(p.x, p.y) == vertexColor(p.vertex));
  }
}

}  // namespace

TEST_CASE("pipeline primitives: flat shading takes the provoking vertex of table 2.6") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glShadeModel(GL_FLAT);

  checkProvoking(GL_POINTS, {{10.5f, 10.5f}, {20.5f, 20.5f}}, {{10, 10, 0}, {20, 20, 1}});
  checkProvoking(GL_LINES, {{2.5f, 10.5f}, {60.5f, 10.5f}, {2.5f, 20.5f}, {60.5f, 20.5f}},
                 {{30, 10, 1}, {30, 20, 3}});
  checkProvoking(GL_LINE_STRIP, {{2.5f, 10.5f}, {60.5f, 10.5f}, {60.5f, 50.5f}},
                 {{30, 10, 1}, {60, 30, 2}});
  // The closing segment of a loop takes the first vertex's colour.
  checkProvoking(GL_LINE_LOOP, {{10.5f, 10.5f}, {50.5f, 10.5f}, {50.5f, 50.5f}},
                 {{30, 10, 1}, {50, 30, 2}, {30, 30, 0}});
  checkProvoking(GL_TRIANGLES, {{2, 2}, {30, 2}, {2, 30}, {60, 34}, {60, 62}, {32, 62}},
                 {{8, 8, 2}, {54, 56, 5}});
  checkProvoking(GL_TRIANGLE_STRIP, {{4, 4}, {4, 60}, {60, 4}, {60, 60}},
                 {{14, 14, 2}, {50, 50, 3}});
  checkProvoking(GL_TRIANGLE_FAN, {{32, 32}, {62, 32}, {32, 62}, {2, 32}},
                 {{40, 40, 2}, {24, 40, 3}});
  checkProvoking(GL_QUADS, {{4, 4}, {60, 4}, {60, 60}, {4, 60}}, {{14, 50, 3}, {50, 14, 3}});
  checkProvoking(GL_QUAD_STRIP, {{4, 4}, {4, 60}, {30, 4}, {30, 60}, {60, 4}, {60, 60}},
                 {{15, 30, 3}, {45, 30, 5}});
  // A polygon takes its first vertex's colour.
  checkProvoking(GL_POLYGON, {{4, 4}, {60, 4}, {62, 40}, {32, 62}, {2, 40}},
                 {{32, 32, 0}, {10, 10, 0}, {55, 20, 0}});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline primitives: smooth shading interpolates and flat shading does not") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glBegin(GL_LINES);
  glColor3f(0, 0, 0);
  glVertex2f(0.5f, 5.5f);
  glColor3f(1, 1, 1);
  glVertex2f(64.5f, 5.5f);
  glEnd();
  const Rgba middle = pixelAt(32, 5);
  CHECK(middle.r > 120);
  CHECK(middle.r < 136);
}

TEST_CASE("pipeline primitives: facing follows glFrontFace and culling removes the named faces") {
  ScopedContext context(64, 32);
  glass::test::pixelProjection(64, 32);
  const auto draw = [] {
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 2), glVertex2f(30, 2), glVertex2f(2, 30);     // counter-clockwise, left
    glVertex2f(34, 2), glVertex2f(34, 30), glVertex2f(62, 2);   // clockwise, right
    glEnd();
  };
  const auto drawn = [](int x) { return pixelAt(x, 8).r == 255; };

  draw();
  CHECK((drawn(8) && drawn(40)));  // no culling

  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  draw();
  CHECK((drawn(8) && !drawn(40)));
  glCullFace(GL_FRONT);
  draw();
  CHECK((!drawn(8) && drawn(40)));
  glCullFace(GL_FRONT_AND_BACK);
  draw();
  CHECK((!drawn(8) && !drawn(40)));

  glFrontFace(GL_CW);
  glCullFace(GL_BACK);
  draw();
  CHECK((!drawn(8) && drawn(40)));

  // Points and lines are never culled.
  glCullFace(GL_FRONT_AND_BACK);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_LINES);
  glVertex2f(0.5f, 20.5f);
  glVertex2f(63.5f, 20.5f);
  glEnd();
  CHECK(pixelAt(30, 20).r == 255);
}

TEST_CASE("pipeline primitives: polygon modes draw boundary edges or vertices, per face") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glColor3f(1, 1, 1);
  const auto square = [] {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);  // counter-clockwise: front facing
    glVertex2f(10.5f, 10.5f), glVertex2f(50.5f, 10.5f), glVertex2f(50.5f, 50.5f), glVertex2f(10.5f, 50.5f);
    glEnd();
  };
  const auto lit = [](int x, int y) { return pixelAt(x, y).r == 255; };

  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  square();
  CHECK(lit(30, 10));    // bottom edge
  CHECK(lit(10, 30));    // left edge
  CHECK(!lit(30, 30));   // inside
  CHECK(!lit(30, 30));
  CHECK(!lit(25, 25));   // the quad's inner diagonal is not a boundary edge
  CHECK(!lit(35, 35));

  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  square();
  CHECK(lit(10, 10));
  CHECK(lit(50, 50));
  CHECK(!lit(30, 10));

  // Only the back face is drawn as lines: a front-facing square stays filled.
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  square();
  CHECK(lit(30, 30));
  glFrontFace(GL_CW);  // now the same square is back facing
  square();
  CHECK(!lit(30, 30));
  CHECK(lit(30, 10));
  glFrontFace(GL_CCW);

  // Edge flags: the edge that starts at a vertex flagged GL_FALSE is not drawn.
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POLYGON);
  glEdgeFlag(GL_FALSE);
  glVertex2f(10.5f, 10.5f);  // bottom edge: not drawn
  glEdgeFlag(GL_TRUE);
  glVertex2f(50.5f, 10.5f);
  glVertex2f(50.5f, 50.5f);
  glVertex2f(10.5f, 50.5f);
  glEnd();
  CHECK(!lit(30, 10));
  CHECK(lit(50, 30));
  CHECK(lit(10, 30));

  // Edge flags do not apply to strips: every edge of every triangle is drawn.
  glClear(GL_COLOR_BUFFER_BIT);
  glEdgeFlag(GL_FALSE);
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2f(10.5f, 10.5f), glVertex2f(10.5f, 50.5f), glVertex2f(50.5f, 10.5f);
  glEnd();
  glEdgeFlag(GL_TRUE);
  CHECK(lit(30, 10));
  CHECK(lit(10, 30));
  CHECK(lit(30, 30));  // the hypotenuse
}

TEST_CASE("pipeline primitives: user clip planes keep the side where p . eye >= 0") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glColor3f(1, 1, 1);
  glPushMatrix();
  glTranslatef(32, 0, 0);
  const GLdouble keepLeft[4] = {-1, 0, 0, 0};  // x <= 0 in object space: window x <= 32
  glClipPlane(GL_CLIP_PLANE3, keepLeft);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE3);
  glRectf(0, 0, 64, 64);
  CHECK(pixelAt(20, 20).r == 255);
  CHECK(pixelAt(40, 20).r == 0);
  glDisable(GL_CLIP_PLANE3);
  glRectf(0, 0, 64, 64);
  CHECK(pixelAt(40, 20).r == 255);
}

TEST_CASE("pipeline primitives: glRect draws a polygon and the viewport maps to the window") {
  ScopedContext context(64, 64);
  glViewport(32, 0, 32, 32);
  glColor3f(0, 1, 0);
  glRecti(-1, -1, 1, 1);  // the whole viewport
  CHECK(pixelAt(40, 10).g == 255);
  CHECK(pixelAt(10, 10).g == 0);
  CHECK(pixelAt(40, 40).g == 0);
}

TEST_CASE("pipeline primitives: quads split along v0-v2, or along v1-v3 when clipped, as Mesa") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  // Red, green, blue, black corners. Near the v1 corner, the (v0, v1, v2) triangle of the v0-v2
  // split has blue in it; the (v0, v1, v3) triangle of the v1-v3 split has none.
  const auto quad = [](float left) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0), glVertex2f(left, 4);
    glColor3f(0, 1, 0), glVertex2f(60, 4);
    glColor3f(0, 0, 1), glVertex2f(60, 60);
    glColor3f(0, 0, 0), glVertex2f(left, 60);
    glEnd();
  };
  quad(4.0f);  // inside the window
  CHECK(pixelAt(50, 8).b > 0);
  quad(-20.0f);  // crosses the left clip plane
  CHECK(pixelAt(50, 8).b == 0);
  CHECK(pixelAt(50, 8).g > 0);
}

TEST_CASE("pipeline primitives: in GL_LINE mode the cut along a user clip plane is drawn, as Mesa") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(1, 1, 1);
  const GLdouble keepBelow[4] = {0, -1, 0, 32.5};  // y <= 32.5 in window coordinates
  glClipPlane(GL_CLIP_PLANE0, keepBelow);
  glEnable(GL_CLIP_PLANE0);
  glBegin(GL_TRIANGLES);
  glVertex2f(4.5f, 4.5f), glVertex2f(60.5f, 4.5f), glVertex2f(32.5f, 60.5f);
  glEnd();
  CHECK(pixelAt(32, 32).r == 255);  // on the cut
  CHECK(pixelAt(32, 20).r == 0);    // inside the triangle
  // Along the frustum planes nothing is drawn: the same triangle cut by the window's edge.
  glDisable(GL_CLIP_PLANE0);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(4.5f, 4.5f), glVertex2f(60.5f, 4.5f), glVertex2f(32.5f, 90.5f);
  glEnd();
  CHECK(pixelAt(32, 63).r == 0);
}
