// Shared by the tests that prove a fast path equal to the reference path: the same drawing is
// rendered in fresh contexts with the fast paths off (the reference path alone) and on, and the
// colour, depth and stencil buffers must be identical byte for byte.
#pragma once

#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "core/fast_paths.h"
#include "pipeline_test_support.h"

namespace glass::test {

// The window the comparisons draw in: wider and taller than one 64 x 64 tile, not a multiple of it.
inline constexpr int kComparisonWidth = 150, kComparisonHeight = 100;

struct Buffers {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
};

// The buffers of a context of the comparison window's size after clearing (colour to (0.1, 0.2,
// 0.3, 0.4), depth to one half, so that every depth function passes some fragments and fails
// others, stencil to 1) and calling draw() with a pixel projection and setState() applied, with
// the fast paths on or off.
inline Buffers renderBuffers(bool fastPaths, const std::function<void()>& setState,
                             const std::function<void()>& draw) {
  constexpr int width = kComparisonWidth, height = kComparisonHeight;
  glass::gl::ScopedFastPaths paths(fastPaths);
  ScopedContext context(width, height);
  pixelProjection(width, height);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(0.5);
  glClearStencil(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  setState();
  draw();
  glFinish();

  Buffers b;
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  b.color.resize(pixels * 4);
  b.depth.resize(pixels);
  b.stencil.resize(pixels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
  glReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
  return b;
}

// draw() with setState() gives the same buffers with the fast paths on as off. drawsSomething:
// the state lets some fragment through (GL_NEVER does not, nor GL_EQUAL against the cleared
// depth), and then the drawing must have changed some pixel's colour or depth, so that the
// comparison is not one of two empty pictures.
inline void checkFastPathsMatch(const std::function<void()>& setState, const std::function<void()>& draw,
                                bool drawsSomething = true) {
  const Buffers reference = renderBuffers(false, setState, draw);
  const Buffers fast = renderBuffers(true, setState, draw);
  CHECK(fast.color == reference.color);
  CHECK(fast.depth == reference.depth);
  CHECK(fast.stencil == reference.stencil);
  if (!drawsSomething) return;
  const Buffers cleared = renderBuffers(false, [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); }, draw);
  CHECK((reference.color != cleared.color || reference.depth != cleared.depth));
}

// Random vertices across the comparison window and a little beyond it, in random colours (alpha
// too) and depths between -0.9 and 0.9; a fixed seed gives the same ones on every run.
class RandomVertices {
 public:
  explicit RandomVertices(unsigned seed) : random_(seed) {}
  float x() { return x_(random_); }
  float y() { return y_(random_); }
  float unit() { return unit_(random_); }
  float shift() { return shift_(random_); }  // -40 to 40
  // glColor4f and glVertex3f of a vertex at (vx, vy).
  void vertex(float vx, float vy) {
    glColor4f(unit(), unit(), unit(), unit());
    glVertex3f(vx, vy, z_(random_));
  }

 private:
  std::mt19937 random_;
  std::uniform_real_distribution<float> x_{-10.0f, kComparisonWidth + 10.0f}, y_{-10.0f, kComparisonHeight + 10.0f};
  std::uniform_real_distribution<float> z_{-0.9f, 0.9f}, unit_{0.0f, 1.0f}, shift_{-40.0f, 40.0f};
};

// States the comparisons share.

// A perspective view of the pixel projection's plane, tilted by nothing but scaled about the
// window's centre, with the depth test GL_LESS.
inline void usePerspectiveView() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(0, kComparisonWidth, 0, kComparisonHeight, 1, 3);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(-kComparisonWidth * 0.5f, -kComparisonHeight * 0.5f, -2.0f);
  glScalef(1.5f, 1.5f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

inline void useDepthTest(GLenum func, bool mask) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(func);
  glDepthMask(mask ? GL_TRUE : GL_FALSE);
}

// Linear fog over window depths -1 to 1 (the pixel projection's z).
inline void useLinearFog() {
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, -1.0f);
  glFogf(GL_FOG_END, 1.0f);
}

// A 2 x 2 RGBA texture, one texel half transparent, minified by `filter` (magnified linearly)
// and modulating the colour, its coordinates generated from the object's x and y.
inline void useGeneratedTexture(GLenum filter = GL_NEAREST) {
  static const uint8_t texels[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 128};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  static const float sPlane[4] = {0.05f, 0.0f, 0.0f, 0.0f}, tPlane[4] = {0.0f, 0.07f, 0.0f, 0.0f};
  glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, tPlane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
}

}  // namespace glass::test
