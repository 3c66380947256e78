// Selection and feedback (spec 5.2, 5.3): glRenderMode, glSelectBuffer and the name stack, hit
// records; glFeedbackBuffer, the five feedback types and the tokens; the errors of both.
#include <GL/gl.h>
#include <GL/glu.h>
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

// Spec 5.2: window z in [0, 1] times 2^32 - 1, rounded.
GLuint scaled(double z) { return static_cast<GLuint>(std::llround(z * 4294967295.0)); }

// Identity matrices: object z maps to window depth (1 + z) / 2, x and y to the 64 x 64 window.
void triangle(float x, float y, float z0, float z1, float z2) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x, y, z0);
  glVertex3f(x + 0.2f, y, z1);
  glVertex3f(x, y + 0.2f, z2);
  glEnd();
}

}  // namespace

TEST_CASE("select: hit records hold the name stack and the depth range of what was hit") {
  ScopedContext context(64, 64);
  GLuint buffer[64] = {};
  glSelectBuffer(64, buffer);
  CHECK(glRenderMode(GL_SELECT) == 0);
  GLint mode = 0;
  glGetIntegerv(GL_RENDER_MODE, &mode);
  CHECK(mode == GL_SELECT);
  glInitNames();
  glPushName(7);
  triangle(0.0f, 0.0f, 0.5f, -0.5f, 0.0f);  // depths 0.75, 0.25, 0.5
  glPushName(8);
  triangle(2.0f, 2.0f, 0.0f, 0.0f, 0.0f);   // outside: no hit
  glLoadName(9);
  triangle(-0.5f, -0.5f, -1.0f, -1.0f, 0.0f);  // depths 0, 0, 0.5
  glBegin(GL_POINTS);
  glVertex3f(0.1f, 0.1f, 1.0f);  // depth 1, same record
  glEnd();
  glPopName();
  glPopName();
  glBegin(GL_LINES);  // no names on the stack
  glVertex3f(-0.9f, 0.9f, 0.6f);
  glVertex3f(0.9f, 0.9f, 0.2f);
  glEnd();
  GLint depth = -1;
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  CHECK(depth == 0);
  CHECK(glRenderMode(GL_RENDER) == 3);

  const GLuint expected[] = {1, scaled(0.25), scaled(0.75), 7,
                             2, 0, 0xFFFFFFFFu, 7, 9,
                             0, scaled(0.6), scaled(0.8)};
  for (size_t i = 0; i < sizeof expected / sizeof expected[0]; ++i) {
    CAPTURE(i);
    // Window depth is computed in float: allow a few units of 2^-32 * 2^8.
    CHECK(std::abs(static_cast<double>(buffer[i]) - static_cast<double>(expected[i])) <= 512.0);
  }
  CHECK(buffer[3] == 7);
  CHECK(buffer[7] == 7);
  CHECK(buffer[8] == 9);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("select: raster positions hit, nothing is drawn, and the name stack ends empty") {
  ScopedContext context(16, 16);
  GLuint buffer[16] = {};
  glSelectBuffer(16, buffer);
  glRenderMode(GL_SELECT);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);  // no effect in selection mode (as in Mesa)
  glPushName(3);
  glRasterPos3f(0.0f, 0.0f, 0.5f);  // window depth 0.75
  glRasterPos3f(5.0f, 0.0f, 0.0f);  // invalid: no hit
  glRectf(-1.0f, -1.0f, 1.0f, 1.0f);  // depth 0.5
  CHECK(glRenderMode(GL_RENDER) == 1);
  CHECK(buffer[0] == 1);
  CHECK(buffer[1] == scaled(0.5));
  CHECK(buffer[2] == scaled(0.75));
  CHECK(buffer[3] == 3);
  CHECK(glass::test::pixelAt(8, 8) == glass::test::Rgba{0, 0, 0, 0});
  GLint depth = -1;
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  CHECK(depth == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("select: culling and clipping decide what hits; gluPickMatrix narrows the volume") {
  ScopedContext context(100, 100);
  GLuint buffer[64] = {};
  glSelectBuffer(64, buffer);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(0);
  glEnable(GL_CULL_FACE);
  glLoadName(1);
  glBegin(GL_TRIANGLES);  // clockwise: culled
  glVertex2f(0.0f, 0.0f);
  glVertex2f(0.0f, 0.5f);
  glVertex2f(0.5f, 0.0f);
  glEnd();
  glDisable(GL_CULL_FACE);

  // A 4 x 4 pixel pick region around window (25, 75): only the square containing it hits.
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  gluPickMatrix(25.0, 75.0, 4.0, 4.0, viewport);
  glMatrixMode(GL_MODELVIEW);
  for (int i = 0; i < 4; ++i) {
    glLoadName(10 + i);
    const float x = (i % 2) - 1.0f, y = (i / 2) - 1.0f;
    glRectf(x + 0.1f, y + 0.1f, x + 0.9f, y + 0.9f);
  }
  CHECK(glRenderMode(GL_RENDER) == 1);
  CHECK(buffer[3] == 12);  // the square at x in [-0.9, -0.1], y in [0.1, 0.9]
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("select: overflow returns -1 and keeps what fits") {
  ScopedContext context(16, 16);
  GLuint buffer[6] = {};
  glSelectBuffer(5, buffer);
  glRenderMode(GL_SELECT);
  glPushName(1);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  glLoadName(2);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  CHECK(glRenderMode(GL_RENDER) == -1);
  CHECK(buffer[3] == 1);
  CHECK(buffer[4] == 1);  // the second record's name count, then no room
  CHECK(buffer[5] == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("select: name stack errors, and commands ignored outside selection mode") {
  ScopedContext context(16, 16);
  glPushName(1);  // ignored in GL_RENDER mode
  glPopName();
  glLoadName(1);
  CHECK(glGetError() == GL_NO_ERROR);
  GLint max = 0;
  glGetIntegerv(GL_MAX_NAME_STACK_DEPTH, &max);
  CHECK(max == 64);

  CHECK(glRenderMode(GL_SELECT) == 0);  // no buffer given yet
  CHECK(glGetError() == GL_INVALID_OPERATION);
  GLint mode = 0;
  glGetIntegerv(GL_RENDER_MODE, &mode);
  CHECK(mode == GL_RENDER);

  GLuint buffer[8];
  glSelectBuffer(8, buffer);
  GLint size = 0;
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &size);
  CHECK(size == 8);
  GLvoid* pointer = nullptr;
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &pointer);
  CHECK(pointer == buffer);
  glRenderMode(GL_SELECT);
  glLoadName(1);
  CHECK(glGetError() == GL_INVALID_OPERATION);  // empty stack
  glPopName();
  CHECK(glGetError() == GL_STACK_UNDERFLOW);
  for (int i = 0; i < max; ++i) glPushName(static_cast<GLuint>(i));
  CHECK(glGetError() == GL_NO_ERROR);
  glPushName(99);
  CHECK(glGetError() == GL_STACK_OVERFLOW);
  glSelectBuffer(8, buffer);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glPushName(1);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glRenderMode(GL_RENDER);
  glSelectBuffer(-1, buffer);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glRenderMode(GL_POINTS);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glRenderMode(GL_RENDER);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("select: name stack commands compile into display lists") {
  ScopedContext context(16, 16);
  GLuint buffer[8] = {};
  glSelectBuffer(8, buffer);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glInitNames();
  glPushName(4);
  glPushName(5);
  glPopName();
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  glEndList();
  glRenderMode(GL_SELECT);
  glCallList(list);
  CHECK(glRenderMode(GL_RENDER) == 1);
  CHECK(buffer[0] == 1);
  CHECK(buffer[3] == 4);
}

TEST_CASE("feedback: the five types and the point, line and polygon tokens") {
  ScopedContext context(100, 100);
  glass::test::pixelProjection(100, 100);
  std::vector<GLfloat> buffer(256, -1.0f);

  glFeedbackBuffer(256, GL_2D, buffer.data());
  CHECK(glRenderMode(GL_FEEDBACK) == 0);
  glBegin(GL_POINTS);
  glVertex2f(10.0f, 20.0f);
  glEnd();
  CHECK(glRenderMode(GL_RENDER) == 3);
  CHECK(buffer[0] == GL_POINT_TOKEN);
  CHECK(buffer[1] == doctest::Approx(10.0f));
  CHECK(buffer[2] == doctest::Approx(20.0f));

  glFeedbackBuffer(256, GL_3D_COLOR, buffer.data());
  glRenderMode(GL_FEEDBACK);
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glBegin(GL_LINE_STRIP);
  glVertex3f(10.0f, 10.0f, 0.5f);
  glVertex3f(30.0f, 10.0f, 0.5f);
  glVertex3f(30.0f, 40.0f, 0.0f);
  glEnd();
  CHECK(glRenderMode(GL_RENDER) == 2 * (1 + 2 * 7));
  // The first segment of a strip resets the line stipple (spec 3.4.2): GL_LINE_RESET_TOKEN.
  CHECK(buffer[0] == GL_LINE_RESET_TOKEN);
  CHECK(buffer[1] == doctest::Approx(10.0f));
  CHECK(buffer[3] == doctest::Approx(0.25f));  // window depth (1 - 0.5) / 2
  CHECK(buffer[4] == 0.25f);
  CHECK(buffer[7] == 1.0f);
  CHECK(buffer[15] == GL_LINE_TOKEN);
  CHECK(buffer[23] == doctest::Approx(30.0f));
  CHECK(buffer[24] == doctest::Approx(40.0f));
  CHECK(buffer[25] == doctest::Approx(0.5f));

  glFeedbackBuffer(256, GL_4D_COLOR_TEXTURE, buffer.data());
  glRenderMode(GL_FEEDBACK);
  glTexCoord2f(0.5f, 0.75f);
  glBegin(GL_TRIANGLES);
  glVertex2f(10.0f, 10.0f);
  glVertex2f(50.0f, 10.0f);
  glVertex2f(10.0f, 50.0f);
  glEnd();
  CHECK(glRenderMode(GL_RENDER) == 2 + 3 * 12);
  CHECK(buffer[0] == GL_POLYGON_TOKEN);
  CHECK(buffer[1] == 3.0f);
  CHECK(buffer[2] == doctest::Approx(10.0f));
  CHECK(buffer[5] == 1.0f);   // w
  CHECK(buffer[10] == 0.5f);  // s
  CHECK(buffer[11] == 0.75f);
  CHECK(buffer[13] == 1.0f);  // q
  CHECK(buffer[14] == doctest::Approx(50.0f));

  glFeedbackBuffer(256, GL_3D, buffer.data());
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_QUADS);  // two triangles
  glVertex2f(10.0f, 10.0f);
  glVertex2f(50.0f, 10.0f);
  glVertex2f(50.0f, 50.0f);
  glVertex2f(10.0f, 50.0f);
  glEnd();
  // A rectangle is two triangles; clipped at x = 0 the first becomes a quadrilateral, given as
  // two triangles, the second stays a triangle.
  glRectf(-50.0f, 10.0f, 50.0f, 20.0f);
  CHECK(glRenderMode(GL_RENDER) == 5 * (2 + 3 * 3));
  CHECK(buffer[22] == GL_POLYGON_TOKEN);
  for (int t = 2; t < 5; ++t)
    for (int v = 0; v < 3; ++v) CHECK(buffer[t * 11 + 2 + v * 3] >= 0.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("feedback: pass-through, pixel commands, overflow and errors") {
  ScopedContext context(100, 100);
  glass::test::pixelProjection(100, 100);
  GLfloat buffer[64];
  for (GLfloat& v : buffer) v = -1.0f;
  glFeedbackBuffer(64, GL_3D_COLOR, buffer);
  GLint type = 0;
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &type);
  CHECK(type == GL_3D_COLOR);
  glPassThrough(5.0f);  // ignored outside feedback mode
  glRenderMode(GL_FEEDBACK);
  glPassThrough(5.0f);
  glColor3f(1.0f, 0.0f, 0.0f);
  glRasterPos2f(20.0f, 30.0f);
  const GLubyte pixel[4] = {};
  glBitmap(0, 0, 0.0f, 0.0f, 4.0f, 0.0f, nullptr);  // moves the raster position
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glRasterPos2f(200.0f, 30.0f);  // invalid: the next command gives nothing
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  CHECK(glRenderMode(GL_RENDER) == 2 + 3 * 8);
  CHECK(buffer[0] == GL_PASS_THROUGH_TOKEN);
  CHECK(buffer[1] == 5.0f);
  CHECK(buffer[2] == GL_BITMAP_TOKEN);
  CHECK(buffer[3] == doctest::Approx(20.0f));
  CHECK(buffer[6] == 1.0f);  // the raster colour
  CHECK(buffer[10] == GL_DRAW_PIXEL_TOKEN);
  CHECK(buffer[11] == doctest::Approx(24.0f));
  CHECK(buffer[18] == GL_COPY_PIXEL_TOKEN);

  glFeedbackBuffer(3, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex2f(1.0f, 1.0f);
  glVertex2f(2.0f, 2.0f);
  glEnd();
  CHECK(glRenderMode(GL_RENDER) == -1);
  CHECK(buffer[2] == doctest::Approx(1.0f));

  glFeedbackBuffer(4, GL_RGB, buffer);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glFeedbackBuffer(-4, GL_2D, buffer);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glFeedbackBuffer(4, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glFeedbackBuffer(4, GL_2D, buffer);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glRenderMode(GL_RENDER);
  CHECK(glGetError() == GL_NO_ERROR);
}
