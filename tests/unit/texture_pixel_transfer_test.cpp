// The pixel transfer operations on texture images (OpenGL 1.4 specification, sections 3.8.1 and
// 3.8.2): glTexImage, glTexSubImage, glCopyTexImage and glCopyTexSubImage take their groups through
// scale and bias, the GL_MAP_COLOR lookups and the imaging subset, as glDrawPixels and
// glCopyPixels do. Every expected texel is worked out by hand here and read back with
// glGetTexImage.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

// An RGBA texel as glGetTexImage returns it.
struct Texel {
  GLubyte r, g, b, a;
};

std::vector<Texel> texImage2D(int width, int height) {
  std::vector<Texel> texels(static_cast<size_t>(width) * static_cast<size_t>(height));
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  return texels;
}

GLint levelParameter(GLenum target, GLenum pname) {
  GLint value = -1;
  glGetTexLevelParameteriv(target, 0, pname, &value);
  return value;
}

// Two RGBA texels: (200, 0, 40, 255) and (0, 100, 255, 128).
const GLubyte kTwoTexels[8] = {200, 0, 40, 255, 0, 100, 255, 128};

// A 4 x 3 luminance image, row 0 first: 8 16 24 32 / 40 48 56 64 / 72 80 88 96.
const GLubyte kImage[12] = {8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96};

// A 3 x 3 luminance filter: 0.25 at the four neighbours of the centre, 0 elsewhere.
const GLfloat kCross[9] = {0, 0.25f, 0, 0.25f, 0, 0.25f, 0, 0.25f, 0};

}  // namespace

TEST_CASE("texture pixel transfer: scale and bias apply to glTexImage2D and glTexSubImage2D") {
  ScopedContext context(8, 8);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  std::vector<Texel> t = texImage2D(2, 1);
  // Red 200 * 0.5 = 100; green 0 + 0.25 * 255 = 63.75 -> 64 and 100 + 63.75 -> 164.
  CHECK(t[0].r == 100);
  CHECK(t[0].g == 64);
  CHECK(t[0].b == 40);
  CHECK(t[0].a == 255);
  CHECK(t[1].r == 0);
  CHECK(t[1].g == 164);
  CHECK(t[1].b == 255);
  CHECK(t[1].a == 128);

  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferf(GL_BLUE_SCALE, 2.0f);  // 40 -> 80; 255 clamps at 255
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  t = texImage2D(2, 1);
  CHECK(t[0].r == 100);
  CHECK(t[0].g == 0);
  CHECK(t[0].b == 80);
  CHECK(t[1].b == 255);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("texture pixel transfer: GL_MAP_COLOR looks components up in the pixel maps") {
  ScopedContext context(8, 8);
  const GLfloat invert[2] = {1.0f, 0.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  // The other maps keep their single entry 0: green, blue and alpha become 0.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  const std::vector<Texel> t = texImage2D(2, 1);
  // Red 200/255 selects entry round(0.784 * 1) = 1 -> 0; red 0 selects entry 0 -> 1.
  CHECK(t[0].r == 0);
  CHECK(t[1].r == 255);
  CHECK(t[0].g == 0);
  CHECK(t[1].a == 0);
}

TEST_CASE("texture pixel transfer: a compiled glTexImage2D uses the transfer state of execution") {
  ScopedContext context(8, 8);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  glEndList();
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glCallList(list);
  std::vector<Texel> t = texImage2D(2, 1);
  CHECK(t[0].r == 100);
  CHECK(t[0].b == 40);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glCallList(list);
  t = texImage2D(2, 1);
  CHECK(t[0].r == 200);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("texture pixel transfer: a GL_REDUCE convolution makes the texture image smaller") {
  ScopedContext context(8, 8);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, kCross);
  glEnable(GL_CONVOLUTION_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 3, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, kImage);
  CHECK(glGetError() == GL_NO_ERROR);
  // A 4 x 3 image under a 3 x 3 filter leaves 2 x 1 groups (spec 3.6.5, GL_REDUCE).
  CHECK(levelParameter(GL_TEXTURE_2D, GL_TEXTURE_WIDTH) == 2);
  CHECK(levelParameter(GL_TEXTURE_2D, GL_TEXTURE_HEIGHT) == 1);
  GLubyte luminance[2] = {0, 0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, luminance);
  // Around (1, 1): (16 + 40 + 56 + 80) / 4 = 48; around (2, 1): (24 + 48 + 64 + 88) / 4 = 56.
  CHECK(luminance[0] == 48);
  CHECK(luminance[1] == 56);

  // A three-dimensional image is never convolved: it keeps its 4 x 3 x 1 size and its values.
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 4, 3, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, kImage);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(levelParameter(GL_TEXTURE_3D, GL_TEXTURE_WIDTH) == 4);
  CHECK(levelParameter(GL_TEXTURE_3D, GL_TEXTURE_HEIGHT) == 3);
}

TEST_CASE("texture pixel transfer: the colour matrix applies to glCopyTexImage2D and glCopyTexSubImage2D") {
  ScopedContext context(8, 8);
  glClearColor(1.0f, 0.0f, 0.2f, 1.0f);  // (255, 0, 51, 255)
  glClear(GL_COLOR_BUFFER_BIT);
  // A colour matrix that swaps red and blue (column-major).
  const GLfloat swapRB[16] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  glMatrixMode(GL_COLOR);
  glLoadMatrixf(swapRB);
  glMatrixMode(GL_MODELVIEW);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 2, 2, 0);
  std::vector<Texel> t = texImage2D(2, 2);
  CHECK(t[3].r == 51);
  CHECK(t[3].g == 0);
  CHECK(t[3].b == 255);

  glMatrixMode(GL_COLOR);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPixelTransferf(GL_RED_SCALE, 0.0f);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 0, 0, 1, 1);
  t = texImage2D(2, 2);
  CHECK(t[0].r == 51);  // untouched
  CHECK(t[3].r == 0);   // red scaled to 0
  CHECK(t[3].b == 51);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("texture pixel transfer: a histogram sink takes the groups and leaves the texture as it was") {
  ScopedContext context(8, 8);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  glHistogram(GL_HISTOGRAM, 2, GL_RGBA, GL_TRUE);
  glEnable(GL_HISTOGRAM);
  const GLubyte white[8] = {255, 255, 255, 255, 255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  CHECK(glGetError() == GL_NO_ERROR);
  const std::vector<Texel> t = texImage2D(2, 1);
  CHECK(t[0].r == 200);
  CHECK(t[1].g == 100);
  // Both groups were counted in the upper bin of every component.
  GLuint counts[8] = {};
  glGetHistogram(GL_HISTOGRAM, GL_FALSE, GL_RGBA, GL_UNSIGNED_INT, counts);
  CHECK(counts[4] == 2);
  CHECK(counts[7] == 2);
  CHECK(counts[0] == 0);
}

TEST_CASE("texture pixel transfer: without any operation the texels are the client's bytes") {
  ScopedContext context(8, 8);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, kTwoTexels);
  const std::vector<Texel> t = texImage2D(2, 1);
  CHECK(t[0].r == 200);
  CHECK(t[0].b == 40);
  CHECK(t[1].g == 100);
  CHECK(t[1].a == 128);
}
