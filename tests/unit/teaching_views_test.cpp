// GLASS_VIEW on small programs, against pictures computed here from the geometry drawn.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "glass/geometry/teaching_scales.h"
#include "pipeline_test_support.h"

namespace {

// GLASS_VIEW for the contexts created while the object lives.
struct ScopedView : glass::test::ScopedEnvironment {
  explicit ScopedView(const char* name) : ScopedEnvironment("GLASS_VIEW", name) {}
};

const unsigned char* pixel(const unsigned char* rgba, int width, int x, int y) {
  return rgba + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
}

void drawQuadNdc(float x0, float y0, float x1, float y1, float z0, float z1) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z0);
  glVertex3f(x1, y0, z1);
  glVertex3f(x1, y1, z1);
  glVertex3f(x0, y1, z0);
  glEnd();
}

double distanceToSegment(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double t = std::clamp(((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

}  // namespace

TEST_CASE("GLASS_VIEW=depth shows a tilted plane's depth as grey from black (near) to white (far)") {
  ScopedView view("depth");
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Identity matrices: NDC z = x / 2, so window z = (x / 2 + 1) / 2 grows from left to right over
  // the covered rows 0-47; rows 48-63 keep the cleared depth 1 (white).
  drawQuadNdc(-1.0f, -1.0f, 1.0f, 0.5f, -0.5f, 0.5f);
  const unsigned char* shown = glassGetColorBuffer(context.get());
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      // Window z at the pixel centre is 0.25 + 0.5 (x + 0.5) / 64; the picture spreads the drawn
      // range [z(0), z(63)] over black to white, so the grey of column x is x / 63.
      const int expected = y < 48 ? static_cast<int>(std::lround(x / 63.0 * 255.0)) : 255;
      const unsigned char* p = pixel(shown, 64, x, y);
      CHECK(std::abs(p[0] - expected) <= 1);
      CHECK(p[0] == p[1]);
      CHECK(p[1] == p[2]);
    }
  }
}

TEST_CASE("GLASS_VIEW=overdraw counts N overlapping quads as N, early depth test or not") {
  ScopedView view("overdraw");
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Quad j covers columns 8j to 63 and is nearer than quad j + 1 is: drawn front to back, the
  // later quads fail the depth test, but every fragment rasterized counts.
  for (int j = 0; j < 5; ++j) {
    const float left = -1.0f + 8.0f * static_cast<float>(j) / 32.0f;
    const float z = -0.5f + 0.1f * static_cast<float>(j);
    drawQuadNdc(left, -1.0f, 1.0f, 1.0f, z, z);
  }
  const unsigned char* shown = glassGetColorBuffer(context.get());
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const int count = std::min(x / 8 + 1, 5);
      const auto expected = glass::geometry::overdrawScaleColor(count);
      const unsigned char* p = pixel(shown, 64, x, y);
      REQUIRE(p[0] == expected[0]);
      REQUIRE(p[1] == expected[1]);
      REQUIRE(p[2] == expected[2]);
    }
  }
  // A new frame (glClear of the colour buffer) starts counting again.
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  drawQuadNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f, 0.0f);
  const auto one = glass::geometry::overdrawScaleColor(1);
  CHECK(pixel(glassGetColorBuffer(context.get()), 64, 60, 5)[0] == one[0]);
  CHECK(pixel(glassGetColorBuffer(context.get()), 64, 60, 5)[2] == one[2]);
}

TEST_CASE("GLASS_VIEW=wireframe draws the triangles clipping made of one triangle") {
  ScopedView view("wireframe");
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);
  glVertex2f(1.5f, -0.5f);
  glVertex2f(-0.5f, 1.5f);
  glEnd();
  // Clipped at x = 1 and y = 1, the triangle is the pentagon (16,16) (64,16) (64,32) (32,64)
  // (16,64) in window coordinates, rasterized as a fan of three triangles: the outline and two
  // diagonals (from whichever vertex the clipper's polygon starts at).
  const double polygon[5][2] = {{16, 16}, {64, 16}, {64, 32}, {32, 64}, {16, 64}};
  std::vector<std::array<double, 4>> outline, diagonals;
  for (int i = 0; i < 5; ++i) {
    for (int j = i + 1; j < 5; ++j) {
      const bool side = j == i + 1 || (i == 0 && j == 4);
      (side ? outline : diagonals).push_back({polygon[i][0], polygon[i][1], polygon[j][0], polygon[j][1]});
    }
  }
  // Edges on the window's right and top border show in its last column and row.
  auto nearestTo = [](const std::vector<std::array<double, 4>>& segments, int x, int y) {
    double nearest = 1e9;
    for (const auto& s : segments) {
      const double px = x == 63 && s[0] == 64 && s[2] == 64 ? 64.0 : x + 0.5;
      const double py = y == 63 && s[1] == 64 && s[3] == 64 ? 64.0 : y + 0.5;
      nearest = std::min(nearest, distanceToSegment(px, py, s[0], s[1], s[2], s[3]));
    }
    return nearest;
  };
  const unsigned char* shown = glassGetColorBuffer(context.get());
  auto litAt = [&](int x, int y) { return pixel(shown, 64, x, y)[0] == 255; };
  int lit = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const double nearest = std::min(nearestTo(outline, x, y), nearestTo(diagonals, x, y));
      if (litAt(x, y)) {
        ++lit;
        CHECK(nearest <= 0.71);  // a marked pixel holds a point of an edge
      }
      if (nearestTo(outline, x, y) <= 0.25) CHECK(litAt(x, y));  // the outline passes through it
    }
  }
  int drawnDiagonals = 0;
  for (const auto& d : diagonals) {
    bool all = true;
    for (int k = 1; k < 8; ++k) {
      const double t = k / 8.0;
      // The point may lie on a pixel corner: one of the four pixels around it.
      const int x = static_cast<int>(std::lround(d[0] + (d[2] - d[0]) * t));
      const int y = static_cast<int>(std::lround(d[1] + (d[3] - d[1]) * t));
      all = all && (litAt(x, y) || litAt(x - 1, y) || litAt(x, y - 1) || litAt(x - 1, y - 1));
    }
    drawnDiagonals += all;
  }
  CHECK(drawnDiagonals == 2);
  CHECK(lit > 0);
  for (int y = 16; y < 32; ++y) CHECK(pixel(shown, 64, 63, y)[0] == 255);  // the edge x = 1 made
  for (int x = 16; x < 32; ++x) CHECK(pixel(shown, 64, x, 63)[0] == 255);  // the edge y = 1 made
}

TEST_CASE("A view leaves the colour buffer as the program drew it; unset, nothing changes") {
  auto draw = [] {
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glColor3f(1.0f, 0.5f, 0.0f);
    drawQuadNdc(-0.5f, -0.5f, 0.7f, 0.6f, -0.2f, 0.3f);
    glColor3f(0.0f, 0.5f, 1.0f);
    drawQuadNdc(-0.8f, -0.2f, 0.3f, 0.9f, 0.1f, -0.4f);
  };
  std::vector<uint8_t> plain, viewed;
  {
    glass::test::ScopedContext context(48, 40);
    draw();
    plain = glass::test::readFramebuffer(48, 40);
    // Unset, the readers get the colour buffer itself.
    CHECK(std::memcmp(glassGetColorBuffer(context.get()), plain.data(), plain.size()) == 0);
  }
  for (const char* name : {"depth", "overdraw", "wireframe", "normals", "mipmap"}) {
    CAPTURE(name);
    ScopedView view(name);
    glass::test::ScopedContext context(48, 40);
    draw();
    viewed = glass::test::readFramebuffer(48, 40);
    CHECK(viewed == plain);
    CHECK(std::memcmp(glassGetColorBuffer(context.get()), plain.data(), plain.size()) != 0);
  }
}

namespace {

// The normals view's colour of an eye-space normal: 255 (n / |n| + 1) / 2, computed here in
// double precision from the definition in docs/teaching.md.
std::array<int, 3> normalColor(double x, double y, double z) {
  const double length = std::sqrt(x * x + y * y + z * z);
  return {static_cast<int>(std::lround(127.5 * (x / length + 1.0))),
          static_cast<int>(std::lround(127.5 * (y / length + 1.0))),
          static_cast<int>(std::lround(127.5 * (z / length + 1.0)))};
}

void checkColor(const unsigned char* p, std::array<int, 3> expected, int tolerance) {
  CHECK(std::abs(p[0] - expected[0]) <= tolerance);
  CHECK(std::abs(p[1] - expected[1]) <= tolerance);
  CHECK(std::abs(p[2] - expected[2]) <= tolerance);
  CHECK(p[3] == 255);
}

}  // namespace

TEST_CASE("GLASS_VIEW=normals shows the eye-space normal of the surface each pixel shows") {
  ScopedView view("normals");
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Quadrant x < 32, y < 32: normal (0, 0, 1), facing the eye.
  glNormal3f(0.0f, 0.0f, 1.0f);
  drawQuadNdc(-1.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f);
  // Quadrant x >= 32, y < 32: the normal (1, 0, 0) under a modelview rotation of 90 degrees about
  // z is (0, 1, 0) in eye space (n_e = n_o M^-1); the quad is drawn rotated to cover the quadrant.
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  // A quarter turn about z, (x, y) -> (-y, x), written exactly (glRotatef's cos 90 is not 0).
  const GLfloat quarterTurn[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  glMultMatrixf(quarterTurn);
  glNormal3f(1.0f, 0.0f, 0.0f);
  drawQuadNdc(-1.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f);
  glPopMatrix();
  // Quadrant x < 32, y >= 32: (0, -3, 0), not unit length and GL_NORMALIZE off: shown as (0, -1, 0).
  glNormal3f(0.0f, -3.0f, 0.0f);
  drawQuadNdc(-1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f);
  // Quadrant x >= 32, y >= 32: first a near quad with normal (-1, 0, 0), then a far one with
  // (0, 0, -1) that fails the depth test: the pixel shows the near quad's normal.
  glNormal3f(-1.0f, 0.0f, 0.0f);
  drawQuadNdc(0.0f, 0.0f, 1.0f, 1.0f, -0.5f, -0.5f);
  glNormal3f(0.0f, 0.0f, -1.0f);
  drawQuadNdc(0.0f, 0.0f, 1.0f, 1.0f, 0.5f, 0.5f);

  const unsigned char* shown = glassGetColorBuffer(context.get());
  const std::array<int, 3> facing = {128, 128, 255}, up = {128, 255, 128}, down = {128, 0, 128},
                           left = {0, 128, 128};
  CHECK(normalColor(0, 0, 1) == facing);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      CAPTURE(x);
      CAPTURE(y);
      const std::array<int, 3> expected = y < 32 ? (x < 32 ? facing : up) : (x < 32 ? down : left);
      checkColor(pixel(shown, 64, x, y), expected, 0);
    }
  }
  // A new frame starts black: no fragment has painted a pixel yet.
  glClear(GL_COLOR_BUFFER_BIT);
  checkColor(pixel(glassGetColorBuffer(context.get()), 64, 10, 10), {0, 0, 0}, 0);
}

TEST_CASE("GLASS_VIEW=normals interpolates the normal across a triangle, then normalizes it") {
  ScopedView view("normals");
  glass::test::ScopedContext context(64, 8);
  glClear(GL_COLOR_BUFFER_BIT);
  // Normals (-1, 0, 1) on the left edge and (1, 0, 1) on the right: at the centre of column x the
  // interpolated normal is (2 t - 1, 0, 1), t = (x + 0.5) / 64 (orthographic: w = 1, so
  // perspective-correct interpolation is linear).
  glBegin(GL_QUADS);
  glNormal3f(-1.0f, 0.0f, 1.0f);
  glVertex2f(-1.0f, -1.0f);
  glNormal3f(1.0f, 0.0f, 1.0f);
  glVertex2f(1.0f, -1.0f);
  glVertex2f(1.0f, 1.0f);
  glNormal3f(-1.0f, 0.0f, 1.0f);
  glVertex2f(-1.0f, 1.0f);
  glEnd();
  const unsigned char* shown = glassGetColorBuffer(context.get());
  for (int x = 0; x < 64; ++x) {
    const double nx = 2.0 * (x + 0.5) / 64.0 - 1.0;
    for (int y = 0; y < 8; ++y) checkColor(pixel(shown, 64, x, y), normalColor(nx, 0.0, 1.0), 1);
  }
  // The program's own picture is its colours, here the current colour white.
  CHECK(glass::test::pixelAt(5, 5) == glass::test::Rgba{255, 255, 255, 255});
}

namespace {

// A 64 x 64 RGBA texture with all seven mipmap levels, level k filled with one grey.
void loadMipmappedTexture(GLenum minFilter) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  for (int level = 0, size = 64; size >= 1; ++level, size /= 2) {
    std::vector<unsigned char> texels(static_cast<std::size_t>(size) * size * 4,
                                      static_cast<unsigned char>(200 - 20 * level));
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
}

// A strip of the window, columns 16k to 16k + 15 of a 64 x 64 window, whose texture coordinates
// make one pixel cover `scale` texels of the 64 x 64 base image in both directions: rho = scale
// (spec 3.8.8, equation 3.21), so lambda = log2(scale).
void drawStripWithScale(int k, double scale) {
  const float x0 = -1.0f + 0.5f * static_cast<float>(k), x1 = x0 + 0.5f;
  const auto sRange = static_cast<float>(scale * 16.0 / 64.0), tRange = static_cast<float>(scale);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex2f(x0, -1.0f);
  glTexCoord2f(sRange, 0.0f);
  glVertex2f(x1, -1.0f);
  glTexCoord2f(sRange, tRange);
  glVertex2f(x1, 1.0f);
  glTexCoord2f(0.0f, tRange);
  glVertex2f(x0, 1.0f);
  glEnd();
}

}  // namespace

TEST_CASE("GLASS_VIEW=mipmap shows the level each pixel's lookup reads, one colour a level") {
  ScopedView view("mipmap");
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  loadMipmappedTexture(GL_NEAREST_MIPMAP_NEAREST);
  // Strips with rho = 1, 2, 4, 8: lambda = 0 is magnification (lambda <= c = 0, spec 3.8.9), the
  // base level; lambda = 1, 2, 3 select level d = ceil(lambda + 1/2) - 1 = lambda (spec 3.8.8).
  for (int k = 0; k < 4; ++k) drawStripWithScale(k, std::ldexp(1.0, k));
  const unsigned char* shown = glassGetColorBuffer(context.get());
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const auto expected = glass::geometry::mipmapScaleColor(x / 16);
      checkColor(pixel(shown, 64, x, y), {expected[0], expected[1], expected[2]}, 0);
    }
  }
  CHECK(glass::geometry::mipmapScaleColor(0) != glass::geometry::mipmapScaleColor(1));

  // GL_LINEAR_MIPMAP_LINEAR mixes two levels: rho = 2^1.5 gives lambda = 1.5, half level 1 and
  // half level 2, and the view mixes their colours the same way. rho = 2^3.25: a quarter of 4.
  glClear(GL_COLOR_BUFFER_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  drawStripWithScale(0, std::pow(2.0, 1.5));
  drawStripWithScale(1, std::pow(2.0, 3.25));
  // Untextured fragments are grey.
  glDisable(GL_TEXTURE_2D);
  drawStripWithScale(2, 1.0);
  shown = glassGetColorBuffer(context.get());
  auto mix = [](int a, int b, double w) {
    const auto ca = glass::geometry::mipmapScaleColor(a), cb = glass::geometry::mipmapScaleColor(b);
    std::array<int, 3> out{};
    for (int c = 0; c < 3; ++c) out[c] = static_cast<int>(std::lround((1.0 - w) * ca[c] + w * cb[c]));
    return out;
  };
  const auto grey = glass::geometry::kMipmapUntexturedColor;
  for (int y = 0; y < 64; y += 7) {
    checkColor(pixel(shown, 64, 5, y), mix(1, 2, 0.5), 2);
    checkColor(pixel(shown, 64, 20, y), mix(3, 4, 0.25), 2);
    checkColor(pixel(shown, 64, 40, y), {grey[0], grey[1], grey[2]}, 0);
    checkColor(pixel(shown, 64, 60, y), {0, 0, 0}, 0);  // nothing drawn
  }
}

TEST_CASE("An unknown GLASS_VIEW leaves the program's picture") {
  ScopedView view("sideways");
  glass::test::ScopedContext context(8, 8);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(glassGetColorBuffer(context.get())[0] == 255);
  CHECK(glassGetColorBuffer(context.get())[1] == 0);
}
