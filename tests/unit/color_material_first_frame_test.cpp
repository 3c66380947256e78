// The first sphere of tests/image/programs/color_material_init.c, where glass follows the
// specification and Mesa 22.3 does not, tested on its own (the image test compares the rest with
// Mesa): a glMaterial of the diffuse reflectance, then glColorMaterial(GL_FRONT, GL_DIFFUSE) and
// glEnable(GL_COLOR_MATERIAL), then a sphere with no glColor call. Spec 2.14.3: while colour
// material is enabled the tracked reflectance is the current colour, from the moment it is
// enabled; the current colour is still the initial white, so the sphere must be lit exactly as a
// sphere whose diffuse reflectance is white, not as one whose is the glMaterial grey.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glut.h>

#include <vector>

#include "pipeline_test_support.h"

namespace {

constexpr int kWidth = 160, kHeight = 160;

enum class Diffuse { GreyThenColorMaterial, White, Grey };

std::vector<uint8_t> litSphere(Diffuse diffuse) {
  glass::test::ScopedContext context(kWidth, kHeight);
  static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat lightPosition[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  glEnable(GL_DEPTH_TEST);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse == Diffuse::White ? white : grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);
  glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  if (diffuse == Diffuse::GreyThenColorMaterial) {
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
  }
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1.5, 1.5, -1.5, 1.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glutSolidSphere(1.0, 20, 16);
  CHECK(glGetError() == GL_NO_ERROR);
  return glass::test::readFramebuffer(kWidth, kHeight);
}

}  // namespace

TEST_CASE("colour material: enabled after a glMaterial, the first sphere is lit with the current colour") {
  const std::vector<uint8_t> tracked = litSphere(Diffuse::GreyThenColorMaterial);
  CHECK(tracked == litSphere(Diffuse::White));
  // The two possible readings give different pictures, so the comparison above decides.
  CHECK(tracked != litSphere(Diffuse::Grey));
}
