// The implementation-dependent values (OpenGL 1.4 specification, tables 6.35 to 6.37) against
// what glass does: each limit a query reports is the one the commands enforce, one past it is
// refused with the specification's error, and the granularities are steps that change pictures.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelProjection;
using glass::test::readFramebuffer;
using glass::test::ScopedContext;

namespace {

GLint integer(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

GLfloat real(GLenum pname, int index = 0) {
  GLfloat v[2] = {-1.0f, -1.0f};
  glGetFloatv(pname, v);
  return v[index];
}

// A smooth line (or point) of the given width (size), blended, as the colour buffer shows it.
std::vector<uint8_t> smoothPicture(bool line, float size, float offset = 0.0f) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  pixelProjection(32, 32);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor3f(1, 1, 1);
  if (line) {
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(size);
    glBegin(GL_LINES);
    glVertex2f(4.3f, 5.1f);
    glVertex2f(27.6f, 25.4f);
    glEnd();
    glDisable(GL_LINE_SMOOTH);
  } else {
    glEnable(GL_POINT_SMOOTH);
    glPointSize(size);
    glBegin(GL_POINTS);
    glVertex2f(16.2f + offset, 15.7f + offset);
    glEnd();
    glDisable(GL_POINT_SMOOTH);
  }
  glDisable(GL_BLEND);
  return readFramebuffer(32, 32);
}

// Pushes until the stack reports overflow; returns how many pushes succeeded.
template <class Push>
int pushesUntilOverflow(Push push, int limit) {
  int pushed = 0;
  for (int i = 0; i < limit + 4; ++i) {
    push();
    if (glGetError() == GL_STACK_OVERFLOW) break;
    ++pushed;
  }
  return pushed;
}

}  // namespace

TEST_CASE("implementation limits: point and line sizes and their granularity") {
  ScopedContext context(32, 32);
  const float lineStep = real(GL_LINE_WIDTH_GRANULARITY);
  const float pointStep = real(GL_POINT_SIZE_GRANULARITY);
  CHECK(lineStep == doctest::Approx(0.1));
  CHECK(pointStep == doctest::Approx(0.1));
  // One step apart, smooth lines and points draw differently (a 1.5-pixel line is not a 1- or
  // 2-pixel line).
  for (float width : {1.0f, 1.5f, 2.3f, 4.0f}) {
    CAPTURE(width);
    CHECK(smoothPicture(true, width) != smoothPicture(true, width + lineStep));
  }
  // A smooth point covers the pixel centres within its radius (smooth_coverage.h), so a step
  // in size shows where it moves the circle across a centre: at one of a few positions.
  for (float size : {3.0f, 4.5f, 7.0f}) {
    CAPTURE(size);
    bool differs = false;
    for (float offset : {0.0f, 0.13f, 0.29f, 0.41f})
      differs = differs || smoothPicture(false, size, offset) != smoothPicture(false, size + pointStep, offset);
    CHECK(differs);
  }
  // The ranges: widths and sizes beyond the maximum draw as the maximum.
  CHECK(real(GL_LINE_WIDTH_RANGE, 1) == 255.0f);
  CHECK(real(GL_POINT_SIZE_RANGE, 1) == 255.0f);
  CHECK(real(GL_ALIASED_LINE_WIDTH_RANGE, 1) == 255.0f);
  CHECK(smoothPicture(true, 255.0f) == smoothPicture(true, 400.0f));
  CHECK(smoothPicture(false, 255.0f) == smoothPicture(false, 400.0f));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("implementation limits: stacks overflow one past their depth") {
  ScopedContext context(8, 8);
  glMatrixMode(GL_MODELVIEW);
  CHECK(pushesUntilOverflow(glPushMatrix, 64) == integer(GL_MAX_MODELVIEW_STACK_DEPTH) - 1);
  glMatrixMode(GL_PROJECTION);
  CHECK(pushesUntilOverflow(glPushMatrix, 64) == integer(GL_MAX_PROJECTION_STACK_DEPTH) - 1);
  glMatrixMode(GL_TEXTURE);
  CHECK(pushesUntilOverflow(glPushMatrix, 64) == integer(GL_MAX_TEXTURE_STACK_DEPTH) - 1);
  glMatrixMode(GL_MODELVIEW);
  CHECK(pushesUntilOverflow([] { glPushAttrib(GL_CURRENT_BIT); }, 64) ==
        integer(GL_MAX_ATTRIB_STACK_DEPTH));
  CHECK(pushesUntilOverflow([] { glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT); }, 64) ==
        integer(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH));
  std::vector<GLuint> names(256);
  glSelectBuffer(256, names.data());
  glRenderMode(GL_SELECT);
  glInitNames();
  CHECK(pushesUntilOverflow([] { glPushName(1); }, 256) == integer(GL_MAX_NAME_STACK_DEPTH));
  glRenderMode(GL_RENDER);
}

TEST_CASE("implementation limits: counts and sizes are the ones the commands take") {
  ScopedContext context(8, 8);
  const GLfloat on[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0 + integer(GL_MAX_LIGHTS) - 1, GL_DIFFUSE, on);
  CHECK(glGetError() == GL_NO_ERROR);
  glLightfv(GL_LIGHT0 + integer(GL_MAX_LIGHTS), GL_DIFFUSE, on);
  CHECK(glGetError() == GL_INVALID_ENUM);

  const GLdouble plane[4] = {1, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE0 + integer(GL_MAX_CLIP_PLANES) - 1, plane);
  CHECK(glGetError() == GL_NO_ERROR);
  glClipPlane(GL_CLIP_PLANE0 + integer(GL_MAX_CLIP_PLANES), plane);
  CHECK(glGetError() == GL_INVALID_ENUM);

  glActiveTexture(GL_TEXTURE0 + integer(GL_MAX_TEXTURE_UNITS) - 1);
  CHECK(glGetError() == GL_NO_ERROR);
  glActiveTexture(GL_TEXTURE0 + integer(GL_MAX_TEXTURE_UNITS));
  CHECK(glGetError() == GL_INVALID_ENUM);
  glActiveTexture(GL_TEXTURE0);

  const GLint maxTexture = integer(GL_MAX_TEXTURE_SIZE);
  GLint width = -1;
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, maxTexture, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  CHECK(width == maxTexture);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 2 * maxTexture, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  CHECK(width == 0);
  const GLint max3D = integer(GL_MAX_3D_TEXTURE_SIZE);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, max3D, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &width);
  CHECK(width == max3D);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 2 * max3D, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &width);
  CHECK(width == 0);

  GLint viewport[4];
  GLint maxViewportDims[2] = {-1, -1};  // width and height: two values
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewportDims);
  const GLint maxViewport = maxViewportDims[0];
  glViewport(0, 0, maxViewport + 100, maxViewport + 100);
  glGetIntegerv(GL_VIEWPORT, viewport);
  CHECK(viewport[2] == maxViewport);

  std::vector<GLfloat> map(static_cast<size_t>(integer(GL_MAX_PIXEL_MAP_TABLE)) + 1, 0.5f);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, integer(GL_MAX_PIXEL_MAP_TABLE), map.data());
  CHECK(glGetError() == GL_NO_ERROR);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, integer(GL_MAX_PIXEL_MAP_TABLE) + 1, map.data());
  CHECK(glGetError() == GL_INVALID_VALUE);

  const GLint order = integer(GL_MAX_EVAL_ORDER);
  std::vector<GLfloat> points(static_cast<size_t>(order + 1) * 3, 0.0f);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, order, points.data());
  CHECK(glGetError() == GL_NO_ERROR);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, order + 1, points.data());
  CHECK(glGetError() == GL_INVALID_VALUE);

  CHECK(integer(GL_SUBPIXEL_BITS) == 8);
  CHECK(integer(GL_DEPTH_BITS) == 24);
  CHECK(integer(GL_STENCIL_BITS) == 8);
  CHECK(integer(GL_ACCUM_RED_BITS) == 16);
  CHECK(integer(GL_AUX_BUFFERS) == 0);
  CHECK(integer(GL_SAMPLE_BUFFERS) == 0);
}

TEST_CASE("implementation limits: GL_SUBPIXEL_BITS is the grid vertices snap to") {
  // A triangle whose left edge is the vertical line x = 4.5 through the centres of column 4,
  // which the top-left rule includes. Moved right by a quarter of a 2^-8 pixel step, the edge
  // snaps back onto the same line; moved by one step it leaves the centres outside.
  ScopedContext context(8, 8);
  auto picture = [](float dx) {
    glClear(GL_COLOR_BUFFER_BIT);
    pixelProjection(8, 8);
    glBegin(GL_TRIANGLES);
    glVertex2f(4.5f + dx, 0.0f);
    glVertex2f(8.0f, 0.0f);
    glVertex2f(4.5f + dx, 8.0f);
    glEnd();
    return readFramebuffer(8, 8);
  };
  glColor3f(1, 1, 1);
  const float step = 1.0f / static_cast<float>(1 << integer(GL_SUBPIXEL_BITS));
  const std::vector<uint8_t> base = picture(0.0f);
  CHECK(base[(4 * 8 + 4) * 4] == 255);  // column 4 is in
  CHECK(picture(step / 4.0f) == base);
  const std::vector<uint8_t> moved = picture(step);
  CHECK(moved[(4 * 8 + 4) * 4] == 0);
}
