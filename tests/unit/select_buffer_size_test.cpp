// glSelectBuffer and glFeedbackBuffer with a null buffer (OpenGL 1.4 specification, sections
// 5.2, 5.3 and table 6.31): GL_SELECTION_BUFFER_SIZE and GL_FEEDBACK_BUFFER_SIZE are the sizes
// given; nothing is stored through the null pointer, and glRenderMode still counts what would
// have been written.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

TEST_CASE("select buffer: the size of a null buffer is queried as given, and nothing is written") {
  ScopedContext context(8, 8);
  GLint size = -1;
  glSelectBuffer(8, nullptr);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &size);
  CHECK(size == 8);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  CHECK(glRenderMode(GL_RENDER) == 1);  // 4 values of the 8
  // A refused call leaves the size as it was.
  glSelectBuffer(-1, nullptr);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &size);
  CHECK(size == 8);
}

TEST_CASE("feedback buffer: the size of a null buffer is queried as given, and nothing is written") {
  ScopedContext context(8, 8);
  GLint size = -1;
  glFeedbackBuffer(16, GL_2D, nullptr);
  glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &size);
  CHECK(size == 16);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex2f(0, 0);
  glEnd();
  CHECK(glRenderMode(GL_RENDER) == 3);  // GL_POINT_TOKEN, x, y
  CHECK(glGetError() == GL_NO_ERROR);
}
