// Depth textures and their comparison (OpenGL 1.4, sections 3.8.1, 3.8.2, 3.8.4, 3.8.13 and
// 3.8.14; GL_ARB_depth_texture, GL_ARB_shadow, GL_EXT_shadow_funcs): the errors, the level
// queries, read-back, copies from the depth buffer, and lookups with and without comparison.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <vector>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// A 4 x 1 depth texture with the values 0.2, 0.4, 0.6, 0.8, nearest filtering, bound to 2D.
GLuint rampTexture() {
  const GLfloat depths[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  return name;
}

// Draws a 4 x 1 rectangle with s across the texture and the given r, white, and returns the
// four pixels.
std::vector<Rgba> drawRow(float r) {
  pixelProjection(4, 4);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_QUADS);
  glTexCoord3f(0.0f, 0.5f, r);
  glVertex2f(0, 0);
  glTexCoord3f(1.0f, 0.5f, r);
  glVertex2f(4, 0);
  glTexCoord3f(1.0f, 0.5f, r);
  glVertex2f(4, 1);
  glTexCoord3f(0.0f, 0.5f, r);
  glVertex2f(0, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  std::vector<Rgba> row;
  for (int x = 0; x < 4; ++x) row.push_back(pixelAt(x, 0));
  return row;
}

}  // namespace

TEST_CASE("depth textures: errors, parameters and level queries") {
  ScopedContext context(4, 4);
  const GLfloat one = 0.5f;
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  // Depth data only with a depth internal format and the other way round (3.8.1).
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_LUMINANCE, GL_FLOAT, &one);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_BITMAP, &one);
  CHECK(glGetError() == GL_INVALID_ENUM);
  // Only 1D and 2D targets take depth images.
  GLuint cube = 0;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, &one);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 1, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_DEPTH_COMPONENT, 0, 0, 1, 1, 0);
  CHECK(glGetError() == GL_INVALID_OPERATION);

  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  CHECK(glGetError() == GL_NO_ERROR);
  GLint value = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &value);
  CHECK(value == 16);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &value);
  CHECK(value == 0);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &value);
  CHECK(value == GL_DEPTH_COMPONENT16);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32, 8, 8, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_INT, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &value);
  CHECK(value == 24);
  // Sub-images: depth into depth only.
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_LUMINANCE, GL_FLOAT, &one);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  CHECK(glGetError() == GL_NO_ERROR);
  GLfloat readBack[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, readBack);
  CHECK(glGetError() == GL_INVALID_OPERATION);

  // The three parameters, their defaults (table 6.16) and their errors (3.8.4).
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &value);
  CHECK(value == GL_NONE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &value);
  CHECK(value == GL_LEQUAL);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &value);
  CHECK(value == GL_LUMINANCE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_RGBA);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ADD);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGB);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_ALPHA);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &value);
  CHECK(value == GL_COMPARE_R_TO_TEXTURE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &value);
  CHECK(value == GL_GREATER);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &value);
  CHECK(value == GL_ALPHA);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("depth textures: values read back as specified, with the depth scale and bias") {
  ScopedContext context(4, 4);
  const GLushort depths[4] = {0, 16384, 32768, 65535};
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_1D, name);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT24, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT,
               depths);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
  GLfloat back[4] = {};
  glGetTexImage(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(back[0] == doctest::Approx(0.25).epsilon(1e-6));
  CHECK(back[1] == doctest::Approx(0.25 + 0.5 * 16384.0 / 65535.0).epsilon(1e-6));
  CHECK(back[2] == doctest::Approx(0.25 + 0.5 * 32768.0 / 65535.0).epsilon(1e-6));
  CHECK(back[3] == doctest::Approx(0.75).epsilon(1e-6));
}

TEST_CASE("depth textures: glCopyTexImage2D and glCopyTexSubImage2D read the depth buffer") {
  ScopedContext context(4, 4);
  pixelProjection(4, 4);
  glEnable(GL_DEPTH_TEST);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  // z = 0 maps to depth 0.5 with the default depth range; the left half gets it.
  glRectf(0, 0, 2, 4);
  glDisable(GL_DEPTH_TEST);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glReadBuffer(GL_NONE);  // no colour buffer is read: a depth copy does not need one
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);
  CHECK(glGetError() == GL_NO_ERROR);
  glReadBuffer(GL_BACK);
  std::vector<GLfloat> back(16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back.data());
  // The depth buffer's 24-bit values, exactly.
  GLfloat half = 0.0f;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &half);
  CHECK(half == doctest::Approx(0.5).epsilon(1e-6));
  CHECK(back[0] == half);
  CHECK(back[1] == half);
  CHECK(back[2] == 1.0f);
  CHECK(back[15] == 1.0f);
  // A sub-image copy of the right column of the depth buffer into the left column.
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 3, 0, 1, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back.data());
  CHECK(back[0] == 1.0f);
  CHECK(back[1] == half);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("depth textures: sampled values and comparisons") {
  ScopedContext context(4, 4);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  rampTexture();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  // Without comparison: the depth as luminance (3.8.13).
  std::vector<Rgba> row = drawRow(0.5f);
  CHECK(row[0] == Rgba{51, 51, 51, 255});
  CHECK(row[3] == Rgba{204, 204, 204, 255});

  // r = 0.5 against 0.2, 0.4, 0.6, 0.8: LEQUAL passes for the last two texels.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  row = drawRow(0.5f);
  CHECK(row[0] == Rgba{0, 0, 0, 255});
  CHECK(row[1] == Rgba{0, 0, 0, 255});
  CHECK(row[2] == Rgba{255, 255, 255, 255});
  CHECK(row[3] == Rgba{255, 255, 255, 255});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
  row = drawRow(0.5f);
  CHECK(row[1] == Rgba{255, 255, 255, 255});
  CHECK(row[2] == Rgba{0, 0, 0, 255});
  // r is clamped to [0, 1] before the comparison.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  row = drawRow(-3.0f);
  CHECK(row[0] == Rgba{255, 255, 255, 255});
  // GL_EXT_shadow_funcs: NEVER and ALWAYS.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NEVER);
  CHECK(drawRow(0.5f)[3] == Rgba{0, 0, 0, 255});
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ALWAYS);
  CHECK(drawRow(0.5f)[0] == Rgba{255, 255, 255, 255});

  // The result as intensity and as alpha: with GL_REPLACE an alpha texture keeps the colour.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  row = drawRow(0.5f);
  CHECK(row[0] == Rgba{0, 0, 0, 0});
  CHECK(row[2] == Rgba{255, 255, 255, 255});
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  row = drawRow(0.5f);
  CHECK(row[0] == Rgba{255, 255, 255, 0});
  CHECK(row[2] == Rgba{255, 255, 255, 255});

  // Linear filtering weighs the comparisons (percentage closer): at the centre between texels 1
  // and 2 half of them pass.
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  pixelProjection(4, 4);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_POINTS);
  glTexCoord3f(0.5f, 0.5f, 0.5f);
  glVertex2f(1.5f, 2.5f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  const Rgba mixed = pixelAt(1, 2);
  CHECK((mixed.r == 127 || mixed.r == 128));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("depth textures: GL_GENERATE_MIPMAP averages depths") {
  ScopedContext context(4, 4);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const GLfloat depths[4] = {0.0f, 0.25f, 0.5f, 1.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  GLfloat level1 = -1.0f;
  glGetTexImage(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &level1);
  CHECK(level1 == doctest::Approx(0.4375).epsilon(1e-6));
  GLint bits = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_DEPTH_SIZE, &bits);
  CHECK(bits == 24);
}
