// Three-dimensional textures (OpenGL 1.2, sections 3.8.1, 3.8.2 and 3.8.8): the commands and their
// errors, unpacking with GL_UNPACK_IMAGE_HEIGHT and GL_UNPACK_SKIP_IMAGES, read-back, copies,
// completeness and lookups along r.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// A 2 x 2 x 4 RGB volume whose slice k is the grey 60 k + 10 (all texels of a slice alike).
std::vector<GLubyte> greySlices() {
  std::vector<GLubyte> v;
  for (int k = 0; k < 4; ++k)
    for (int n = 0; n < 4 * 3; ++n) v.push_back(static_cast<GLubyte>(60 * k + 10));
  return v;
}

Rgba drawAtR(float r) {
  pixelProjection(4, 4);
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexCoord3f(0.5f, 0.5f, r);
  glRectf(0, 0, 4, 4);
  return pixelAt(1, 1);
}

}  // namespace

TEST_CASE("glTexImage3D and friends: errors and queries") {
  ScopedContext context;
  GLint value = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &value);
  CHECK(value == 2048);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_3D, name);
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &value);
  CHECK(value == static_cast<GLint>(name));
  const std::vector<GLubyte> texels = greySlices();
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 4, 2, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  CHECK(glGetError() == GL_INVALID_VALUE);  // border 2
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4096, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_INVALID_VALUE);  // beyond GL_MAX_3D_TEXTURE_SIZE
  glTexImage3D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  CHECK(glGetError() == GL_NO_ERROR);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &value);
  CHECK(value == 4);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 3, 2, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  CHECK(glGetError() == GL_INVALID_VALUE);  // slices 3 and 4 of 4
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGB, 8, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &value);
  CHECK(value == 8);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &value);
  CHECK(value == GL_CLAMP_TO_EDGE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("3D images unpack slice by slice and read back; glTexSubImage3D and glCopyTexSubImage3D") {
  ScopedContext context(4, 4);
  // Three slices of 1 x 2 luminance texels, stored 3 rows apart (GL_UNPACK_IMAGE_HEIGHT), after
  // one skipped image.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  // Each image is 3 rows of 1 texel: rows 0 and 1 are the slice, row 2 is padding.
  const GLubyte volume[3 * 4] = {0, 0, 0, 10, 11, 0, 20, 21, 0, 30, 31, 0};
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 1, 2, 3, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
               volume);
  // The 3D layout is state a program (or GLU) can read back (table 6.23).
  GLint imageHeight = 0, skipImages = 0, packImageHeight = -1;
  glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
  glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &skipImages);
  glGetIntegerv(GL_PACK_IMAGE_HEIGHT, &packImageHeight);
  CHECK(imageHeight == 3);
  CHECK(skipImages == 1);
  CHECK(packImageHeight == 0);
  CHECK(glGetError() == GL_NO_ERROR);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  GLubyte back[6] = {};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, back);
  const GLubyte expected[6] = {10, 11, 20, 21, 30, 31};
  for (int i = 0; i < 6; ++i) CHECK(back[i] == expected[i]);

  const GLubyte patch[2] = {77, 78};
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 1, 2, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, patch);
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 1, 2, 0, 0, 1, 1);  // slice 2, row 1
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, back);
  CHECK(back[2] == 77);
  CHECK(back[3] == 78);
  CHECK(back[5] == 51);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("3D lookups: NEAREST picks a slice, LINEAR mixes two, GL_GENERATE_MIPMAP reduces r too") {
  ScopedContext context(4, 4);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_3D, name);
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<GLubyte> texels = greySlices();
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  // The default minification filter needs mipmaps: incomplete, so the fragment stays white.
  CHECK(drawAtR(0.4f).r == 255);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  CHECK(drawAtR(0.4f).r == 70);   // floor(0.4 * 4) = slice 1
  CHECK(drawAtR(0.9f).r == 190);  // slice 3
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  // w = 0.5 * 4 - 1/2 = 1.5: halfway between slices 1 and 2.
  CHECK(drawAtR(0.5f).r == 100);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  CHECK(drawAtR(1.5f).r == 190);

  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  GLint value = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 2, GL_TEXTURE_DEPTH, &value);
  CHECK(value == 1);
  GLubyte last[3] = {};
  glGetTexImage(GL_TEXTURE_3D, 2, GL_RGB, GL_UNSIGNED_BYTE, last);
  CHECK(last[0] == 100);  // the mean of 10, 70, 130 and 190
  CHECK(glGetError() == GL_NO_ERROR);
}
