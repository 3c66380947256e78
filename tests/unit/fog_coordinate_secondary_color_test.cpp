// OpenGL 1.4's vertex attributes and point parameters: glFogCoord with
// GL_FOG_COORDINATE_SOURCE, glSecondaryColor with GL_COLOR_SUM, their arrays, lists and errors,
// and glPointParameter's state.
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

void linearWhiteFog() {
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  const GLfloat white[4] = {1, 1, 1, 1};
  glFogfv(GL_FOG_COLOR, white);
}

}  // namespace

TEST_CASE("glFogCoord is fog's distance with GL_FOG_COORDINATE as the source; -c fogs like c") {
  ScopedContext context(8, 8);
  CHECK(integerState(GL_FOG_COORDINATE_SOURCE) == GL_FRAGMENT_DEPTH);
  linearWhiteFog();
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(integerState(GL_FOG_COORDINATE_SOURCE) == GL_FOG_COORDINATE);
  glColor3f(1, 0, 0);
  glFogCoordf(5.0f);  // f = (10 - 5) / 10 = 1/2
  glRectf(-1, -1, 0, 1);
  glFogCoordd(-5.0);
  glRectf(0, -1, 1, 1);
  CHECK(pixelAt(2, 4) == Rgba{255, 128, 128, 255});
  CHECK(pixelAt(6, 4) == Rgba{255, 128, 128, 255});
  GLfloat c = 0;
  glGetFloatv(GL_CURRENT_FOG_COORDINATE, &c);
  CHECK(c == -5.0f);

  // Per vertex: interpolated between the vertices' coordinates.
  glBegin(GL_QUADS);
  glFogCoordf(0.0f);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glFogCoordf(10.0f);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  CHECK(pixelAt(4, 0).g < 30);
  CHECK(pixelAt(4, 7).g > 225);

  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_MODE);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("Fog coordinate arrays, and glFogCoord in display lists") {
  ScopedContext context(8, 8);
  linearWhiteFog();
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  const GLfloat quad[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLdouble fog[4] = {5, 5, 5, 5};
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glFogCoordPointer(GL_DOUBLE, 0, fog);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_FOG_COORDINATE_ARRAY);
  CHECK(glIsEnabled(GL_FOG_COORDINATE_ARRAY) == GL_TRUE);
  CHECK(integerState(GL_FOG_COORDINATE_ARRAY_TYPE) == GL_DOUBLE);
  GLvoid* pointer = nullptr;
  glGetPointerv(GL_FOG_COORDINATE_ARRAY_POINTER, &pointer);
  CHECK(pointer == fog);
  glColor3f(0, 0, 1);
  glDrawArrays(GL_QUADS, 0, 4);
  CHECK(pixelAt(4, 4) == Rgba{128, 128, 255, 255});
  glFogCoordPointer(GL_INT, 0, fog);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glFogCoordPointer(GL_FLOAT, -4, fog);
  CHECK(glGetError() == GL_INVALID_VALUE);

  glNewList(1, GL_COMPILE);
  glFogCoordf(2.0f);
  glEndList();
  GLfloat c = 0;
  glGetFloatv(GL_CURRENT_FOG_COORDINATE, &c);
  CHECK(c == 5.0f);  // the array's last element
  glCallList(1);
  glGetFloatv(GL_CURRENT_FOG_COORDINATE, &c);
  CHECK(c == 2.0f);
}

TEST_CASE("glSecondaryColor: current value, conversions, array state, GL_COLOR_SUM enable") {
  ScopedContext context;
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  CHECK(c[0] == 0.0f);
  CHECK(c[3] == 1.0f);
  glSecondaryColor3ub(255, 0, 51);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  CHECK(c[0] == 1.0f);
  CHECK(c[2] == doctest::Approx(0.2f));
  const GLshort s[3] = {32767, 0, 0};
  glSecondaryColor3sv(s);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  CHECK(c[0] == 1.0f);
  CHECK(c[1] == doctest::Approx(1.0f / 65535.0f));

  CHECK(glIsEnabled(GL_COLOR_SUM) == GL_FALSE);
  glEnable(GL_COLOR_SUM);
  CHECK(glIsEnabled(GL_COLOR_SUM) == GL_TRUE);
  glPushAttrib(GL_FOG_BIT);
  glDisable(GL_COLOR_SUM);
  glPopAttrib();
  CHECK(glIsEnabled(GL_COLOR_SUM) == GL_TRUE);

  const GLubyte colors[9] = {};
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 3, colors);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(integerState(GL_SECONDARY_COLOR_ARRAY_SIZE) == 3);
  CHECK(integerState(GL_SECONDARY_COLOR_ARRAY_STRIDE) == 3);
  glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glSecondaryColorPointer(3, GL_BITMAP, 0, colors);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("glPointParameter: defaults, values, errors, attribute stack") {
  ScopedContext context;
  GLfloat v[3] = {};
  glGetFloatv(GL_POINT_SIZE_MIN, v);
  CHECK(v[0] == 0.0f);
  glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, v);
  CHECK(v[0] == 1.0f);
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  CHECK(v[0] == 1.0f);
  CHECK(v[1] == 0.0f);
  const GLfloat attenuation[3] = {0.0f, 0.5f, 0.25f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glPointParameteri(GL_POINT_SIZE_MAX, 12);
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  CHECK(v[2] == 0.25f);
  glGetFloatv(GL_POINT_SIZE_MAX, v);
  CHECK(v[0] == 12.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glPointParameterf(GL_POINT_SIZE, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glPushAttrib(GL_POINT_BIT);
  glPointParameterf(GL_POINT_SIZE_MAX, 3.0f);
  glPopAttrib();
  glGetFloatv(GL_POINT_SIZE_MAX, v);
  CHECK(v[0] == 12.0f);
}

// Spec 3.9 clamps the colour sum to [0, 1] before fog (3.10) blends it with the fog colour.
// Primary (0.8, 0.5, 0.2) + secondary (0.5, 0.2, 0.1) = (1.3, 0.7, 0.3), clamped (1, 0.7, 0.3);
// f = 1/2 towards (0.2, 0.4, 0.6) gives (0.6, 0.55, 0.45) = (153, 140, 115). Fogging the
// unclamped sum would give red 0.75 (191). Where no sum exceeds 1, the order shows instead:
// (0.6, 0.3, 0.2) + (0.3, 0.5, 0.4) fogged is (0.55, 0.6, 0.6) = (140, 153, 153), where fogging
// the primary and adding the secondary after would give (0.7, 0.85, 0.8).
TEST_CASE("Colour sum is clamped, then fogged") {
  ScopedContext context(8, 8);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  const GLfloat fogColor[4] = {0.2f, 0.4f, 0.6f, 1.0f};
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glFogCoordf(5.0f);
  glEnable(GL_COLOR_SUM);
  glColor3f(0.8f, 0.5f, 0.2f);
  glSecondaryColor3f(0.5f, 0.2f, 0.1f);
  glRectf(-1, -1, 0, 1);
  glColor3f(0.6f, 0.3f, 0.2f);
  glSecondaryColor3f(0.3f, 0.5f, 0.4f);
  glRectf(0, -1, 1, 1);
  CHECK(pixelAt(2, 4) == Rgba{153, 140, 115, 255});
  CHECK(pixelAt(6, 4) == Rgba{140, 153, 153, 255});
}
