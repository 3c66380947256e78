// The GL errors the specification lists for each command the pipeline implements, the sticky
// error flag, commands between glBegin and glEnd, and GL calls without a current context.
#include <GL/gl.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <functional>
#include <string>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

struct ErrorCase {
  const char* call;
  std::function<void()> run;
  GLenum expected;
};

void checkErrors(const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& c : cases) {
    INFO(c.call);
    REQUIRE(glGetError() == GL_NO_ERROR);
    c.run();
    CHECK(glGetError() == c.expected);
    CHECK(glGetError() == GL_NO_ERROR);  // reading the error cleared it
  }
}

}  // namespace

TEST_CASE("pipeline errors: state, matrices and viewport") {
  ScopedContext context;
  GLint value[16];
  checkErrors({
      {"glEnable(bad)", [] { glEnable(0x1234); }, GL_INVALID_ENUM},
      {"glDisable(bad)", [] { glDisable(GL_TRIANGLES + 0x40); }, GL_INVALID_ENUM},
      {"glEnable(GL_VERTEX_ARRAY)", [] { glEnable(GL_VERTEX_ARRAY); }, GL_INVALID_ENUM},
      {"glIsEnabled(bad)", [] { CHECK(glIsEnabled(0x1234) == GL_FALSE); }, GL_INVALID_ENUM},
      {"glGetIntegerv(bad)", [&] { glGetIntegerv(0x1234, value); }, GL_INVALID_ENUM},
      {"glGetString(bad)", [] { CHECK(glGetString(0x1234) == nullptr); }, GL_INVALID_ENUM},
      {"glHint(bad target)", [] { glHint(0x1234, GL_NICEST); }, GL_INVALID_ENUM},
      {"glHint(bad mode)", [] { glHint(GL_FOG_HINT, GL_LINE); }, GL_INVALID_ENUM},
      {"glMatrixMode(GL_DEPTH)", [] { glMatrixMode(GL_DEPTH); }, GL_INVALID_ENUM},
      {"glOrtho(l == r)", [] { glOrtho(1, 1, 0, 1, 0, 1); }, GL_INVALID_VALUE},
      {"glOrtho(b == t)", [] { glOrtho(0, 1, 2, 2, 0, 1); }, GL_INVALID_VALUE},
      {"glOrtho(n == f)", [] { glOrtho(0, 1, 0, 1, 3, 3); }, GL_INVALID_VALUE},
      {"glFrustum(n <= 0)", [] { glFrustum(-1, 1, -1, 1, 0, 10); }, GL_INVALID_VALUE},
      {"glFrustum(f <= 0)", [] { glFrustum(-1, 1, -1, 1, 1, -10); }, GL_INVALID_VALUE},
      {"glFrustum(l == r)", [] { glFrustum(1, 1, -1, 1, 1, 10); }, GL_INVALID_VALUE},
      {"glFrustum(n == f)", [] { glFrustum(-1, 1, -1, 1, 2, 2); }, GL_INVALID_VALUE},
      {"glViewport(width < 0)", [] { glViewport(0, 0, -1, 10); }, GL_INVALID_VALUE},
      {"glViewport(height < 0)", [] { glViewport(0, 0, 10, -1); }, GL_INVALID_VALUE},
      {"glClipPlane(GL_CLIP_PLANE0 + 6)",
       [] { const GLdouble p[4] = {1, 0, 0, 0}; glClipPlane(GL_CLIP_PLANE0 + 6, p); }, GL_INVALID_ENUM},
      {"glGetClipPlane(bad)", [] { GLdouble p[4]; glGetClipPlane(GL_LIGHT0, p); }, GL_INVALID_ENUM},
  });
  // A failed command changes nothing.
  glGetIntegerv(GL_VIEWPORT, value);
  CHECK(value[2] == 64);
}

TEST_CASE("pipeline errors: the first error is kept until glGetError") {
  ScopedContext context;
  glEnable(0x1234);         // GL_INVALID_ENUM
  glPointSize(-1.0f);       // GL_INVALID_VALUE, dropped
  glPopMatrix();            // GL_STACK_UNDERFLOW, dropped
  CHECK(glGetError() == GL_INVALID_ENUM);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline errors: primitives, arrays and rasterization state") {
  ScopedContext context;
  GLfloat data[16] = {};
  GLubyte indices[3] = {0, 1, 2};
  checkErrors({
      {"glBegin(bad)", [] { glBegin(GL_POLYGON + 1); }, GL_INVALID_ENUM},
      {"glEnd without glBegin", [] { glEnd(); }, GL_INVALID_OPERATION},
      {"glBegin twice", [] { glBegin(GL_POINTS); glBegin(GL_LINES); glEnd(); }, GL_INVALID_OPERATION},
      {"glEnableClientState(bad)", [] { glEnableClientState(GL_LIGHTING); }, GL_INVALID_ENUM},
      {"glDisableClientState(bad)", [] { glDisableClientState(GL_TEXTURE_2D); }, GL_INVALID_ENUM},
      {"glVertexPointer(size 1)", [&] { glVertexPointer(1, GL_FLOAT, 0, data); }, GL_INVALID_VALUE},
      {"glVertexPointer(size 5)", [&] { glVertexPointer(5, GL_FLOAT, 0, data); }, GL_INVALID_VALUE},
      {"glVertexPointer(stride < 0)", [&] { glVertexPointer(3, GL_FLOAT, -4, data); }, GL_INVALID_VALUE},
      {"glVertexPointer(GL_BYTE)", [&] { glVertexPointer(3, GL_BYTE, 0, data); }, GL_INVALID_ENUM},
      {"glColorPointer(size 2)", [&] { glColorPointer(2, GL_FLOAT, 0, data); }, GL_INVALID_VALUE},
      {"glColorPointer(bad type)", [&] { glColorPointer(4, GL_2_BYTES, 0, data); }, GL_INVALID_ENUM},
      {"glNormalPointer(GL_UNSIGNED_BYTE)", [&] { glNormalPointer(GL_UNSIGNED_BYTE, 0, data); }, GL_INVALID_ENUM},
      {"glNormalPointer(stride < 0)", [&] { glNormalPointer(GL_FLOAT, -1, data); }, GL_INVALID_VALUE},
      {"glTexCoordPointer(size 0)", [&] { glTexCoordPointer(0, GL_FLOAT, 0, data); }, GL_INVALID_VALUE},
      {"glTexCoordPointer(GL_UNSIGNED_BYTE)", [&] { glTexCoordPointer(2, GL_UNSIGNED_BYTE, 0, data); }, GL_INVALID_ENUM},
      {"glEdgeFlagPointer(stride < 0)", [&] { glEdgeFlagPointer(-1, data); }, GL_INVALID_VALUE},
      {"glGetPointerv(bad)", [] { GLvoid* p; glGetPointerv(GL_VERTEX_ARRAY, &p); }, GL_INVALID_ENUM},
      {"glDrawArrays(bad mode)", [] { glDrawArrays(0x20, 0, 3); }, GL_INVALID_ENUM},
      {"glDrawArrays(count < 0)", [] { glDrawArrays(GL_TRIANGLES, 0, -1); }, GL_INVALID_VALUE},
      {"glDrawElements(bad mode)", [&] { glDrawElements(0x20, 3, GL_UNSIGNED_BYTE, indices); }, GL_INVALID_ENUM},
      {"glDrawElements(GL_FLOAT)", [&] { glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, indices); }, GL_INVALID_ENUM},
      {"glDrawElements(count < 0)", [&] { glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_BYTE, indices); }, GL_INVALID_VALUE},
      {"glPointSize(0)", [] { glPointSize(0.0f); }, GL_INVALID_VALUE},
      {"glLineWidth(-1)", [] { glLineWidth(-1.0f); }, GL_INVALID_VALUE},
      {"glShadeModel(bad)", [] { glShadeModel(GL_FILL); }, GL_INVALID_ENUM},
      {"glPolygonMode(bad face)", [] { glPolygonMode(GL_LEFT, GL_LINE); }, GL_INVALID_ENUM},
      {"glPolygonMode(bad mode)", [] { glPolygonMode(GL_FRONT, GL_LINES); }, GL_INVALID_ENUM},
      {"glCullFace(bad)", [] { glCullFace(GL_CW); }, GL_INVALID_ENUM},
      {"glFrontFace(bad)", [] { glFrontFace(GL_FRONT); }, GL_INVALID_ENUM},
  });
}

TEST_CASE("pipeline errors: fragment operations, clear and pixels") {
  ScopedContext context;
  GLubyte pixels[64 * 4];
  checkErrors({
      {"glDepthFunc(bad)", [] { glDepthFunc(GL_ZERO); }, GL_INVALID_ENUM},
      {"glAlphaFunc(bad)", [] { glAlphaFunc(GL_KEEP, 0.5f); }, GL_INVALID_ENUM},
      {"glStencilFunc(bad)", [] { glStencilFunc(GL_INCR, 1, 0xFF); }, GL_INVALID_ENUM},
      {"glStencilOp(bad fail)", [] { glStencilOp(GL_LESS, GL_KEEP, GL_KEEP); }, GL_INVALID_ENUM},
      {"glStencilOp(bad zfail)", [] { glStencilOp(GL_KEEP, GL_ONE, GL_KEEP); }, GL_INVALID_ENUM},
      {"glStencilOp(bad zpass)", [] { glStencilOp(GL_KEEP, GL_KEEP, GL_AND); }, GL_INVALID_ENUM},
      {"glBlendFunc(bad src)", [] { glBlendFunc(GL_LESS, GL_ONE); }, GL_INVALID_ENUM},
      {"glBlendFunc(SRC_ALPHA_SATURATE as dst)", [] { glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE); }, GL_INVALID_ENUM},
      {"glBlendFuncSeparate(bad)", [] { glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_KEEP); }, GL_INVALID_ENUM},
      {"glBlendEquation(bad)", [] { glBlendEquation(GL_ADD); }, GL_INVALID_ENUM},
      {"glLogicOp(bad)", [] { glLogicOp(GL_ONE); }, GL_INVALID_ENUM},
      {"glScissor(width < 0)", [] { glScissor(0, 0, -1, 1); }, GL_INVALID_VALUE},
      {"glScissor(height < 0)", [] { glScissor(0, 0, 1, -1); }, GL_INVALID_VALUE},
      {"glClear(bad bit)", [] { glClear(GL_COLOR_BUFFER_BIT | 0x2); }, GL_INVALID_VALUE},
      {"glPixelStorei(alignment 3)", [] { glPixelStorei(GL_PACK_ALIGNMENT, 3); }, GL_INVALID_VALUE},
      {"glPixelStorei(row length < 0)", [] { glPixelStorei(GL_UNPACK_ROW_LENGTH, -1); }, GL_INVALID_VALUE},
      {"glPixelStorei(bad)", [] { glPixelStorei(GL_DEPTH_TEST, 1); }, GL_INVALID_ENUM},
      {"glReadPixels(width < 0)", [&] { glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels); }, GL_INVALID_VALUE},
      {"glReadPixels(bad format)", [&] { glReadPixels(0, 0, 1, 1, GL_TRIANGLES, GL_UNSIGNED_BYTE, pixels); }, GL_INVALID_ENUM},
      {"glReadPixels(bad type)", [&] { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_2_BYTES, pixels); }, GL_INVALID_ENUM},
  });
}

TEST_CASE("pipeline errors: display lists") {
  ScopedContext context;
  const GLuint names[2] = {1, 2};
  checkErrors({
      {"glNewList(0)", [] { glNewList(0, GL_COMPILE); }, GL_INVALID_VALUE},
      {"glNewList(bad mode)", [] { glNewList(1, GL_FILL); }, GL_INVALID_ENUM},
      {"glNewList inside glNewList", [] { glNewList(1, GL_COMPILE); glNewList(2, GL_COMPILE); glEndList(); }, GL_INVALID_OPERATION},
      {"glEndList without glNewList", [] { glEndList(); }, GL_INVALID_OPERATION},
      {"glGenLists(-1)", [] { CHECK(glGenLists(-1) == 0u); }, GL_INVALID_VALUE},
      {"glDeleteLists(range < 0)", [] { glDeleteLists(1, -1); }, GL_INVALID_VALUE},
      {"glCallLists(n < 0)", [&] { glCallLists(-1, GL_UNSIGNED_INT, names); }, GL_INVALID_VALUE},
      {"glCallLists(bad type)", [&] { glCallLists(2, GL_DOUBLE, names); }, GL_INVALID_ENUM},
  });
  CHECK(glGenLists(0) == 0u);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline errors: only the listed commands are allowed between glBegin and glEnd") {
  ScopedContext context;
  glass::test::pixelProjection(64, 64);
  GLint value[16];
  GLubyte pixel[4];
  const GLfloat vertices[6] = {0, 0, 10, 0, 0, 10};
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glEnableClientState(GL_VERTEX_ARRAY);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColor3f(1, 0, 0);
  glEndList();

  const std::vector<ErrorCase> forbidden = {
      {"glEnable", [] { glEnable(GL_DEPTH_TEST); }, GL_INVALID_OPERATION},
      {"glIsEnabled", [] { glIsEnabled(GL_DEPTH_TEST); }, GL_INVALID_OPERATION},
      {"glMatrixMode", [] { glMatrixMode(GL_MODELVIEW); }, GL_INVALID_OPERATION},
      {"glLoadIdentity", [] { glLoadIdentity(); }, GL_INVALID_OPERATION},
      {"glPushMatrix", [] { glPushMatrix(); }, GL_INVALID_OPERATION},
      {"glTranslatef", [] { glTranslatef(1, 0, 0); }, GL_INVALID_OPERATION},
      {"glViewport", [] { glViewport(0, 0, 1, 1); }, GL_INVALID_OPERATION},
      {"glDepthRange", [] { glDepthRange(0, 1); }, GL_INVALID_OPERATION},
      {"glGetIntegerv", [&] { glGetIntegerv(GL_VIEWPORT, value); }, GL_INVALID_OPERATION},
      {"glGetString", [] { glGetString(GL_VENDOR); }, GL_INVALID_OPERATION},
      {"glClear", [] { glClear(GL_COLOR_BUFFER_BIT); }, GL_INVALID_OPERATION},
      {"glClearColor", [] { glClearColor(1, 1, 1, 1); }, GL_INVALID_OPERATION},
      {"glDepthFunc", [] { glDepthFunc(GL_LESS); }, GL_INVALID_OPERATION},
      {"glBlendFunc", [] { glBlendFunc(GL_ONE, GL_ONE); }, GL_INVALID_OPERATION},
      {"glPointSize", [] { glPointSize(2); }, GL_INVALID_OPERATION},
      {"glShadeModel", [] { glShadeModel(GL_FLAT); }, GL_INVALID_OPERATION},
      {"glRectf", [] { glRectf(0, 0, 1, 1); }, GL_INVALID_OPERATION},
      {"glDrawArrays", [] { glDrawArrays(GL_TRIANGLES, 0, 3); }, GL_INVALID_OPERATION},
      {"glGenLists", [] { glGenLists(1); }, GL_INVALID_OPERATION},
      {"glNewList", [] { glNewList(50, GL_COMPILE); }, GL_INVALID_OPERATION},
      {"glIsList", [] { glIsList(1); }, GL_INVALID_OPERATION},
      {"glReadPixels", [&] { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel); }, GL_INVALID_OPERATION},
      {"glPixelStorei", [] { glPixelStorei(GL_PACK_ALIGNMENT, 1); }, GL_INVALID_OPERATION},
      {"glFinish", [] { glFinish(); }, GL_INVALID_OPERATION},
      {"glFlush", [] { glFlush(); }, GL_INVALID_OPERATION},
      {"glEnableClientState", [] { glEnableClientState(GL_COLOR_ARRAY); }, GL_INVALID_OPERATION},
      {"glColorPointer", [&] { glColorPointer(3, GL_FLOAT, 0, vertices); }, GL_INVALID_OPERATION},
  };
  for (const ErrorCase& c : forbidden) {
    INFO(c.call);
    glBegin(GL_TRIANGLES);
    c.run();
    glEnd();
    CHECK(glGetError() == c.expected);
    CHECK(glGetError() == GL_NO_ERROR);
  }

  // glGetError itself is not allowed inside either: it reports GL_NO_ERROR and sets the flag.
  glBegin(GL_POINTS);
  CHECK(glGetError() == GL_NO_ERROR);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);

  // The allowed ones.
  glBegin(GL_TRIANGLES);
  glColor4f(1, 1, 1, 1);
  glNormal3f(0, 0, 1);
  glTexCoord2f(0, 0);
  glEdgeFlag(GL_TRUE);
  glVertex2f(1, 1);
  glArrayElement(1);
  glCallList(list);
  glVertex2f(1, 20);
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  glDisableClientState(GL_VERTEX_ARRAY);
}

TEST_CASE("pipeline errors: GL calls without a current context do nothing") {
  glassMakeCurrent(nullptr);
  CHECK(glassGetCurrentContext() == nullptr);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glEnd();
  glEnable(0x1234);
  GLint value = 42;
  glGetIntegerv(GL_VIEWPORT, &value);
  CHECK(value == 42);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(glGetString(GL_VENDOR) == nullptr);
  CHECK(glIsEnabled(GL_DEPTH_TEST) == GL_FALSE);
  CHECK(glGenLists(1) == 0u);
  GLubyte pixel[4] = {9, 9, 9, 9};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  CHECK(pixel[0] == 9);
}
