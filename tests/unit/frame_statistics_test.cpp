// GLASS_STATS on small scenes whose counts follow from the geometry: pixels covered, triangles
// culled or clipped, fragments each test rejects, texels each lookup reads.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "core/context.h"
#include "pipeline_test_support.h"
#include "teaching/frame_statistics.h"

namespace {

// GLASS_STATS=1 for the contexts created while the object lives.
struct ScopedStatistics : glass::test::ScopedEnvironment {
  ScopedStatistics() : ScopedEnvironment("GLASS_STATS", "1") {}
};

// The current context's counts, with its queued drawing finished.
const glass::gl::FrameStatistics& counts() {
  glFinish();
  const glass::gl::FrameStatistics* s = glass::gl::frameStatisticsFor(*glass::gl::currentContext());
  REQUIRE(s != nullptr);
  return *s;
}

}  // namespace

TEST_CASE("GLASS_STATS counts a rectangle's vertices, triangles and the pixels it covers") {
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  // x from pixel 0 to 32, y from 0 to 48 of a 64 x 64 window: 32 x 48 = 1536 pixel centres.
  glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 0.5f, 0.0f);
  const auto& s = counts();
  CHECK(s.vertices == 4);
  CHECK(s.triangles == 2);  // a quad is two triangles
  CHECK(s.points + s.lines == 0);
  CHECK(s.culled == 0);
  CHECK(s.clippedAway + s.clipped + s.producedByClipping == 0);
  CHECK(s.fragments == 1536);
  CHECK(s.passed == 1536);
  CHECK(s.depthRejected + s.stencilRejected + s.alphaRejected + s.scissorRejected == 0);
  CHECK(s.texelReads == 0);

  const std::string text = glass::gl::formatFrameStatistics(s);
  CHECK(text.find("glass stats, frame 0:\n") == 0);
  CHECK(text.find("  fragments                      1536") != std::string::npos);
  CHECK(text.find("  primitives                        2   (0 points, 0 lines, 2 triangles)") != std::string::npos);

  // Presenting the frame prints it and starts the next one.
  glassGetColorBuffer(context.get());
  CHECK(s.frame == 1);
  CHECK(s.vertices == 0);
  CHECK(s.fragments == 0);
}

TEST_CASE("GLASS_STATS: a culled back face, a triangle wholly clipped, one cut into three") {
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  glEnable(GL_CULL_FACE);  // back faces; counter-clockwise is front
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);  // clockwise: culled
  glVertex2f(-0.5f, 0.5f);
  glVertex2f(0.5f, -0.5f);
  glVertex2f(1.5f, -0.5f);  // right of x = 1 entirely: clipped away
  glVertex2f(2.5f, -0.5f);
  glVertex2f(1.5f, 0.5f);
  glEnd();
  {
    const auto& s = counts();
    CHECK(s.vertices == 6);
    CHECK(s.triangles == 2);
    CHECK(s.culled == 1);
    CHECK(s.clippedAway == 1);
    CHECK(s.clipped == 0);
    CHECK(s.fragments == 0);
  }
  glassGetColorBuffer(context.get());
  // Cut by x = 1 and y = 1: the pentagon (16,16) (64,16) (64,32) (32,64) (16,64), a fan of three.
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);
  glVertex2f(1.5f, -0.5f);
  glVertex2f(-0.5f, 1.5f);
  glEnd();
  const auto& s = counts();
  CHECK(s.triangles == 1);
  CHECK(s.clipped == 1);
  CHECK(s.producedByClipping == 3);
  CHECK(s.clippedAway == 0);
}

TEST_CASE("GLASS_STATS: lines and points, clipped and clipped away") {
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  glBegin(GL_LINES);
  glVertex2f(-0.5f, 0.0f);  // crosses x = 1: cut into one line
  glVertex2f(1.5f, 0.0f);
  glVertex2f(1.5f, 0.0f);  // outside: clipped away
  glVertex2f(2.0f, 0.0f);
  glEnd();
  glBegin(GL_POINTS);
  glVertex2f(0.0f, 0.0f);
  glVertex2f(0.0f, 3.0f);  // outside
  glEnd();
  const auto& s = counts();
  CHECK(s.vertices == 6);
  CHECK(s.lines == 2);
  CHECK(s.points == 2);
  CHECK(s.clipped == 1);
  CHECK(s.producedByClipping == 1);
  CHECK(s.clippedAway == 2);
}

TEST_CASE("GLASS_STATS: fragments rejected by the depth, scissor, alpha and stencil tests") {
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  SUBCASE("a quad half hidden by depth") {
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 1.0f, -0.5f);  // the left half, near: 2048 fragments
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.5f);   // the whole window, far: 4096, half hidden
    const auto& s = counts();
    CHECK(s.fragments == 2048 + 4096);
    CHECK(s.depthRejected == 2048);
    CHECK(s.passed == 4096);
  }
  SUBCASE("the scissor box, 16 of 64 columns") {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 16, 64);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
    const auto& s = counts();
    CHECK(s.fragments == 4096);
    CHECK(s.scissorRejected == 4096 - 1024);
    CHECK(s.passed == 1024);
  }
  SUBCASE("the alpha test") {
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glColor4f(1.0f, 1.0f, 1.0f, 0.25f);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
    const auto& s = counts();
    CHECK(s.alphaRejected == 4096);
    CHECK(s.passed == 0);
  }
  SUBCASE("the stencil test") {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0xFF);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 0.0f, 0.0f);
    const auto& s = counts();
    CHECK(s.stencilRejected == 2048);
    CHECK(s.passed == 0);
  }
}

TEST_CASE("GLASS_STATS counts the texels each lookup reads") {
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  for (int level = 0, size = 64; size >= 1; ++level, size /= 2) {
    const std::vector<unsigned char> texels(static_cast<std::size_t>(size) * size * 4, 200);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  glEnable(GL_TEXTURE_2D);
  SUBCASE("nearest: one texel a fragment") {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
    CHECK(counts().texelReads == 4096);
  }
  SUBCASE("linear: four") {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
    CHECK(counts().texelReads == 4 * 4096);
  }
  SUBCASE("trilinear between two levels: eight") {
    // Texture coordinates 0 to 2^1.5 across 64 pixels put 2^1.5 texels of the 64 x 64 image in a
    // pixel: rho = 2^1.5, lambda = 1.5, so levels 1 and 2 are read, four texels each.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glMatrixMode(GL_TEXTURE);
    glScalef(2.828427125f, 2.828427125f, 1.0f);
    glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
    CHECK(counts().texelReads == 8 * 4096);
  }
}

TEST_CASE("GLASS_STATS counts the vertices of glDrawArrays and leaves the pictures as they are") {
  const GLfloat positions[] = {-1.0f, -1.0f, 0.5f, -1.0f, 0.5f, 0.25f, -1.0f, 0.25f};
  auto draw = [&] {
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 5, 40, 50);
    glColor3f(0.9f, 0.5f, 0.1f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, positions);
    glDrawArrays(GL_QUADS, 0, 4);
    glColor3f(0.2f, 0.8f, 0.4f);
    glass::test::rectangleNdc(-0.5f, -0.5f, 1.0f, 1.0f, 0.5f);
    glFinish();
  };
  std::vector<uint8_t> plain;
  {
    glass::test::ScopedContext context(64, 64);
    draw();
    plain = glass::test::readFramebuffer(64, 64);
  }
  ScopedStatistics statistics;
  glass::test::ScopedContext context(64, 64);
  draw();
  CHECK(glass::test::readFramebuffer(64, 64) == plain);
  CHECK(counts().vertices == 8);
  CHECK(counts().triangles == 4);
}
