// GLASS_TRACE_VERTEX on small programs: every stage's value of the traced vertex, computed here by
// hand from the transforms, the viewport and the lighting equation.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cstdlib>
#include <string>

#include "core/context.h"
#include "pipeline_test_support.h"
#include "teaching/vertex_trace.h"

namespace {

// GLASS_TRACE_VERTEX for the contexts created while the object lives.
struct ScopedTrace : glass::test::ScopedEnvironment {
  explicit ScopedTrace(const char* value) : ScopedEnvironment("GLASS_TRACE_VERTEX", value) {}
};

std::string report() { return glass::gl::vertexTraceReport(*glass::gl::currentContext()); }

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// glOrtho(0, 4, 0, 2, -1, 1) on a 40 x 20 window, then glTranslatef(1, 0, 0).
void orthoScene() {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0.0, 4.0, 0.0, 2.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1.0f, 0.0f, 0.0f);
}

}  // namespace

TEST_CASE("GLASS_TRACE_VERTEX follows a lit vertex through every stage") {
  ScopedTrace trace("1");
  glass::test::ScopedContext context(40, 20);
  orthoScene();
  // A directional light along +z with diffuse (1, 1, 1), a material with diffuse (0.5, 0.25, 1)
  // and no ambient anywhere: the colour is n.L d_m d_l = (0.5, 0.25, 1) with n.L = 1.
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat direction[] = {0.0f, 0.0f, 1.0f, 0.0f}, none[] = {0.0f, 0.0f, 0.0f, 1.0f};
  const GLfloat diffuse[] = {0.5f, 0.25f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, direction);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, none);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glBegin(GL_POINTS);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glVertex2f(0.0f, 0.0f);
  glVertex2f(1.0f, 1.0f);  // vertex 1
  glEnd();
  const std::string text = report();
  CAPTURE(text);
  CHECK(has(text, "glass trace: vertex 1 of frame 0\n"));
  CHECK(has(text, "  object  (   1.000000,    1.000000,    0.000000,    1.000000)   as given"));
  // eye = translate (1, 0, 0) x object
  CHECK(has(text, "  eye     (   2.000000,    1.000000,    0.000000,    1.000000)   = MODELVIEW x object"));
  // clip: x_c = 2 x / (4 - 0) - 1 = 0, y_c = 2 y / 2 - 1 = 0, z_c = -z = 0
  const bool clipAtOrigin = has(text, "  clip    (   0.000000,    0.000000,   -0.000000,    1.000000)") ||
                            has(text, "  clip    (   0.000000,    0.000000,    0.000000,    1.000000)");
  CHECK(clipAtOrigin);
  CHECK(has(text, "  ndc     (   0.000000,    0.000000,"));
  // window: x_w = (0 + 1) 40 / 2 = 20, y_w = (0 + 1) 20 / 2 = 10, z_w = 0.5
  CHECK(has(text, "  window  (  20.000000,   10.000000,    0.500000)"));
  CHECK(has(text, "inside the view volume"));
  CHECK(has(text, "          (   0.000000,    0.000000,    1.000000)                eye space"));
  CHECK(has(text, "    light 0: att 1.000000, spot 1.000000, n.L 1.000000"));
  CHECK(has(text, "      diffuse           (   0.500000,    0.250000,    1.000000)"));
  CHECK(has(text, "      ambient           (   0.000000,    0.000000,    0.000000)"));
  CHECK(has(text, "  colour  (   0.500000,    0.250000,    1.000000,    1.000000)   lit per vertex"));
}

TEST_CASE("GLASS_TRACE_VERTEX: clipping, texture coordinates, glDrawArrays, a later frame") {
  SUBCASE("a vertex right of the view volume, in glDrawArrays, with a texture matrix") {
    ScopedTrace trace("2");
    glass::test::ScopedContext context(40, 20);
    orthoScene();
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    const unsigned char texel[4] = {255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25f, 0.5f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat positions[] = {0.0f, 0.0f, 1.0f, 0.0f, 4.0f, 1.0f};  // vertex 2: eye x 5
    const GLfloat coordinates[] = {0.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.25f};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, positions);
    glTexCoordPointer(2, GL_FLOAT, 0, coordinates);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const std::string text = report();
    CAPTURE(text);
    // clip x = 2 * 5 / 4 - 1 = 1.5 > w = 1
    CHECK(has(text, "  clip    (   1.500000,    0.000000,"));
    CHECK(has(text, "outside right (x > w)"));
    CHECK(has(text, "    as given            (   0.500000,    0.250000,    0.000000,    1.000000)"));
    CHECK(has(text, "after texgen and the texture matrix (   0.750000,    0.750000,    0.000000,    1.000000)"));
    CHECK(has(text, "as given; lighting off"));
  }
  SUBCASE("vertex 0 of frame 1") {
    ScopedTrace trace("0@1");
    glass::test::ScopedContext context(40, 20);
    orthoScene();
    glBegin(GL_POINTS);
    glVertex2f(0.5f, 0.5f);
    glEnd();
    glassGetColorBuffer(context.get());  // the end of frame 0
    CHECK(report().empty());
    glBegin(GL_POINTS);
    glVertex2f(0.25f, 0.75f);
    glEnd();
    CHECK(has(report(), "glass trace: vertex 0 of frame 1\n"));
    CHECK(has(report(), "  object  (   0.250000,    0.750000,    0.000000,    1.000000)"));
  }
  SUBCASE("a vertex the frame never reaches") {
    ScopedTrace trace("5");
    glass::test::ScopedContext context(40, 20);
    glBegin(GL_LINES);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(0.5f, 0.5f);
    glEnd();
    glassGetColorBuffer(context.get());
    CHECK(report() == "glass trace: vertex 5 of frame 0 was not reached: the frame had 2 vertices\n");
  }
  SUBCASE("a value that is not a vertex number") {
    ScopedTrace trace("first");
    glass::test::ScopedContext context(40, 20);
    CHECK(glass::gl::vertexTraceFor(*glass::gl::currentContext()) == nullptr);
  }
}
