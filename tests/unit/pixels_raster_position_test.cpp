// The current raster position (spec 2.13): glRasterPos transforms, clips, lights and textures like
// a vertex; glWindowPos sets window coordinates; glBitmap moves the position; the queries of
// table 6.5; display lists and errors.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

struct RasterState {
  float window[4];
  bool valid;
  float distance;
  float color[4];
  float texCoord[4];
};

RasterState rasterState() {
  RasterState r{};
  GLboolean valid = GL_FALSE;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, r.window);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &r.distance);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, r.color);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, r.texCoord);
  r.valid = valid == GL_TRUE;
  return r;
}

}  // namespace

TEST_CASE("pixels raster position: the initial state of table 6.5") {
  ScopedContext context(32, 32);
  const RasterState r = rasterState();
  CHECK(r.valid);
  CHECK(r.window[0] == 0.0f);
  CHECK(r.window[1] == 0.0f);
  CHECK(r.window[2] == 0.0f);
  CHECK(r.window[3] == 1.0f);
  CHECK(r.distance == 0.0f);
  for (int i = 0; i < 4; ++i) CHECK(r.color[i] == 1.0f);
  CHECK(r.texCoord[0] == 0.0f);
  CHECK(r.texCoord[3] == 1.0f);
}

TEST_CASE("pixels raster position: transformed like a vertex, with the clip w kept") {
  ScopedContext context(100, 80);
  glViewport(10, 20, 60, 40);
  glDepthRange(0.25, 0.75);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -2.0f);
  glRasterPos3f(0.5f, -0.5f, 0.0f);
  const RasterState r = rasterState();
  CHECK(r.valid);
  // Eye (0.5, -0.5, -2): clip = (0.5, -0.5, z_c, 2), ndc = (0.25, -0.25, z_c / 2).
  CHECK(r.window[0] == doctest::Approx(10 + 30 * 1.25));
  CHECK(r.window[1] == doctest::Approx(20 + 20 * 0.75));
  const double zc = -(10.0 + 1.0) / (10.0 - 1.0) * -2.0 - 2.0 * 10.0 * 1.0 / (10.0 - 1.0);
  CHECK(r.window[2] == doctest::Approx(0.5 + 0.25 * (zc / 2.0)).epsilon(1e-5));
  CHECK(r.window[3] == doctest::Approx(2.0));
  // Spec 2.13: the distance from the eye to the point.
  CHECK(r.distance == doctest::Approx(std::sqrt(0.25 + 0.25 + 4.0)));
}

TEST_CASE("pixels raster position: outside the view volume or a user clip plane it is invalid") {
  ScopedContext context(32, 32);
  glColor3f(0.25f, 0.5f, 0.75f);
  glRasterPos2f(0.5f, 0.5f);
  CHECK(rasterState().valid);
  const RasterState before = rasterState();

  glColor3f(1.0f, 0.0f, 0.0f);
  glRasterPos2f(1.5f, 0.0f);
  RasterState r = rasterState();
  CHECK_FALSE(r.valid);
  // The rest of the raster state keeps its values.
  CHECK(r.window[0] == before.window[0]);
  CHECK(r.color[0] == before.color[0]);

  glRasterPos3f(0.0f, 0.0f, -1.5f);  // beyond the far plane
  CHECK_FALSE(rasterState().valid);
  glRasterPos2f(1.0f, -1.0f);        // on the boundary: inside
  CHECK(rasterState().valid);

  const GLdouble plane[4] = {1.0, 0.0, 0.0, -0.25};  // keeps x >= 0.25
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glRasterPos2f(0.0f, 0.0f);
  CHECK_FALSE(rasterState().valid);
  glRasterPos2f(0.5f, 0.0f);
  CHECK(rasterState().valid);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels raster position: the colour is the current colour, clamped, or lit") {
  ScopedContext context(32, 32);
  glColor4f(0.2f, 1.5f, -0.5f, 0.5f);
  glRasterPos2f(0.0f, 0.0f);
  RasterState r = rasterState();
  CHECK(r.color[0] == doctest::Approx(0.2f));
  CHECK(r.color[1] == 1.0f);
  CHECK(r.color[2] == 0.0f);
  CHECK(r.color[3] == doctest::Approx(0.5f));

  // Lighting: only the material's emission and the global ambient times its ambient.
  const GLfloat ambient[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  const GLfloat materialAmbient[4] = {0.4f, 0.2f, 0.0f, 1.0f};
  const GLfloat emission[4] = {0.1f, 0.0f, 0.3f, 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_AMBIENT, materialAmbient);
  glMaterialfv(GL_FRONT, GL_EMISSION, emission);
  glEnable(GL_LIGHTING);
  glRasterPos2f(0.0f, 0.0f);
  r = rasterState();
  CHECK(r.color[0] == doctest::Approx(0.1f + 0.5f * 0.4f));
  CHECK(r.color[1] == doctest::Approx(0.5f * 0.2f));
  CHECK(r.color[2] == doctest::Approx(0.3f));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels raster position: texture coordinates through texgen and the texture matrix") {
  ScopedContext context(32, 32);
  glTexCoord4f(1.0f, 2.0f, 3.0f, 1.0f);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0.0f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
  // Texturing is disabled: the raster position still carries transformed coordinates.
  glRasterPos2f(0.25f, 0.5f);
  RasterState r = rasterState();
  CHECK(r.texCoord[0] == doctest::Approx(1.5f));
  CHECK(r.texCoord[1] == doctest::Approx(2.0f));

  const GLfloat plane[4] = {2.0f, 0.0f, 0.0f, 0.0f};  // s = 2 x_o
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glRasterPos2f(0.25f, 0.5f);
  r = rasterState();
  CHECK(r.texCoord[0] == doctest::Approx(0.5f + 0.5f));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels raster position: glWindowPos sets window coordinates directly") {
  ScopedContext context(64, 64);
  glDepthRange(0.2, 0.6);
  glColor4f(0.5f, 0.25f, 2.0f, 1.0f);
  glTexCoord2f(3.0f, 4.0f);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(100.0f, 100.0f, 0.0f);  // no effect on glWindowPos
  glRasterPos2f(5.0f, 5.0f);           // invalid
  CHECK_FALSE(rasterState().valid);
  glWindowPos3f(10.5f, -20.0f, 0.5f);
  RasterState r = rasterState();
  CHECK(r.valid);  // even outside the window
  CHECK(r.window[0] == 10.5f);
  CHECK(r.window[1] == -20.0f);
  CHECK(r.window[2] == doctest::Approx(0.4f));  // z in [0, 1] mapped through the depth range
  CHECK(r.window[3] == 1.0f);
  CHECK(r.distance == 0.0f);
  CHECK(r.color[2] == 1.0f);
  CHECK(r.texCoord[0] == 3.0f);
  glWindowPos3i(1, 2, 5);  // z clamped to 1
  CHECK(rasterState().window[2] == doctest::Approx(0.6f));
  const GLshort v[2] = {7, 9};
  glWindowPos2sv(v);
  r = rasterState();
  CHECK(r.window[0] == 7.0f);
  CHECK(r.window[1] == 9.0f);
  CHECK(r.window[2] == doctest::Approx(0.2f));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels raster position: glBitmap moves a valid position, not an invalid one") {
  ScopedContext context(64, 64);
  glWindowPos2f(10.0f, 20.0f);
  glBitmap(0, 0, 0.0f, 0.0f, 2.5f, -4.0f, nullptr);
  RasterState r = rasterState();
  CHECK(r.window[0] == 12.5f);
  CHECK(r.window[1] == 16.0f);
  glRasterPos2f(3.0f, 0.0f);  // invalid
  glBitmap(0, 0, 0.0f, 0.0f, 2.5f, -4.0f, nullptr);
  r = rasterState();
  CHECK_FALSE(r.valid);
  CHECK(r.window[0] == 12.5f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pixels raster position: all entry points, display lists and errors") {
  ScopedContext context(64, 64);
  glass::test::pixelProjection(64, 64);
  const GLint iv[4] = {3, 4, 0, 1};
  const GLdouble dv[3] = {5.0, 6.0, 0.0};
  const GLshort sv[4] = {7, 8, 0, 1};
  glRasterPos4iv(iv);
  CHECK(rasterState().window[0] == 3.0f);
  glRasterPos3dv(dv);
  CHECK(rasterState().window[1] == 6.0f);
  glRasterPos4sv(sv);
  CHECK(rasterState().window[0] == 7.0f);
  glRasterPos4f(8.0f, 8.0f, 0.0f, 2.0f);  // w = 2: (4, 4)
  CHECK(rasterState().window[0] == 4.0f);

  // Compiled into display lists, executed when called.
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glRasterPos2i(20, 30);
  glWindowPos2i(1, 1);
  glRasterPos2i(21, 31);
  glEndList();
  CHECK(rasterState().window[0] == 4.0f);
  glCallList(list);
  CHECK(rasterState().window[0] == 21.0f);
  CHECK(rasterState().window[1] == 31.0f);

  glBegin(GL_POINTS);
  glRasterPos2i(1, 1);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glWindowPos2i(1, 1);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  CHECK(rasterState().window[0] == 21.0f);
}
