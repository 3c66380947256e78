// glRotate, glOrtho and glFrustum give Mesa's matrices to the last bit.
//
// The specification leaves the rounding of these matrices open, but it decides where a vertex
// that lies exactly on a clip plane or a polygon edge falls, so glass rounds as Mesa does (the
// reference renderer of the image tests): the rotation's sine and cosine in float of the angle
// rounded to float radians, the projections in float from the arguments rounded to float.
//
// The expected values were read back with glGetFloatv from Mesa 22.3.6 (llvmpipe) after the
// same calls, through the reference tool (tools/reference), on glibc's libm.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

void checkMatrix(GLenum pname, const float (&expected)[16]) {
  GLfloat m[16];
  glGetFloatv(pname, m);
  for (int i = 0; i < 16; ++i) {
    INFO("element ", i, ": glass ", m[i], ", Mesa ", expected[i]);
    CHECK(m[i] == expected[i]);
  }
}

}  // namespace

TEST_CASE("glRotatef(90) about x has Mesa's cosine, cosf(float(pi / 2)) < 0, not 0") {
  ScopedContext context;
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  const float c = std::cos(static_cast<float>(90.0 * std::numbers::pi / 180.0));
  CHECK(c < 0.0f);  // float(pi / 2) is above pi / 2
  const float mesa[16] = {0x1p+0f, 0, 0, 0, 0, -0x1.777a5cp-25f, 0x1p+0f, 0,
                          0, -0x1p+0f, -0x1.777a5cp-25f, 0, 0, 0, 0, 0x1p+0f};
  checkMatrix(GL_MODELVIEW_MATRIX, mesa);
}

TEST_CASE("glRotatef(180) about z and about general axes as Mesa computes them") {
  ScopedContext context;
  glMatrixMode(GL_MODELVIEW);

  glLoadIdentity();
  glRotatef(180.0f, 0.0f, 0.0f, 1.0f);
  const float half[16] = {-0x1p+0f, -0x1.777a5cp-24f, 0, 0, 0x1.777a5cp-24f, -0x1p+0f, 0, 0,
                          0, 0, 0x1p+0f, 0, 0, 0, 0, 0x1p+0f};
  checkMatrix(GL_MODELVIEW_MATRIX, half);

  glLoadIdentity();
  glRotatef(37.0f, 1.0f, 2.0f, -0.5f);
  const float general[16] = {0x1.ac8a0ap-1f,  -0x1.bf6b2cp-5f, -0x1.16c6b4p-1f, 0,
                             0x1.aa0f54p-3f,  0x1.e773e4p-1f,  0x1.cb5cfep-3f,  0,
                             0x1.03236cp-1f,  -0x1.343ba2p-2f, 0x1.9dcf94p-1f,  0,
                             0,               0,               0,               0x1p+0f};
  checkMatrix(GL_MODELVIEW_MATRIX, general);

  glLoadIdentity();
  glRotatef(-123.4f, -0.3f, 0.2f, 0.9f);
  const float negative[16] = {-0x1.9badep-2f, -0x1.bf74e4p-1f, -0x1.17b0bp-2f, 0,
                              0x1.5a1d5p-1f,  -0x1.f02186p-2f, 0x1.1c4664p-1f, 0,
                              -0x1.3c31bap-1f, 0x1.3c052p-5f,  0x1.923676p-1f, 0,
                              0,              0,               0,              0x1p+0f};
  checkMatrix(GL_MODELVIEW_MATRIX, negative);
}

TEST_CASE("glRotatef about an axis shorter than 1e-4 leaves the matrix unchanged, as Mesa") {
  ScopedContext context;
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30.0f, 5e-5f, 0.0f, 5e-5f);
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  checkMatrix(GL_MODELVIEW_MATRIX, identity);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glOrtho and glFrustum in float from float arguments, as Mesa") {
  ScopedContext context;
  glMatrixMode(GL_PROJECTION);

  glLoadIdentity();
  glOrtho(-2.1, 3.3, -1.7, 4.1, 0.5, 20.0);
  const float ortho[16] = {0x1.7b426p-2f, 0, 0, 0, 0, 0x1.611a7ap-2f, 0, 0,
                           0, 0, -0x1.a41a42p-4f, 0,
                           -0x1.c71c76p-3f, -0x1.a7b95ep-2f, -0x1.0d20d2p+0f, 0x1p+0f};
  checkMatrix(GL_PROJECTION_MATRIX, ortho);

  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.25, 0.25, 1.0, 30.0);
  const float frustum[16] = {0x1.aaaaaap+0f, 0, 0, 0, 0, 0x1p+2f, 0, 0,
                             0, 0, -0x1.11a7bap+0f, -0x1p+0f, 0, 0, -0x1.08d3dcp+1f, 0};
  checkMatrix(GL_PROJECTION_MATRIX, frustum);

  glLoadIdentity();
  glFrustum(-1.3, 1.7, -0.9, 1.1, 0.7, 55.0);
  const float offCentre[16] = {0x1.dddddep-2f, 0, 0, 0, 0, 0x1.666666p-1f, 0, 0,
                               0x1.111116p-3f, 0x1.9999ap-4f, -0x1.0699b2p+0f, -0x1p+0f,
                               0, 0, -0x1.6b053p+0f, 0};
  checkMatrix(GL_PROJECTION_MATRIX, offCentre);
}
