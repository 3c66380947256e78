// Per-fragment lighting (glShadeModel(GL_PHONG_WIN)) against the lighting equation evaluated
// analytically at every pixel centre.
//
// A square at z = 0 fills a 64 x 64 viewport under glOrtho(-1, 1, -1, 1, -1, 1), so the eye-space
// position of pixel (i, j) is exactly (-1 + (i + 0.5) / 32, -1 + (j + 0.5) / 32, 0) and its
// normal is the square's. A close positional light with attenuation, a spotlight and a tight
// highlight make the colour vary strongly across the square: interpolating vertex colours
// (Gouraud) cannot reproduce it, per-fragment lighting must.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "lighting/color_material.h"
#include "lighting/lighting_equation.h"

namespace {

constexpr int kSize = 64;

struct Scene {
  glass::gl::LightingState state;  // the same lighting, set here by hand for the expectation

  Scene() {
    using glass::gl::LightSource;
    glass::gl::Material& m = state.materials[glass::gl::kFrontMaterial];
    set(m.ambient, 0.2f, 0.1f, 0.1f, 1.0f);
    set(m.diffuse, 0.8f, 0.6f, 0.3f, 1.0f);
    set(m.specular, 0.9f, 0.9f, 0.9f, 1.0f);
    m.shininess = 50.0f;
    glass::gl::Material& back = state.materials[glass::gl::kBackMaterial];
    set(back.diffuse, 0.2f, 0.4f, 0.9f, 1.0f);
    set(state.model.ambient, 0.1f, 0.1f, 0.1f, 1.0f);

    LightSource& point = state.lights[0];
    point.enabled = true;
    set(point.position, 0.3f, -0.2f, 0.6f, 1.0f);
    point.constantAttenuation = 0.5f;
    point.quadraticAttenuation = 1.5f;

    LightSource& spot = state.lights[1];
    spot.enabled = true;
    set(spot.diffuse, 0.3f, 0.5f, 0.8f, 1.0f);
    set(spot.specular, 0.0f, 0.0f, 0.0f, 1.0f);
    set(spot.position, -0.5f, 0.5f, 1.0f, 1.0f);
    spot.spotDirection[0] = 0.0f;
    spot.spotDirection[1] = 0.0f;
    spot.spotDirection[2] = -1.0f;
    spot.spotCutoff = 25.0f;
    spot.spotExponent = 3.0f;
  }

  static void set(float* c, float r, float g, float b, float a) {
    c[0] = r;
    c[1] = g;
    c[2] = b;
    c[3] = a;
  }

  // The same state through the GL (with the identity modelview, eye coordinates = as given).
  void apply() const {
    const glass::gl::Material& m = state.materials[0];
    const glass::gl::Material& back = state.materials[1];
    glMaterialfv(GL_FRONT, GL_AMBIENT, m.ambient);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, m.diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, m.specular);
    glMaterialf(GL_FRONT, GL_SHININESS, m.shininess);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back.diffuse);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, state.model.ambient);
    const glass::gl::LightSource& point = state.lights[0];
    glLightfv(GL_LIGHT0, GL_POSITION, point.position);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, point.constantAttenuation);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, point.quadraticAttenuation);
    const glass::gl::LightSource& spot = state.lights[1];
    glLightfv(GL_LIGHT1, GL_DIFFUSE, spot.diffuse);
    glLightfv(GL_LIGHT1, GL_SPECULAR, spot.specular);
    glLightfv(GL_LIGHT1, GL_POSITION, spot.position);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot.spotDirection);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, spot.spotCutoff);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, spot.spotExponent);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHTING);
  }
};

// Renders the square (counter-clockwise, or clockwise to show its back) and reads it back.
std::vector<unsigned char> render(const Scene& scene, GLenum shadeModel, bool backFacing,
                                  bool twoSided) {
  GlassContext* ctx = glassCreateContext(kSize, kSize);
  REQUIRE(ctx != nullptr);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  scene.apply();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, twoSided ? GL_TRUE : GL_FALSE);
  glShadeModel(shadeModel);
  glClear(GL_COLOR_BUFFER_BIT);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);
  if (backFacing) {
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(-1.0f, 1.0f);
    glVertex2f(1.0f, 1.0f);
    glVertex2f(1.0f, -1.0f);
  } else {
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(1.0f, 1.0f);
    glVertex2f(-1.0f, 1.0f);
  }
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  std::vector<unsigned char> pixels(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
  return pixels;
}

int toByte(float c) { return static_cast<int>(std::floor(c * 255.0f + 0.5f)); }

// The largest difference, over every pixel and channel, between the picture and the equation.
int largestError(const Scene& scene, const std::vector<unsigned char>& pixels, bool back) {
  int worst = 0;
  const float normal[3] = {0.0f, 0.0f, back ? -1.0f : 1.0f};
  const glass::gl::Material& material = scene.state.materials[back ? 1 : 0];
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const float point[3] = {-1.0f + (static_cast<float>(i) + 0.5f) / 32.0f,
                              -1.0f + (static_cast<float>(j) + 0.5f) / 32.0f, 0.0f};
      float primary[4], secondary[4];
      glass::gl::evaluateLighting(scene.state, material, point, normal, primary, secondary);
      for (int c = 0; c < 3; ++c) {
        const int got = pixels[(j * kSize + i) * 4 + c];
        worst = std::max(worst, std::abs(got - toByte(primary[c])));
      }
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("Phong shading: every fragment is lit by the equation at its own position") {
  const Scene scene;
  const std::vector<unsigned char> phong = render(scene, GL_PHONG_WIN, false, false);
  CHECK(largestError(scene, phong, false) <= 1);
  // The scene is one that per-vertex lighting gets badly wrong: the test can tell the two apart.
  const std::vector<unsigned char> gouraud = render(scene, GL_SMOOTH, false, false);
  CHECK(largestError(scene, gouraud, false) > 40);
}

TEST_CASE("Phong shading: two-sided lighting lights back faces with the back material") {
  const Scene scene;
  const std::vector<unsigned char> back = render(scene, GL_PHONG_WIN, true, true);
  CHECK(largestError(scene, back, true) <= 1);
}

TEST_CASE("Phong shading: GL_PHONG_WIN is accepted and reported by glGet") {
  GlassContext* ctx = glassCreateContext(4, 4);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  glShadeModel(GL_PHONG_WIN);
  GLint mode = 0;
  glGetIntegerv(GL_SHADE_MODEL, &mode);
  CHECK(mode == GL_PHONG_WIN);
  CHECK(glGetError() == GL_NO_ERROR);
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);
}

TEST_CASE("Phong shading: colour material takes each fragment's interpolated colour") {
  const Scene scene;
  GlassContext* ctx = glassCreateContext(kSize, kSize);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  scene.apply();
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glShadeModel(GL_PHONG_WIN);
  glClear(GL_COLOR_BUFFER_BIT);
  // The colour runs from (0, 1, 0.5) on the left edge to (1, 0, 0.5) on the right.
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);
  glColor3f(0.0f, 1.0f, 0.5f);
  glVertex2f(-1.0f, -1.0f);
  glColor3f(1.0f, 0.0f, 0.5f);
  glVertex2f(1.0f, -1.0f);
  glVertex2f(1.0f, 1.0f);
  glColor3f(0.0f, 1.0f, 0.5f);
  glVertex2f(-1.0f, 1.0f);
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  std::vector<unsigned char> pixels(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glassMakeCurrent(nullptr);
  glassDestroyContext(ctx);

  glass::gl::LightingState state = scene.state;
  state.colorMaterial.enabled = true;
  state.colorMaterial.face = GL_FRONT;
  state.colorMaterial.mode = GL_DIFFUSE;
  int worst = 0;
  const float normal[3] = {0.0f, 0.0f, 1.0f};
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const float t = (static_cast<float>(i) + 0.5f) / kSize;
      const float color[4] = {t, 1.0f - t, 0.5f, 1.0f};
      const float y = -1.0f + (static_cast<float>(j) + 0.5f) / 32.0f;
      const float point[3] = {-1.0f + 2.0f * t, y, 0.0f};
      const glass::gl::Material m =
          glass::gl::materialWithColor(state, glass::gl::kFrontMaterial, color);
      float primary[4], secondary[4];
      glass::gl::evaluateLighting(state, m, point, normal, primary, secondary);
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(pixels[(j * kSize + i) * 4 + c] - toByte(primary[c])));
      }
    }
  }
  CHECK(worst <= 1);
}
