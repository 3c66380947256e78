// glDrawBuffer and glReadBuffer on glass's single colour buffer (fragment/buffer_selection.h):
// which names select it, which are errors, GL_NONE, lists and the attribute stack.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

GLint integerState(GLenum pname) {
  GLint v[4] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

}  // namespace

TEST_CASE("glDrawBuffer: the front-left names and GL_BACK select the colour buffer") {
  ScopedContext context;
  CHECK(integerState(GL_DRAW_BUFFER) == GL_FRONT);
  CHECK(integerState(GL_READ_BUFFER) == GL_FRONT);
  for (GLenum buffer : {GL_BACK, GL_FRONT_AND_BACK, GL_LEFT, GL_FRONT_LEFT, GL_BACK_LEFT,
                        GL_NONE, GL_FRONT}) {
    glDrawBuffer(buffer);
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK(integerState(GL_DRAW_BUFFER) == static_cast<GLint>(buffer));
  }
}

TEST_CASE("glDrawBuffer and glReadBuffer: missing buffers and bad names are errors") {
  ScopedContext context;
  for (GLenum buffer : {GL_RIGHT, GL_FRONT_RIGHT, GL_BACK_RIGHT, GL_AUX0, GL_AUX3}) {
    glDrawBuffer(buffer);
    CHECK(glGetError() == GL_INVALID_OPERATION);
    glReadBuffer(buffer);
    CHECK(glGetError() == GL_INVALID_OPERATION);
  }
  glDrawBuffer(GL_TEXTURE_2D);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glReadBuffer(GL_TEXTURE_2D);
  CHECK(glGetError() == GL_INVALID_ENUM);
  CHECK(integerState(GL_DRAW_BUFFER) == GL_FRONT);
  CHECK(integerState(GL_READ_BUFFER) == GL_FRONT);

  glBegin(GL_POINTS);
  glDrawBuffer(GL_BACK);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  CHECK(integerState(GL_DRAW_BUFFER) == GL_FRONT);
}

TEST_CASE("Drawing to GL_BACK and reading GL_BACK use the one colour buffer") {
  ScopedContext context(8, 8);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(pixelAt(2, 2) == Rgba{0, 255, 0, 255});
}

TEST_CASE("glDrawBuffer and glReadBuffer are compiled into lists and saved by the attribute stack") {
  ScopedContext context;
  glNewList(1, GL_COMPILE);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  glEndList();
  CHECK(integerState(GL_DRAW_BUFFER) == GL_FRONT);
  glCallList(1);
  CHECK(integerState(GL_DRAW_BUFFER) == GL_BACK);
  CHECK(integerState(GL_READ_BUFFER) == GL_BACK);

  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_FRONT);
  glPopAttrib();
  CHECK(integerState(GL_DRAW_BUFFER) == GL_BACK);
  CHECK(integerState(GL_READ_BUFFER) == GL_BACK);

  // Each group holds only its own buffer.
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_FRONT);
  glPopAttrib();
  CHECK(integerState(GL_DRAW_BUFFER) == GL_FRONT);
}
