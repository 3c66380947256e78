// The accumulation buffer (spec 4.2.3, 4.2.4): glClearAccum, glClear(GL_ACCUM_BUFFER_BIT) and the
// five glAccum operations, rounding as Mesa's 16-bit accumulation buffer does.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// The colour one channel of byte c gives after LOAD with `load`, then RETURN with `ret`:
// trunc(c / 255 * (load * 32767)), then round-half-even(a * (ret / 32767) * 255), clamped.
int loadReturn(int c, float load, float ret) {
  const float a = std::trunc(static_cast<float>(c) * (1.0f / 255.0f) * (load * 32767.0f));
  const float v = std::fmin(std::fmax(a * (ret / 32767.0f), 0.0f), 1.0f);
  return static_cast<int>(std::nearbyint(v * 255.0f));
}

void clearColorBytes(GLubyte r, GLubyte g, GLubyte b, GLubyte a) {
  glClearColor(r / 255.0f, g / 255.0f, b / 255.0f, a / 255.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace

TEST_CASE("accum: the buffer has 16 bits per channel and a clamped clear value") {
  ScopedContext context(8, 8);
  GLint bits[4] = {};
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
  glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
  glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
  glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
  for (const GLint b : bits) CHECK(b == 16);
  glClearAccum(-2.0f, 0.5f, 0.25f, 3.0f);
  GLfloat value[4];
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, value);
  CHECK(value[0] == -1.0f);
  CHECK(value[1] == 0.5f);
  CHECK(value[2] == 0.25f);
  CHECK(value[3] == 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("accum: LOAD, ACCUM and RETURN average pictures") {
  ScopedContext context(8, 8);
  // Eight pictures of 200, 200, ... averaged: each adds trunc(200 / 255 * 0.125 * 32767).
  clearColorBytes(200, 100, 37, 255);
  glAccum(GL_LOAD, 0.125f);
  for (int i = 0; i < 7; ++i) glAccum(GL_ACCUM, 0.125f);
  clearColorBytes(0, 0, 0, 0);
  glAccum(GL_RETURN, 1.0f);
  const float step = 0.125f * 32767.0f;
  auto average = [&](int c) {
    const float a = 8.0f * std::trunc(static_cast<float>(c) * (1.0f / 255.0f) * step);
    return static_cast<int>(std::nearbyint(a * (1.0f / 32767.0f) * 255.0f));
  };
  const Rgba p = pixelAt(3, 3);
  CHECK(p.r == average(200));
  CHECK(p.g == average(100));
  CHECK(p.b == average(37));
  CHECK(p.a == average(255));
  CHECK(p.r == 200);  // 8 * trunc(3212.45) = 25696, and 25696 / 32767 * 255 = 199.97
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("accum: each operation's arithmetic") {
  ScopedContext context(4, 4);
  clearColorBytes(128, 64, 255, 10);
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 2.0f);
  Rgba p = pixelAt(0, 0);
  CHECK(p.r == loadReturn(128, 0.5f, 2.0f));
  CHECK(p.g == loadReturn(64, 0.5f, 2.0f));
  CHECK(p.b == loadReturn(255, 0.5f, 2.0f));

  // MULT scales, ADD adds value * 32767 (truncated), RETURN scales and clamps.
  clearColorBytes(100, 100, 100, 100);
  glAccum(GL_LOAD, 1.0f);
  glAccum(GL_MULT, 0.5f);
  glAccum(GL_ADD, 0.25f);
  glAccum(GL_RETURN, 1.0f);
  p = pixelAt(1, 1);
  const float a = std::trunc(100.0f * (1.0f / 255.0f) * 32767.0f);
  const float expected = std::trunc(a * 0.5f) + std::trunc(0.25f * 32767.0f);
  CHECK(p.r == static_cast<int>(std::nearbyint(expected * (1.0f / 32767.0f) * 255.0f)));
  glAccum(GL_ADD, -1.0f);  // far below zero: RETURN clamps to 0
  glAccum(GL_RETURN, 1.0f);
  CHECK(pixelAt(1, 1) == Rgba{0, 0, 0, 0});
  clearColorBytes(100, 100, 100, 100);
  glAccum(GL_LOAD, 1.0f);
  glAccum(GL_ACCUM, 1.0f);
  glAccum(GL_ACCUM, 1.0f);  // saturates at 32767
  glAccum(GL_RETURN, 0.25f);
  CHECK(pixelAt(1, 1).r == static_cast<int>(std::nearbyint(32767.0f * (0.25f / 32767.0f) * 255.0f)));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("accum: glClear of the accumulation buffer and the clear value") {
  ScopedContext context(4, 4);
  glClearAccum(0.5f, -0.5f, 1.0f, 0.25f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  // Stored as trunc((c * 65535 - 1) / 2): 16383 for 0.5, 32767 for 1, 8191 for 0.25.
  const Rgba p = pixelAt(2, 2);
  CHECK(p.r == static_cast<int>(std::nearbyint(16383.0f * (1.0f / 32767.0f) * 255.0f)));
  CHECK(p.g == 0);
  CHECK(p.b == 255);
  CHECK(p.a == static_cast<int>(std::nearbyint(8191.0f * (1.0f / 32767.0f) * 255.0f)));
}

TEST_CASE("accum: the scissor box bounds every operation; RETURN honours the colour mask") {
  ScopedContext context(8, 8);
  clearColorBytes(255, 255, 255, 255);
  glAccum(GL_LOAD, 1.0f);
  clearColorBytes(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(2, 2, 3, 3);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_ACCUM_BUFFER_BIT);  // clears inside the box only
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glAccum(GL_RETURN, 1.0f);
  CHECK(pixelAt(0, 0) == Rgba{255, 0, 255, 255});
  CHECK(pixelAt(3, 3) == Rgba{0, 0, 0, 0});
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  clearColorBytes(9, 9, 9, 9);  // only pixel (0, 0)
  glDisable(GL_SCISSOR_TEST);
  glAccum(GL_RETURN, 1.0f);
  CHECK(pixelAt(0, 0) == Rgba{255, 255, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("accum: errors, display lists and render modes") {
  ScopedContext context(4, 4);
  glAccum(GL_RENDER, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glAccum(GL_LOAD, 1.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);

  clearColorBytes(255, 0, 0, 255);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearAccum(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  glEndList();
  CHECK(pixelAt(0, 0) == Rgba{255, 0, 0, 255});
  glCallList(list);
  CHECK(pixelAt(0, 0) == Rgba{0, 255, 0, 255});

  // In selection mode glAccum does nothing (as in Mesa).
  GLuint buffer[4];
  glSelectBuffer(4, buffer);
  glRenderMode(GL_SELECT);
  glClearAccum(0.0f, 0.0f, 1.0f, 1.0f);
  glAccum(GL_LOAD, 0.0f);
  glAccum(GL_RETURN, 1.0f);
  glRenderMode(GL_RENDER);
  CHECK(pixelAt(0, 0) == Rgba{0, 255, 0, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}
