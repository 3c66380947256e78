// Fog (spec 3.10): the factor of each mode against values worked out by hand, and the blend of a
// fragment's colour towards the fog colour (red, green and blue only).
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cmath>

#include "fragment/fog_hooks.h"
#include "fragment/fog_state.h"

using glass::gl::FogState;
using glass::gl::fogFactor;

TEST_CASE("fog factor: GL_LINEAR falls from 1 at start to 0 at end, clamped outside") {
  FogState fog;
  fog.mode = GL_LINEAR;
  fog.start = 2.0f;
  fog.end = 6.0f;
  CHECK(fogFactor(fog, 2.0f) == doctest::Approx(1.0f));
  CHECK(fogFactor(fog, 5.0f) == doctest::Approx(0.25f));  // (6 - 5) / (6 - 2)
  CHECK(fogFactor(fog, 6.0f) == doctest::Approx(0.0f));
  CHECK(fogFactor(fog, 1.0f) == 1.0f);   // nearer than start: clamped
  CHECK(fogFactor(fog, 10.0f) == 0.0f);  // beyond end: clamped
}

TEST_CASE("fog factor: GL_EXP and GL_EXP2") {
  FogState fog;  // GL_EXP with density 1 by default
  CHECK(fogFactor(fog, 0.0f) == 1.0f);
  fog.density = 0.5f;
  CHECK(fogFactor(fog, 2.0f) == doctest::Approx(std::exp(-1.0f)));     // exp(-0.5 * 2)
  fog.mode = GL_EXP2;
  CHECK(fogFactor(fog, 2.0f) == doctest::Approx(std::exp(-1.0f)));     // exp(-(0.5 * 2)^2)
  CHECK(fogFactor(fog, 4.0f) == doctest::Approx(std::exp(-4.0f)));     // exp(-(0.5 * 4)^2)
}

namespace {

// A white quad at eye depth z_e = -depth, fogged towards blue, read back at the centre.
void foggedPixel(GLenum mode, float depth, unsigned char rgba[4]) {
  GlassContext* ctx = glassCreateContext(8, 8);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, 0.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat blue[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  glFogfv(GL_FOG_COLOR, blue);
  glFogi(GL_FOG_MODE, static_cast<GLint>(mode));
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogf(GL_FOG_DENSITY, 0.2f);
  glEnable(GL_FOG);
  glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
  glBegin(GL_QUADS);
  glVertex3f(-1.0f, -1.0f, -depth);
  glVertex3f(1.0f, -1.0f, -depth);
  glVertex3f(1.0f, 1.0f, -depth);
  glVertex3f(-1.0f, 1.0f, -depth);
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
}

int level(float c) { return static_cast<int>(std::floor(c * 255.0f + 0.5f)); }

}  // namespace

TEST_CASE("fog: fragments blend towards the fog colour by the factor at their eye distance") {
  unsigned char p[4];
  foggedPixel(GL_LINEAR, 5.0f, p);  // f = (10 - 5) / 10
  CHECK(p[0] == level(0.5f));
  CHECK(p[1] == level(0.5f));
  CHECK(p[2] == 255);               // 0.5 * 1 + 0.5 * 1
  CHECK(p[3] == level(0.5f));       // alpha is not fogged

  foggedPixel(GL_EXP, 5.0f, p);     // f = exp(-0.2 * 5)
  CHECK(std::abs(p[0] - level(std::exp(-1.0f))) <= 1);
  foggedPixel(GL_EXP2, 5.0f, p);    // f = exp(-(0.2 * 5)^2)
  CHECK(std::abs(p[0] - level(std::exp(-1.0f))) <= 1);
  foggedPixel(GL_EXP2, 10.0f, p);   // f = exp(-4)
  CHECK(std::abs(p[0] - level(std::exp(-4.0f))) <= 1);
}
