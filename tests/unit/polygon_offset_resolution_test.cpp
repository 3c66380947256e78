// Polygon offset's r, the smallest resolvable depth difference (spec 3.5.5), is 2 / (2^24 - 1),
// as in Mesa's llvmpipe and draw module (offset_units * mrd * 2): glPolygonOffset(0, u) moves a
// polygon by 2u steps of the 24-bit depth buffer.
//
// The probe: a screen-parallel square at window depth 0.75 (0.75 (2^24 - 1) = 12582911.25,
// stored as 12582911) drawn again over itself with GL_LESS and units -0.4. With r = 2 / (2^24 - 1)
// the copy is 0.8 steps nearer, 12582910.45, stored as 12582910, and wins; with r = 1 / (2^24 - 1)
// it would be 12582910.85, stored as 12582911 again, and lose. Mesa 22.3 draws the copy at -0.3
// and not at -0.2 for the same square; both the fill and the GL_LINE mode.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::ScopedContext;

namespace {

void square() {
  glBegin(GL_QUADS);
  glVertex3f(-0.49f, -0.5f, 0.5f);
  glVertex3f(0.5f, -0.5f, 0.5f);
  glVertex3f(0.5f, 0.5f, 0.5f);
  glVertex3f(-0.49f, 0.5f, 0.5f);
  glEnd();
}

// Draws the square red, then green with the offset in `mode`; true when the green copy wins at
// pixel (x, y).
bool offsetCopyWins(GLenum mode, GLenum offsetCap, float units, int x, int y) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  square();
  glEnable(offsetCap);
  glPolygonOffset(0.0f, units);
  glPolygonMode(GL_FRONT_AND_BACK, mode);
  glColor3f(0.0f, 1.0f, 0.0f);
  square();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(offsetCap);
  return pixelAt(x, y).g == 255;
}

}  // namespace

TEST_CASE("glPolygonOffset units count double steps of the 24-bit depth buffer, as in Mesa") {
  ScopedContext context(64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  // Fill: probe inside the square.
  CHECK(offsetCopyWins(GL_FILL, GL_POLYGON_OFFSET_FILL, -0.4f, 32, 32));
  CHECK_FALSE(offsetCopyWins(GL_FILL, GL_POLYGON_OFFSET_FILL, -0.2f, 32, 32));
  // Outline: probe on its left edge (window x = 16.32).
  CHECK(offsetCopyWins(GL_LINE, GL_POLYGON_OFFSET_LINE, -0.4f, 16, 32));
  CHECK_FALSE(offsetCopyWins(GL_LINE, GL_POLYGON_OFFSET_LINE, -0.2f, 16, 32));
  CHECK(glGetError() == GL_NO_ERROR);
}
