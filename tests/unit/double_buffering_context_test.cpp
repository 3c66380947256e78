// glassSetDoubleBuffered: a context with a front and a back colour buffer, as a GLUT_DOUBLE window
// has (spec 4.2.1, 4.3.2; GLX's swap): GL_DOUBLEBUFFER is true, drawing and reading start on the
// back buffer, glDrawBuffer and glReadBuffer choose between them (GL_FRONT_AND_BACK draws into
// both, each blended with its own pixels), glassSwapBuffers copies the back buffer to the front,
// and glassResetContext and glassResizeContext keep the choice.
#include <GL/gl.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <array>
#include <cstring>

namespace {

using Pixel = std::array<int, 4>;

GLint integer(GLenum pname) {
  GLint value = -1;
  glGetIntegerv(pname, &value);
  return value;
}

Pixel readFrom(GLenum buffer, int x, int y) {
  const GLint before = integer(GL_READ_BUFFER);
  glReadBuffer(buffer);
  GLubyte p[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  glReadBuffer(static_cast<GLenum>(before));
  return {p[0], p[1], p[2], p[3]};
}

void rectangle(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
  glEnd();
}

Pixel fromMemory(const unsigned char* pixels, int width, int x, int y) {
  const unsigned char* p = pixels + (static_cast<size_t>(y) * width + x) * 4;
  return {p[0], p[1], p[2], p[3]};
}

}  // namespace

TEST_CASE("glassSetDoubleBuffered: front and back buffers, drawn and read as glDrawBuffer and glReadBuffer say") {
  GlassContext* ctx = glassCreateContext(16, 16);
  REQUIRE(ctx != nullptr);
  glassMakeCurrent(ctx);
  CHECK(integer(GL_DOUBLEBUFFER) == 0);
  CHECK(integer(GL_DRAW_BUFFER) == GL_FRONT);
  CHECK(glassGetFrontBuffer(ctx) == glassGetColorBuffer(ctx));  // one buffer

  REQUIRE(glassSetDoubleBuffered(ctx, 1) == 1);
  CHECK(integer(GL_DOUBLEBUFFER) == 1);
  CHECK(integer(GL_DRAW_BUFFER) == GL_BACK);
  CHECK(integer(GL_READ_BUFFER) == GL_BACK);
  CHECK(glassGetFrontBuffer(ctx) != glassGetColorBuffer(ctx));

  // The back buffer blue; the front keeps what it had (black) until the swap.
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readFrom(GL_BACK, 4, 4) == Pixel{0, 0, 255, 255});
  CHECK(readFrom(GL_FRONT, 4, 4) == Pixel{0, 0, 0, 0});
  REQUIRE(glassSwapBuffers(ctx) == 1);
  CHECK(readFrom(GL_FRONT, 4, 4) == Pixel{0, 0, 255, 255});
  CHECK(readFrom(GL_BACK, 4, 4) == Pixel{0, 0, 255, 255});  // the back keeps its pixels

  // XOR into the front only, as rubber bands are drawn.
  glDrawBuffer(GL_FRONT);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glColor3f(0.0f, 1.0f, 0.0f);
  rectangle(-1.0f, -1.0f, 0.0f, 0.0f);
  glDisable(GL_COLOR_LOGIC_OP);
  CHECK(readFrom(GL_FRONT, 4, 4) == Pixel{0, 255, 255, 0});  // alpha 1 XOR 1
  CHECK(readFrom(GL_BACK, 4, 4) == Pixel{0, 0, 255, 255});
  CHECK(readFrom(GL_FRONT, 12, 12) == Pixel{0, 0, 255, 255});
  glFinish();
  CHECK(fromMemory(glassGetFrontBuffer(ctx), 16, 4, 4) == Pixel{0, 255, 255, 0});
  CHECK(fromMemory(glassGetColorBuffer(ctx), 16, 4, 4) == Pixel{0, 0, 255, 255});

  // Both: a half-transparent red blended into each buffer's own pixels; the back buffer cleared
  // to black first, so the two results differ.
  glDrawBuffer(GL_BACK);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_FRONT_AND_BACK);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 0.0f, 0.0f, 0.5f);
  rectangle(-1.0f, -1.0f, 1.0f, 1.0f);
  glDisable(GL_BLEND);
  const Pixel front = readFrom(GL_FRONT, 4, 4), back = readFrom(GL_BACK, 4, 4);
  CHECK(front[0] == back[0]);
  CHECK(front[1] == 127);  // the XOR square's green and blue, halved
  CHECK(front[2] == 127);
  CHECK(back[1] == 0);
  CHECK(back[2] == 0);

  // Clearing both.
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readFrom(GL_FRONT, 9, 9) == Pixel{255, 255, 255, 255});
  CHECK(readFrom(GL_BACK, 9, 9) == Pixel{255, 255, 255, 255});

  // glPopAttrib puts the draw buffer back, and drawing follows it.
  glDrawBuffer(GL_BACK);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_FRONT);
  glPopAttrib();
  CHECK(integer(GL_DRAW_BUFFER) == GL_BACK);
  glColor3f(0.0f, 0.0f, 0.0f);
  rectangle(-1.0f, -1.0f, 1.0f, 1.0f);
  CHECK(readFrom(GL_BACK, 9, 9) == Pixel{0, 0, 0, 255});
  CHECK(readFrom(GL_FRONT, 9, 9) == Pixel{255, 255, 255, 255});

  // glCopyPixels from the front into the back, and glCopyTexImage and glAccum reading the front.
  glReadBuffer(GL_FRONT);
  glRasterPos2f(-1.0f, -1.0f);
  glCopyPixels(0, 0, 16, 16, GL_COLOR);
  glReadBuffer(GL_BACK);
  CHECK(readFrom(GL_BACK, 9, 9) == Pixel{255, 255, 255, 255});
  glDrawBuffer(GL_FRONT);
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_FRONT);
  glAccum(GL_LOAD, 1.0f);
  glAccum(GL_RETURN, 1.0f);
  CHECK(readFrom(GL_BACK, 9, 9) == Pixel{0, 255, 0, 255});
  GLubyte texel[4] = {};
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  CHECK(Pixel{texel[0], texel[1], texel[2], texel[3]} == Pixel{0, 255, 0, 255});
  CHECK(glGetError() == GL_NO_ERROR);

  // Kept by reset and resize; a reset starts drawing and reading on the back buffer again.
  glDrawBuffer(GL_FRONT);
  REQUIRE(glassResetContext(ctx) == 1);
  CHECK(integer(GL_DOUBLEBUFFER) == 1);
  CHECK(integer(GL_DRAW_BUFFER) == GL_BACK);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(readFrom(GL_BACK, 2, 2) == Pixel{255, 0, 0, 255});
  CHECK(readFrom(GL_FRONT, 2, 2) == Pixel{0, 255, 0, 255});
  REQUIRE(glassResizeContext(ctx, 20, 10) == 1);
  CHECK(integer(GL_DOUBLEBUFFER) == 1);
  CHECK(readFrom(GL_FRONT, 2, 2) == Pixel{0, 0, 0, 0});
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(glassSwapBuffers(ctx) == 1);
  CHECK(fromMemory(glassGetFrontBuffer(ctx), 20, 19, 9) == Pixel{255, 0, 0, 255});

  // Not between glBegin and glEnd; back to one buffer.
  glBegin(GL_TRIANGLES);
  CHECK(glassSetDoubleBuffered(ctx, 0) == 0);
  glEnd();
  CHECK(integer(GL_DOUBLEBUFFER) == 1);
  REQUIRE(glassSetDoubleBuffered(ctx, 0) == 1);
  CHECK(integer(GL_DOUBLEBUFFER) == 0);
  CHECK(glassGetFrontBuffer(ctx) == glassGetColorBuffer(ctx));
  CHECK(glassSetDoubleBuffered(nullptr, 1) == 0);
  CHECK(glassSwapBuffers(nullptr) == 0);
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
}

TEST_CASE("glassSetDoubleBuffered: drawing into both buffers gives the bytes of drawing into one") {
  // Blended triangles drawn with GL_FRONT_AND_BACK take the per-fragment path for both buffers;
  // the same drawn into a single-buffered context takes the fast block kernels. Both buffers of
  // the first began as the second's one buffer, so each must end with its bytes.
  GlassContext* one = glassCreateContext(64, 64);
  GlassContext* two = glassCreateContext(64, 64);
  REQUIRE(one != nullptr);
  REQUIRE(two != nullptr);
  glassSetDoubleBuffered(two, 1);
  for (GlassContext* ctx : {one, two}) {
    glassMakeCurrent(ctx);
    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int i = 0; i < 40; ++i) {
      glColor4f((i % 5) / 4.0f, (i % 3) / 2.0f, (i % 7) / 6.0f, 0.25f + (i % 4) / 8.0f);
      const float t = i / 40.0f;
      glBegin(GL_TRIANGLES);
      glVertex2f(-1.0f + t, -1.0f);
      glVertex2f(1.0f, -0.5f + t);
      glVertex2f(-0.3f * t, 1.0f);
      glEnd();
    }
    glFinish();
  }
  const size_t bytes = 64 * 64 * 4;
  CHECK(std::memcmp(glassGetColorBuffer(one), glassGetFrontBuffer(two), bytes) == 0);
  CHECK(std::memcmp(glassGetColorBuffer(one), glassGetColorBuffer(two), bytes) == 0);
  glassMakeCurrent(nullptr);
  glassDestroyContext(one);
  glassDestroyContext(two);
}
