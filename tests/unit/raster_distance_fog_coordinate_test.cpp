// The current raster distance with fog coordinates (OpenGL 1.4 specification, section 2.13): with
// GL_FOG_COORDINATE_SOURCE GL_FOG_COORDINATE, glRasterPos and glWindowPos set it to the current
// fog coordinate; otherwise glRasterPos sets the eye distance and glWindowPos 0. Bitmaps and
// pixel rectangles are fogged with it.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::ScopedContext;

namespace {

float rasterDistance() {
  GLfloat d = -1.0f;
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  return d;
}

}  // namespace

TEST_CASE("raster distance: the fog coordinate with GL_FOG_COORDINATE_SOURCE GL_FOG_COORDINATE") {
  ScopedContext context(8, 8);
  glTranslatef(0, 0, -0.5f);
  glFogCoordf(7);
  glRasterPos3f(0.3f, 0.4f, 0);
  CHECK(rasterDistance() == doctest::Approx(std::sqrt(0.3 * 0.3 + 0.4 * 0.4 + 0.25)));
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glRasterPos3f(0.3f, 0.4f, 0);
  CHECK(rasterDistance() == 7.0f);
  glFogCoordf(-2);
  glWindowPos2f(1, 1);
  CHECK(rasterDistance() == -2.0f);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  glWindowPos2f(1, 1);
  CHECK(rasterDistance() == 0.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("raster distance: a bitmap is fogged by the raster fog coordinate") {
  ScopedContext context(8, 8);
  const GLfloat fogColor[4] = {0, 0, 1, 1};
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 4);
  glEnable(GL_FOG);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glColor3f(1, 0, 0);
  // f = (4 - |c|) / 4 = 0.75 for c = -1: red 0.75, blue 0.25.
  glFogCoordf(-1);
  glWindowPos2i(2, 2);
  const GLubyte bits[4] = {0x80, 0, 0, 0};
  glBitmap(1, 1, 0, 0, 0, 0, bits);
  glFinish();
  const glass::test::Rgba p = pixelAt(2, 2);
  CHECK(p.r == 191);
  CHECK(p.g == 0);
  CHECK(p.b == 64);
}
