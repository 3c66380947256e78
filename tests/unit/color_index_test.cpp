// Colour index commands in glass's RGBA context: accepted, kept for glGet, lists and the
// attribute stacks, and never visible in a pixel (core/color_index.h).
#include <doctest/doctest.h>

#include <GL/gl.h>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

GLfloat floatState(GLenum pname) {
  GLfloat v[4] = {};
  glGetFloatv(pname, v);
  return v[0];
}

GLint integerState(GLenum pname) {
  GLint v[4] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

}  // namespace

TEST_CASE("glIndex sets the current index in every form; the default is 1") {
  ScopedContext context;
  CHECK(floatState(GL_CURRENT_INDEX) == 1.0f);
  glIndexf(2.5f);
  CHECK(floatState(GL_CURRENT_INDEX) == 2.5f);
  glIndexd(3.25);
  CHECK(floatState(GL_CURRENT_INDEX) == 3.25f);
  glIndexi(-4);  // integers convert as plain numbers, not normalized
  CHECK(floatState(GL_CURRENT_INDEX) == -4.0f);
  glIndexs(7);
  CHECK(floatState(GL_CURRENT_INDEX) == 7.0f);
  glIndexub(200);
  CHECK(floatState(GL_CURRENT_INDEX) == 200.0f);
  const GLdouble d = 1.5;
  const GLfloat f = 2.0f;
  const GLint i = 9;
  const GLshort s = 11;
  const GLubyte ub = 13;
  glIndexdv(&d);
  CHECK(floatState(GL_CURRENT_INDEX) == 1.5f);
  glIndexfv(&f);
  CHECK(floatState(GL_CURRENT_INDEX) == 2.0f);
  glIndexiv(&i);
  CHECK(integerState(GL_CURRENT_INDEX) == 9);
  glIndexsv(&s);
  CHECK(integerState(GL_CURRENT_INDEX) == 11);
  glIndexubv(&ub);
  CHECK(integerState(GL_CURRENT_INDEX) == 13);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glIndex is allowed between glBegin and glEnd and draws nothing different") {
  ScopedContext context(8, 8);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);
  glIndexi(3);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(pixelAt(4, 4) == Rgba{0, 255, 0, 255});
  CHECK(floatState(GL_CURRENT_INDEX) == 3.0f);
}

TEST_CASE("glClearIndex and glIndexMask are state only; glClear ignores them in RGBA mode") {
  ScopedContext context(4, 4);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 0.0f);
  CHECK(integerState(GL_INDEX_WRITEMASK) == -1);
  glClearIndex(5.0f);
  glIndexMask(0x0F);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 5.0f);
  CHECK(integerState(GL_INDEX_WRITEMASK) == 0x0F);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(pixelAt(1, 1) == Rgba{255, 0, 0, 255});

  glBegin(GL_POINTS);
  glClearIndex(1.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 5.0f);
}

TEST_CASE("glPushAttrib saves the current index (current) and clear index and mask (colour)") {
  ScopedContext context;
  glIndexf(4.0f);
  glClearIndex(2.0f);
  glIndexMask(3);
  glPushAttrib(GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT);
  glIndexf(8.0f);
  glClearIndex(6.0f);
  glIndexMask(1);
  glPopAttrib();
  CHECK(floatState(GL_CURRENT_INDEX) == 4.0f);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 2.0f);
  CHECK(integerState(GL_INDEX_WRITEMASK) == 3);
}

TEST_CASE("glIndex, glClearIndex and glIndexMask are compiled into display lists") {
  ScopedContext context;
  glNewList(1, GL_COMPILE);
  glIndexi(6);
  glClearIndex(7.0f);
  glIndexMask(5);
  glEndList();
  CHECK(floatState(GL_CURRENT_INDEX) == 1.0f);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 0.0f);
  glCallList(1);
  CHECK(floatState(GL_CURRENT_INDEX) == 6.0f);
  CHECK(floatState(GL_INDEX_CLEAR_VALUE) == 7.0f);
  CHECK(integerState(GL_INDEX_WRITEMASK) == 5);
}

TEST_CASE("glIndexPointer and GL_INDEX_ARRAY: client state with its errors, ignored by draws") {
  ScopedContext context(8, 8);
  const GLfloat indices[4] = {1, 2, 3, 4};
  CHECK(glIsEnabled(GL_INDEX_ARRAY) == GL_FALSE);
  CHECK(integerState(GL_INDEX_ARRAY_TYPE) == GL_FLOAT);
  glIndexPointer(GL_FLOAT, 4, indices);
  glEnableClientState(GL_INDEX_ARRAY);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(glIsEnabled(GL_INDEX_ARRAY) == GL_TRUE);
  CHECK(integerState(GL_INDEX_ARRAY_STRIDE) == 4);
  GLvoid* pointer = nullptr;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &pointer);
  CHECK(pointer == indices);

  glIndexPointer(GL_BYTE, 0, indices);  // table 2.4: no signed bytes for indices
  CHECK(glGetError() == GL_INVALID_ENUM);
  glIndexPointer(GL_SHORT, -1, indices);
  CHECK(glGetError() == GL_INVALID_VALUE);
  CHECK(integerState(GL_INDEX_ARRAY_TYPE) == GL_FLOAT);

  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_INDEX_ARRAY);
  glPopClientAttrib();
  CHECK(glIsEnabled(GL_INDEX_ARRAY) == GL_TRUE);

  // A draw with the index array enabled draws as without it.
  const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glEnableClientState(GL_VERTEX_ARRAY);
  glColor3f(0.0f, 0.0f, 1.0f);
  glDrawArrays(GL_QUADS, 0, 4);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(pixelAt(3, 3) == Rgba{0, 0, 255, 255});
}
