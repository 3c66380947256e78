// Non-antialiased points take their size rounded to an integer (spec 3.3, "the nearest integer"),
// with halves rounded down as Mesa's llvmpipe rounds them: the sizes 1.5, 2.5 and 3.5 draw 1 x 1,
// 2 x 2 and 3 x 3 squares, 1.6 a 2 x 2 square. Measured against Mesa 22.3 with the same point.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::readFramebuffer;
using glass::test::ScopedContext;

namespace {

int pointPixels(float size) {
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(size);
  glBegin(GL_POINTS);
  glVertex2f(20.3f, 20.6f);
  glEnd();
  const std::vector<uint8_t> pixels = readFramebuffer(64, 64);
  int lit = 0;
  for (std::size_t i = 0; i < pixels.size(); i += 4) lit += pixels[i] != 0;
  return lit;
}

}  // namespace

TEST_CASE("glPointSize: halves round down, as in Mesa") {
  ScopedContext context(64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 64.0, 0.0, 64.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1.0f, 1.0f, 1.0f);

  CHECK(pointPixels(0.5f) == 1);
  CHECK(pointPixels(1.4f) == 1);
  CHECK(pointPixels(1.5f) == 1);
  CHECK(pointPixels(1.6f) == 4);
  CHECK(pointPixels(2.5f) == 4);
  CHECK(pointPixels(3.3f) == 9);
  CHECK(pointPixels(3.5f) == 9);
  CHECK(pointPixels(4.7f) == 25);
  CHECK(glGetError() == GL_NO_ERROR);
}
