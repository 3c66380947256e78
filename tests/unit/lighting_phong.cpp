// Per-fragment lighting (glShadeModel(GL_PHONG_WIN)) against the lighting equation evaluated
// analytically at every pixel centre: the equation of spec 2.14.1 written out here in double,
// independently of glass's own lighting code.
//
// A square at z = 0 fills a 64 x 64 viewport under glOrtho(-1, 1, -1, 1, -1, 1), so the eye-space
// position of pixel (i, j) is exactly (-1 + (i + 0.5) / 32, -1 + (j + 0.5) / 32, 0) and its
// normal is the square's. A close positional light with attenuation, a spotlight and a tight
// highlight make the colour vary strongly across the square: interpolating vertex colours
// (Gouraud) cannot reproduce it, per-fragment lighting must.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace {

constexpr int kSize = 64;

using Vec3 = std::array<double, 3>;
using Rgba = std::array<float, 4>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(const Vec3& v) {
  const double length = std::sqrt(dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

struct MaterialSpec {  // with the defaults of table 6.10 (GL 1.5)
  Rgba ambient{0.2f, 0.2f, 0.2f, 1.0f}, diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  Rgba specular{0.0f, 0.0f, 0.0f, 1.0f}, emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
};

struct LightSpec {  // a positional light in eye coordinates (the modelview is the identity)
  Rgba ambient{0.0f, 0.0f, 0.0f, 1.0f}, diffuse{0.0f, 0.0f, 0.0f, 1.0f};
  Rgba specular{0.0f, 0.0f, 0.0f, 1.0f};
  Rgba position{0.0f, 0.0f, 1.0f, 1.0f};
  float spotDirection[3] = {0.0f, 0.0f, -1.0f};
  float spotCutoff = 180.0f, spotExponent = 0.0f;
  float constantAttenuation = 1.0f, linearAttenuation = 0.0f, quadraticAttenuation = 0.0f;
};

// Spec 2.14.1, with an infinite viewer (GL_LIGHT_MODEL_LOCAL_VIEWER false) and positional lights:
//   c = e_cm + a_cm a_cs + sum_i att_i spot_i (a_cm a_cli + (n . VP_pli) d_cm d_cli
//                                              + f_i (n . h_i)^s_rm s_cm s_cli)
// with VP_pli the unit vector to the light, h_i = VP_pli + (0, 0, 1) normalized, f_i = 1 where
// n . VP_pli is positive, att_i = 1 / (k0 + k1 d + k2 d^2), spot_i = (-VP_pli . s_dli)^s_rli
// inside the cone and 0 outside. Each colour is clamped to [0, 1].
std::array<double, 3> litColor(const MaterialSpec& m, const Rgba& sceneAmbient,
                               const std::vector<LightSpec>& lights, const Vec3& point,
                               const Vec3& normal) {
  std::array<double, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = double(m.emission[k]) + double(m.ambient[k]) * sceneAmbient[k];
  for (const LightSpec& l : lights) {
    const Vec3 toLight{l.position[0] - point[0], l.position[1] - point[1], l.position[2] - point[2]};
    const double distance = std::sqrt(dot(toLight, toLight));
    const Vec3 vp = normalized(toLight);
    const double attenuation =
        1.0 / (l.constantAttenuation + l.linearAttenuation * distance +
               l.quadraticAttenuation * distance * distance);
    double spot = 1.0;
    if (l.spotCutoff != 180.0f) {
      const Vec3 axis = normalized({l.spotDirection[0], l.spotDirection[1], l.spotDirection[2]});
      const double cosine = -dot(vp, axis);
      spot = cosine >= std::cos(l.spotCutoff * M_PI / 180.0) ? std::pow(cosine, l.spotExponent) : 0.0;
    }
    const double diffuse = std::max(dot(normal, vp), 0.0);
    const Vec3 h = normalized({vp[0], vp[1], vp[2] + 1.0});
    const double specular = diffuse > 0.0 ? std::pow(std::max(dot(normal, h), 0.0), m.shininess) : 0.0;
    for (int k = 0; k < 3; ++k) {
      c[k] += attenuation * spot *
              (double(m.ambient[k]) * l.ambient[k] + diffuse * m.diffuse[k] * l.diffuse[k] +
               specular * m.specular[k] * l.specular[k]);
    }
  }
  for (double& v : c) v = std::clamp(v, 0.0, 1.0);
  return c;
}

struct Scene {
  MaterialSpec front, back;
  Rgba modelAmbient{0.1f, 0.1f, 0.1f, 1.0f};
  std::vector<LightSpec> lights;

  Scene() {
    front.ambient = {0.2f, 0.1f, 0.1f, 1.0f};
    front.diffuse = {0.8f, 0.6f, 0.3f, 1.0f};
    front.specular = {0.9f, 0.9f, 0.9f, 1.0f};
    front.shininess = 50.0f;
    back.diffuse = {0.2f, 0.4f, 0.9f, 1.0f};

    LightSpec point;  // GL_LIGHT0: white diffuse and specular by default
    point.diffuse = {1.0f, 1.0f, 1.0f, 1.0f};
    point.specular = {1.0f, 1.0f, 1.0f, 1.0f};
    point.position = {0.3f, -0.2f, 0.6f, 1.0f};
    point.constantAttenuation = 0.5f;
    point.quadraticAttenuation = 1.5f;
    lights.push_back(point);

    LightSpec spot;
    spot.diffuse = {0.3f, 0.5f, 0.8f, 1.0f};
    spot.position = {-0.5f, 0.5f, 1.0f, 1.0f};
    spot.spotCutoff = 25.0f;
    spot.spotExponent = 3.0f;
    lights.push_back(spot);
  }

  // The same state through the GL (with the identity modelview, eye coordinates = as given).
  void apply() const {
    glMaterialfv(GL_FRONT, GL_AMBIENT, front.ambient.data());
    glMaterialfv(GL_FRONT, GL_DIFFUSE, front.diffuse.data());
    glMaterialfv(GL_FRONT, GL_SPECULAR, front.specular.data());
    glMaterialf(GL_FRONT, GL_SHININESS, front.shininess);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back.diffuse.data());
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, modelAmbient.data());
    const LightSpec& point = lights[0];
    glLightfv(GL_LIGHT0, GL_POSITION, point.position.data());
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, point.constantAttenuation);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, point.quadraticAttenuation);
    const LightSpec& spot = lights[1];
    glLightfv(GL_LIGHT1, GL_DIFFUSE, spot.diffuse.data());
    glLightfv(GL_LIGHT1, GL_SPECULAR, spot.specular.data());
    glLightfv(GL_LIGHT1, GL_POSITION, spot.position.data());
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

int toByte(double c) { return static_cast<int>(std::floor(c * 255.0 + 0.5)); }

// The largest difference, over every pixel and channel, between the picture and the equation.
int largestError(const Scene& scene, const std::vector<unsigned char>& pixels, bool back) {
  int worst = 0;
  const Vec3 normal{0.0, 0.0, back ? -1.0 : 1.0};
  const MaterialSpec& material = back ? scene.back : scene.front;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const Vec3 point{-1.0 + (i + 0.5) / 32.0, -1.0 + (j + 0.5) / 32.0, 0.0};
      const std::array<double, 3> primary =
          litColor(material, scene.modelAmbient, scene.lights, point, normal);
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

  // Colour material (spec 2.14.3): the diffuse reflectance is the fragment's colour, linear
  // across the square in x.
  int worst = 0;
  const Vec3 normal{0.0, 0.0, 1.0};
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const double t = (i + 0.5) / kSize;
      MaterialSpec m = scene.front;
      m.diffuse = {static_cast<float>(t), static_cast<float>(1.0 - t), 0.5f, 1.0f};
      const Vec3 point{-1.0 + 2.0 * t, -1.0 + (j + 0.5) / 32.0, 0.0};
      const std::array<double, 3> primary =
          litColor(m, scene.modelAmbient, scene.lights, point, normal);
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(pixels[(j * kSize + i) * 4 + c] - toByte(primary[c])));
      }
    }
  }
  CHECK(worst <= 1);
}
