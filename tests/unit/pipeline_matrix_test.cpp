// Matrix stacks, the matrix commands and GLU's matrix functions, checked against GLM.
#include <GL/gl.h>
#include <GL/glu.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

glm::mat4 currentMatrix(GLenum pname) {
  glm::mat4 m;
  glGetFloatv(pname, glm::value_ptr(m));  // both column-major
  return m;
}

// Equal within float rounding, relative to the size of the entries.
void checkClose(const glm::mat4& actual, const glm::mat4& expected, float tolerance = 2e-6f) {
  float scale = 1.0f;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) scale = std::max(scale, std::fabs(expected[c][r]));
  }
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      INFO("column ", c, " row ", r);
      CHECK(std::fabs(actual[c][r] - expected[c][r]) <= tolerance * scale);
    }
  }
}

}  // namespace

TEST_CASE("pipeline: matrix commands compose as GLM's transforms") {
  ScopedContext context;
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glm::mat4 expected(1.0f);

  glTranslatef(1.5f, -2.0f, 3.25f);
  expected = glm::translate(expected, glm::vec3(1.5f, -2.0f, 3.25f));
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), expected);

  glRotatef(37.0f, 1.0f, 2.0f, -0.5f);  // the axis is normalized, as GLM does
  expected = glm::rotate(expected, glm::radians(37.0f), glm::vec3(1.0f, 2.0f, -0.5f));
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), expected);

  glScalef(2.0f, 0.5f, -1.0f);
  expected = glm::scale(expected, glm::vec3(2.0f, 0.5f, -1.0f));
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), expected);

  glRotated(-90.0, 0.0, 0.0, 3.0);
  expected = glm::rotate(expected, glm::radians(-90.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), expected);

  const glm::mat4 extra = glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(0, 1, 0));
  glMultMatrixf(glm::value_ptr(extra));
  expected = expected * extra;
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), expected);

  const glm::dmat4 loaded = glm::translate(glm::dmat4(1.0), glm::dvec3(4.0, 5.0, 6.0));
  glLoadMatrixd(glm::value_ptr(loaded));
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), glm::mat4(loaded));
}

TEST_CASE("pipeline: rotations about a coordinate axis keep their unit entry exact") {
  ScopedContext context;
  glLoadIdentity();
  glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  CHECK(m[10] == 1.0f);
  CHECK(m[4] == -1.0f);  // x' = -y
  CHECK(m[1] == 1.0f);
}

TEST_CASE("pipeline: glOrtho, glFrustum and the GLU projections match GLM") {
  ScopedContext context;
  glMatrixMode(GL_PROJECTION);

  glLoadIdentity();
  glOrtho(-2.0, 3.0, -1.0, 4.0, 0.5, 20.0);
  checkClose(currentMatrix(GL_PROJECTION_MATRIX), glm::ortho(-2.0f, 3.0f, -1.0f, 4.0f, 0.5f, 20.0f));

  glLoadIdentity();
  glFrustum(-1.0, 1.5, -0.75, 1.0, 1.0, 50.0);
  checkClose(currentMatrix(GL_PROJECTION_MATRIX), glm::frustum(-1.0f, 1.5f, -0.75f, 1.0f, 1.0f, 50.0f));

  glLoadIdentity();
  gluPerspective(60.0, 4.0 / 3.0, 0.1, 100.0);
  checkClose(currentMatrix(GL_PROJECTION_MATRIX),
             glm::perspective(glm::radians(60.0f), 4.0f / 3.0f, 0.1f, 100.0f));

  glLoadIdentity();
  gluOrtho2D(0.0, 640.0, 0.0, 480.0);
  checkClose(currentMatrix(GL_PROJECTION_MATRIX), glm::ortho(0.0f, 640.0f, 0.0f, 480.0f, -1.0f, 1.0f));

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(3.0, 4.0, 5.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0);
  checkClose(currentMatrix(GL_MODELVIEW_MATRIX),
             glm::lookAt(glm::vec3(3, 4, 5), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)));
}

TEST_CASE("pipeline: each matrix mode has its own stack") {
  ScopedContext context;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  checkClose(currentMatrix(GL_MODELVIEW_MATRIX), glm::mat4(1.0f));
  checkClose(currentMatrix(GL_PROJECTION_MATRIX), glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)));
  checkClose(currentMatrix(GL_TEXTURE_MATRIX), glm::scale(glm::mat4(1.0f), glm::vec3(2, 2, 2)));

  GLint mode = 0;
  glGetIntegerv(GL_MATRIX_MODE, &mode);
  CHECK(mode == GL_MODELVIEW);

  // The transpose queries return the same matrices, row-major.
  GLfloat m[16], t[16];
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  glGetFloatv(GL_TRANSPOSE_PROJECTION_MATRIX, t);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) CHECK(t[r * 4 + c] == m[c * 4 + r]);
  }
}

TEST_CASE("pipeline: push and pop restore matrices, and overflow and underflow are errors") {
  ScopedContext context;
  struct StackCase {
    GLenum mode, depthName, maxName;
    int minimumDepth;
  };
  const StackCase cases[] = {{GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH, 32},
                             {GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, 2},
                             {GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH, 2}};
  for (const StackCase& s : cases) {
    CAPTURE(s.mode);
    glMatrixMode(s.mode);
    glLoadIdentity();
    GLint maxDepth = 0, depth = 0;
    glGetIntegerv(s.maxName, &maxDepth);
    CHECK(maxDepth >= s.minimumDepth);

    // Push to the limit, each level with its own translation.
    for (int level = 1; level < maxDepth; ++level) {
      glPushMatrix();
      glTranslatef(1.0f, 0.0f, 0.0f);
    }
    CHECK(glGetError() == GL_NO_ERROR);
    glGetIntegerv(s.depthName, &depth);
    CHECK(depth == maxDepth);

    const glm::mat4 top = currentMatrix(s.mode == GL_MODELVIEW    ? GL_MODELVIEW_MATRIX
                                        : s.mode == GL_PROJECTION ? GL_PROJECTION_MATRIX
                                                                  : GL_TEXTURE_MATRIX);
    glPushMatrix();
    CHECK(glGetError() == GL_STACK_OVERFLOW);
    glGetIntegerv(s.depthName, &depth);
    CHECK(depth == maxDepth);

    for (int level = 1; level < maxDepth; ++level) glPopMatrix();
    CHECK(glGetError() == GL_NO_ERROR);
    glGetIntegerv(s.depthName, &depth);
    CHECK(depth == 1);
    CHECK(top[3][0] == doctest::Approx(maxDepth - 1));

    glPopMatrix();
    CHECK(glGetError() == GL_STACK_UNDERFLOW);
    glGetIntegerv(s.depthName, &depth);
    CHECK(depth == 1);
  }
}

TEST_CASE("pipeline: gluProject and gluUnProject are inverse to each other and agree with GLM") {
  const glm::dmat4 model = glm::lookAt(glm::dvec3(1, 2, 6), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
  const glm::dmat4 proj = glm::perspective(glm::radians(45.0), 1.5, 0.5, 30.0);
  const GLint viewport[4] = {10, 20, 300, 200};
  const glm::dvec3 object(0.3, -0.7, 1.1);

  GLdouble wx, wy, wz;
  REQUIRE(gluProject(object.x, object.y, object.z, glm::value_ptr(model), glm::value_ptr(proj),
                     viewport, &wx, &wy, &wz) == GL_TRUE);
  const glm::dvec3 expected = glm::project(object, model, proj, glm::dvec4(10, 20, 300, 200));
  CHECK(wx == doctest::Approx(expected.x).epsilon(1e-12));
  CHECK(wy == doctest::Approx(expected.y).epsilon(1e-12));
  CHECK(wz == doctest::Approx(expected.z).epsilon(1e-12));

  GLdouble ox, oy, oz;
  REQUIRE(gluUnProject(wx, wy, wz, glm::value_ptr(model), glm::value_ptr(proj), viewport, &ox, &oy,
                       &oz) == GL_TRUE);
  CHECK(ox == doctest::Approx(object.x).epsilon(1e-9));
  CHECK(oy == doctest::Approx(object.y).epsilon(1e-9));
  CHECK(oz == doctest::Approx(object.z).epsilon(1e-9));

  // A singular combined matrix cannot be inverted.
  const GLdouble zero[16] = {};
  CHECK(gluUnProject(1, 1, 0.5, zero, glm::value_ptr(proj), viewport, &ox, &oy, &oz) == GL_FALSE);
}

TEST_CASE("pipeline: gluErrorString names GL and GLU errors") {
  CHECK(std::string(reinterpret_cast<const char*>(gluErrorString(GL_STACK_OVERFLOW))) == "stack overflow");
  CHECK(std::string(reinterpret_cast<const char*>(gluErrorString(GL_INVALID_ENUM))) == "invalid enumerant");
  CHECK(std::string(reinterpret_cast<const char*>(gluErrorString(GLU_INVALID_VALUE))) == "invalid value");
  CHECK(gluErrorString(0x1234) == nullptr);
}
