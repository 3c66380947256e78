// glassSetView and glassGetView: the teaching view of a context switched while it lives, as glass's
// GLUT switches it on Ctrl+Alt+V; the picture shown follows the view from the next draw on.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cstring>
#include <vector>

#include "glass/geometry/teaching_scales.h"
#include "pipeline_test_support.h"

namespace {

// Two overlapping quads: the left half of the window covered twice, the right half once.
void drawTwoQuads() {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
  glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 1.0f, 0.0f);
}

// Pixel (x, y) of what the context shows (glassGetColorBuffer: the view's picture, if any).
std::vector<unsigned char> shownAt(GlassContext* ctx, int x, int y) {
  const unsigned char* p = glassGetColorBuffer(ctx) + (static_cast<std::size_t>(y) * glassGetWidth(ctx) + x) * 4;
  return {p[0], p[1], p[2]};
}

std::vector<unsigned char> overdrawColor(int count) {
  const auto c = glass::geometry::overdrawScaleColor(count);
  return {c[0], c[1], c[2]};
}

}  // namespace

TEST_CASE("glassSetView switches the view a context shows, and NULL gives the program's colours back") {
  glass::test::ScopedContext context(16, 16);
  GlassContext* ctx = context.get();
  CHECK(glassGetView(ctx) == nullptr);
  drawTwoQuads();
  CHECK(shownAt(ctx, 2, 8) == std::vector<unsigned char>{255, 0, 0});

  REQUIRE(glassSetView(ctx, "overdraw") == 1);
  CHECK(std::strcmp(glassGetView(ctx), "overdraw") == 0);
  drawTwoQuads();
  CHECK(shownAt(ctx, 2, 8) == overdrawColor(2));
  CHECK(shownAt(ctx, 12, 8) == overdrawColor(1));
  // The program's own colour buffer is untouched.
  CHECK(glass::test::pixelAt(2, 8) == glass::test::Rgba{255, 0, 0, 255});

  // Refused: an unknown name, a call between glBegin and glEnd; the view stays.
  CHECK(glassSetView(ctx, "colour") == 0);
  glBegin(GL_TRIANGLES);
  CHECK(glassSetView(ctx, nullptr) == 0);
  glEnd();
  CHECK(std::strcmp(glassGetView(ctx), "overdraw") == 0);
  CHECK(glassSetView(nullptr, "depth") == 0);
  CHECK(glassGetView(nullptr) == nullptr);

  REQUIRE(glassSetView(ctx, "wireframe") == 1);
  CHECK(std::strcmp(glassGetView(ctx), "wireframe") == 0);
  REQUIRE(glassSetView(ctx, nullptr) == 1);
  CHECK(glassGetView(ctx) == nullptr);
  drawTwoQuads();
  CHECK(shownAt(ctx, 2, 8) == std::vector<unsigned char>{255, 0, 0});
}
