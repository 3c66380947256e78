// glassSetAncillaryBuffers: a context made without a depth, stencil or accumulation buffer reports
// 0 bits for it and acts as OpenGL 1.x says of a framebuffer without it; glassResetContext and
// glassResizeContext keep the choice.
#include <GL/gl.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <initializer_list>

namespace {

GLint integer(GLenum pname) {
  GLint value = -1;
  glGetIntegerv(pname, &value);
  return value;
}

// A near red square, then a far green one over it with the depth test on: the colour at the
// centre (red when the depth test works).
GLubyte greenAtCentreAfterDepthTest() {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  for (const GLfloat z : {-0.5f, 0.5f}) {
    glColor3f(z < 0.0f ? 1.0f : 0.0f, z < 0.0f ? 0.0f : 1.0f, 0.0f);
    glBegin(GL_QUADS);
    glVertex3f(-1.0f, -1.0f, z);
    glVertex3f(1.0f, -1.0f, z);
    glVertex3f(1.0f, 1.0f, z);
    glVertex3f(-1.0f, 1.0f, z);
    glEnd();
  }
  GLubyte pixel[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  return pixel[1];
}

}  // namespace

TEST_CASE("glassSetAncillaryBuffers: absent buffers read 0 bits and their tests do nothing, kept by reset and resize") {
  GlassContext *ctx = glassCreateContext(16, 16);
  REQUIRE(ctx != nullptr);
  glassMakeCurrent(ctx);
  CHECK(integer(GL_DEPTH_BITS) > 0);
  CHECK(integer(GL_STENCIL_BITS) == 8);
  CHECK(integer(GL_ACCUM_RED_BITS) > 0);

  CHECK(glassSetAncillaryBuffers(ctx, 0, 1, 0) == 1);
  for (int round = 0; round < 3; ++round) {
    CAPTURE(round);
    CHECK(integer(GL_DEPTH_BITS) == 0);
    CHECK(integer(GL_STENCIL_BITS) == 8);
    CHECK(integer(GL_ACCUM_RED_BITS) == 0);
    CHECK(greenAtCentreAfterDepthTest() == 255);  // no depth buffer: the later square shows
    glAccum(GL_LOAD, 1.0f);
    CHECK(glGetError() == GL_INVALID_OPERATION);
    if (round == 0) CHECK(glassResetContext(ctx) == 1);
    if (round == 1) CHECK(glassResizeContext(ctx, 20, 12) == 1);
  }

  CHECK(glassSetAncillaryBuffers(ctx, 1, 1, 1) == 1);
  glassResetContext(ctx);
  CHECK(integer(GL_DEPTH_BITS) > 0);
  CHECK(greenAtCentreAfterDepthTest() == 0);  // the near red square stays
  CHECK(glassSetAncillaryBuffers(nullptr, 1, 1, 1) == 0);
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
}
