// The attribute groups of the raster position, pixel transfer, accumulation clear value and
// polygon stipple (spec 6.1.14, tables 6.5, 6.13, 6.16, 6.17 and 6.21).
#include <GL/gl.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

TEST_CASE("pixels attributes: GL_CURRENT_BIT saves the raster position") {
  ScopedContext context(16, 16);
  glass::test::pixelProjection(16, 16);
  glColor3f(1.0f, 0.0f, 0.0f);
  glRasterPos2i(3, 4);
  glPushAttrib(GL_CURRENT_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  glRasterPos2i(30, 4);  // invalid
  glPopAttrib();
  GLfloat position[4], color[4];
  GLboolean valid = GL_FALSE;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, position);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, color);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  CHECK(valid == GL_TRUE);
  CHECK(position[0] == doctest::Approx(3.0f));
  CHECK(color[0] == 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels attributes: GL_PIXEL_MODE_BIT saves transfer and zoom, not the maps") {
  ScopedContext context(16, 16);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPixelZoom(3.0f, -1.0f);
  const GLfloat map[2] = {0.25f, 0.5f};
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, map);
  glPopAttrib();
  GLfloat f = 0.0f;
  glGetFloatv(GL_RED_SCALE, &f);
  CHECK(f == 1.0f);
  glGetFloatv(GL_ZOOM_X, &f);
  CHECK(f == 1.0f);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_MAP_COLOR, &b);
  CHECK(b == GL_FALSE);
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_G_TO_G_SIZE, &size);
  CHECK(size == 2);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels attributes: GL_ACCUM_BUFFER_BIT and GL_POLYGON_STIPPLE_BIT") {
  ScopedContext context(16, 16);
  glClearAccum(0.5f, 0.25f, 0.0f, 1.0f);
  GLubyte pattern[128];
  for (int i = 0; i < 128; ++i) pattern[i] = static_cast<GLubyte>(i);
  glPolygonStipple(pattern);
  glPushAttrib(GL_ACCUM_BUFFER_BIT | GL_POLYGON_STIPPLE_BIT);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  GLubyte zeros[128] = {};
  glPolygonStipple(zeros);
  glPopAttrib();
  GLfloat clear[4];
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, clear);
  CHECK(clear[0] == 0.5f);
  CHECK(clear[1] == 0.25f);
  GLubyte out[128];
  glGetPolygonStipple(out);
  CHECK(out[77] == 77);
  CHECK(glGetError() == GL_NO_ERROR);
}
