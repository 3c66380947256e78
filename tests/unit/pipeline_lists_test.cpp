// Display lists (spec 5.4): compile and compile-and-execute, calling, nesting and its limit,
// glCallLists with every type and glListBase, deletion, commands that are not compiled, and
// vertex-array data read at compile time.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstring>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// A rectangle of colour c over pixels [x0, x1) x [y0, y1) of a pixel projection.
void rect(int x0, int y0, int x1, int y1, Rgba c) {
  glColor4ub(c.r, c.g, c.b, c.a);
  glRecti(x0, y0, x1, y1);
}

const Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255};
const Rgba kBlack{0, 0, 0, 0};

}  // namespace

TEST_CASE("pipeline lists: GL_COMPILE records without drawing, GL_COMPILE_AND_EXECUTE draws too") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  const GLuint base = glGenLists(2);
  REQUIRE(base != 0);
  CHECK(glIsList(base) == GL_TRUE);
  CHECK(glIsList(base + 1) == GL_TRUE);  // reserved names are empty lists

  glNewList(base, GL_COMPILE);
  rect(0, 0, 16, 16, kRed);
  GLint index = 0, mode = 0;
  glGetIntegerv(GL_LIST_INDEX, &index);
  glGetIntegerv(GL_LIST_MODE, &mode);
  glEndList();
  CHECK(index == static_cast<GLint>(base));
  CHECK(mode == GL_COMPILE);
  CHECK(pixelAt(5, 5) == kBlack);
  glGetIntegerv(GL_LIST_INDEX, &index);
  CHECK(index == 0);

  glNewList(base + 1, GL_COMPILE_AND_EXECUTE);
  rect(16, 0, 32, 16, kGreen);
  glEndList();
  CHECK(pixelAt(20, 5) == kGreen);

  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(base);
  glCallList(base + 1);
  CHECK(pixelAt(5, 5) == kRed);
  CHECK(pixelAt(20, 5) == kGreen);

  // The list holds the transformations it was given, applied to the matrix current when it runs.
  glClear(GL_COLOR_BUFFER_BIT);
  glTranslatef(0, 16, 0);
  glCallList(base);
  CHECK(pixelAt(5, 5) == kBlack);
  CHECK(pixelAt(5, 20) == kRed);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline lists: nested lists, the nesting limit, and replacement at glEndList") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  const GLuint inner = glGenLists(3);
  const GLuint outer = inner + 1, self = inner + 2;
  glNewList(inner, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glEndList();
  glNewList(outer, GL_COMPILE);
  glCallList(inner);
  glCallList(inner);
  glEndList();

  glCallList(outer);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[12] == 2.0f);

  // A list that calls itself runs GL_MAX_LIST_NESTING levels deep and stops.
  glLoadIdentity();
  glNewList(self, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(self);  // calls the old (empty) list while compiling; itself once replaced
  glEndList();
  glCallList(self);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  GLint nesting = 0;
  glGetIntegerv(GL_MAX_LIST_NESTING, &nesting);
  CHECK(m[12] == static_cast<float>(nesting));
  CHECK(glGetError() == GL_NO_ERROR);

  // Calling an undefined list does nothing.
  glLoadIdentity();
  glCallList(999);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[12] == 0.0f);
}

TEST_CASE("pipeline lists: glCallLists with every name type, offset by glListBase") {
  ScopedContext context(32, 32);
  const GLuint base = glGenLists(300);
  REQUIRE(base != 0);
  // List base + k translates x by k.
  for (GLuint k = 0; k < 300; ++k) {
    glNewList(base + k, GL_COMPILE);
    glTranslatef(static_cast<float>(k), 0, 0);
    glEndList();
  }
  glListBase(base);
  const auto sumOf = [](GLsizei n, GLenum type, const void* names) {
    glLoadIdentity();
    glCallLists(n, type, names);
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    return m[12];
  };
  const GLbyte bytes[3] = {1, 2, 3};
  const GLubyte ubytes[3] = {1, 2, 200};
  const GLshort shorts[2] = {5, 7};
  const GLushort ushorts[2] = {250, 9};
  const GLint ints[2] = {11, 13};
  const GLuint uints[2] = {17, 19};
  const GLfloat floats[2] = {23.0f, 29.0f};
  const GLubyte twoBytes[4] = {0, 1, 1, 0};            // 1 and 256
  const GLubyte threeBytes[3] = {0, 1, 3};            // 259
  const GLubyte fourBytes[4] = {0, 0, 1, 2};          // 258
  CHECK(sumOf(3, GL_BYTE, bytes) == 6.0f);
  CHECK(sumOf(3, GL_UNSIGNED_BYTE, ubytes) == 203.0f);
  CHECK(sumOf(2, GL_SHORT, shorts) == 12.0f);
  CHECK(sumOf(2, GL_UNSIGNED_SHORT, ushorts) == 259.0f);
  CHECK(sumOf(2, GL_INT, ints) == 24.0f);
  CHECK(sumOf(2, GL_UNSIGNED_INT, uints) == 36.0f);
  CHECK(sumOf(2, GL_FLOAT, floats) == 52.0f);
  CHECK(sumOf(2, GL_2_BYTES, twoBytes) == 257.0f);
  CHECK(sumOf(1, GL_3_BYTES, threeBytes) == 259.0f);
  CHECK(sumOf(1, GL_4_BYTES, fourBytes) == 258.0f);
  GLint listBase = 0;
  glGetIntegerv(GL_LIST_BASE, &listBase);
  CHECK(listBase == static_cast<GLint>(base));

  // Compiled glCallLists keeps the names and uses the list base of when it runs.
  const GLuint caller = glGenLists(1);
  const GLuint names[2] = {1, 2};
  glNewList(caller, GL_COMPILE);
  glCallLists(2, GL_UNSIGNED_INT, names);
  glEndList();
  glListBase(base + 10);
  glLoadIdentity();
  glCallList(caller);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[12] == 23.0f);  // lists 11 and 12
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline lists: deleted lists do nothing and their names are free again") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  const GLuint first = glGenLists(3);
  for (GLuint k = 0; k < 3; ++k) {
    glNewList(first + k, GL_COMPILE);
    rect(0, 0, 32, 32, kBlue);
    glEndList();
  }
  glDeleteLists(first, 2);
  CHECK(glIsList(first) == GL_FALSE);
  CHECK(glIsList(first + 1) == GL_FALSE);
  CHECK(glIsList(first + 2) == GL_TRUE);
  glCallList(first);
  CHECK(pixelAt(10, 10) == kBlack);
  glCallList(first + 2);
  CHECK(pixelAt(10, 10) == kBlue);
  CHECK(glGenLists(2) == first);  // the lowest free range
  glDeleteLists(first + 100, 5);  // unused names: no error
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline lists: commands that are not compiled run at once; errors appear on execution") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);  // executed now, not compiled
  glEnableClientState(GL_NORMAL_ARRAY);
  const GLuint other = glGenLists(1);
  glEnable(0x1234);                     // compiled: the error comes when the list runs
  GLint alignment = 0;
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  glEndList();
  CHECK(alignment == 2);
  CHECK(other != 0);
  CHECK(glIsEnabled(GL_NORMAL_ARRAY) == GL_TRUE);
  CHECK(glGetError() == GL_NO_ERROR);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glCallList(list);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  CHECK(alignment == 4);
  glDisableClientState(GL_NORMAL_ARRAY);
}

TEST_CASE("pipeline lists: vertex array draws are read when compiled") {
  ScopedContext context(32, 32);
  glass::test::pixelProjection(32, 32);
  GLfloat vertices[8] = {0, 0, 16, 0, 16, 16, 0, 16};
  GLubyte colors[16] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  glNewList(list + 1, GL_COMPILE);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) glArrayElement(i);
  glEnd();
  glEndList();
  CHECK(pixelAt(5, 5) == kBlack);  // GL_COMPILE drew nothing

  // Changing the arrays and disabling them does not change the lists.
  for (GLfloat& v : vertices) v += 16;
  std::memset(colors, 0, sizeof colors);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glCallList(list);
  CHECK(pixelAt(5, 5) == kRed);
  CHECK(pixelAt(20, 20) == kBlack);
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(list + 1);
  CHECK(pixelAt(5, 5) == kRed);
  CHECK(glGetError() == GL_NO_ERROR);
}
