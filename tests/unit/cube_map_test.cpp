// Cube map textures (OpenGL 1.3, section 3.8.6): face selection, the targets and their errors,
// cube completeness, and GL_REFLECTION_MAP / GL_NORMAL_MAP generation.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include "pipeline_test_support.h"
#include "texture/cube_map.h"

using glass::gl::cubeFaceCoordinates;
using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

// Defines face `face` of the bound cube map as 2 x 2 texels of one colour.
void solidFace(int face, GLubyte r, GLubyte g, GLubyte b) {
  GLubyte texels[4][3];
  for (auto& t : texels) {
    t[0] = r;
    t[1] = g;
    t[2] = b;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE,
               texels);
}

// A quad filling the 4 x 4 window with texture coordinates (s, t, r) at every corner.
Rgba drawWithDirection(float s, float t, float r) {
  pixelProjection(4, 4);
  glColor3f(1.0f, 1.0f, 1.0f);
  glTexCoord3f(s, t, r);
  glRectf(0, 0, 4, 4);
  return pixelAt(1, 1);
}

}  // namespace

TEST_CASE("Cube map faces are chosen by the major axis, with table 3.19's (sc, tc)") {
  auto c = cubeFaceCoordinates(2.0f, 1.0f, -1.0f);  // +x: sc = -rz, tc = -ry
  CHECK(c.face == 0);
  CHECK(c.s == doctest::Approx(0.75f));
  CHECK(c.t == doctest::Approx(0.25f));
  c = cubeFaceCoordinates(-2.0f, 1.0f, -1.0f);  // -x: sc = rz, tc = -ry
  CHECK(c.face == 1);
  CHECK(c.s == doctest::Approx(0.25f));
  c = cubeFaceCoordinates(0.5f, 1.0f, 0.5f);  // +y: sc = rx, tc = rz
  CHECK(c.face == 2);
  CHECK(c.t == doctest::Approx(0.75f));
  c = cubeFaceCoordinates(0.5f, -1.0f, 0.5f);  // -y: tc = -rz
  CHECK(c.face == 3);
  CHECK(c.t == doctest::Approx(0.25f));
  c = cubeFaceCoordinates(0.5f, 0.0f, 1.0f);  // +z: sc = rx
  CHECK(c.face == 4);
  CHECK(c.s == doctest::Approx(0.75f));
  c = cubeFaceCoordinates(0.5f, 0.0f, -1.0f);  // -z: sc = -rx
  CHECK(c.face == 5);
  CHECK(c.s == doctest::Approx(0.25f));
}

TEST_CASE("Cube map targets, errors and queries") {
  ScopedContext context;
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_CUBE_MAP, name);
  GLint value = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &value);
  CHECK(value == static_cast<GLint>(name));
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &value);
  CHECK(value >= 16);
  glBindTexture(GL_TEXTURE_2D, name);  // a cube map is not a 2D texture
  CHECK(glGetError() == GL_INVALID_OPERATION);

  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_INVALID_ENUM);
  const GLenum negativeY = GL_TEXTURE_CUBE_MAP_NEGATIVE_Y;
  glTexImage2D(negativeY, 0, GL_RGB, 4, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_INVALID_VALUE);  // faces are square
  glTexImage2D(negativeY, 0, GL_RGBA, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  CHECK(glGetError() == GL_NO_ERROR);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_TEXTURE_WIDTH, &value);
  CHECK(value == 4);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_TEXTURE_WIDTH, &value);
  CHECK(value == 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, &value);
  CHECK(value == GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_WRAP_S, GL_REPEAT);
  CHECK(glGetError() == GL_INVALID_ENUM);  // a face is not a texture target

  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &value);
  CHECK(value == 8);

  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  CHECK(glGetError() == GL_NO_ERROR);
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);  // s, t and r only
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  CHECK(glGetError() == GL_INVALID_ENUM);

  glEnable(GL_TEXTURE_CUBE_MAP);
  CHECK(glIsEnabled(GL_TEXTURE_CUBE_MAP) == GL_TRUE);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glPopAttrib();
  CHECK(glIsEnabled(GL_TEXTURE_CUBE_MAP) == GL_TRUE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("A cube map is sampled on the face its direction points at, once cube complete") {
  ScopedContext context(4, 4);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_CUBE_MAP, name);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_CUBE_MAP);
  for (int face = 0; face < 5; ++face) solidFace(face, static_cast<GLubyte>(40 * face), 100, 200);
  // Five faces: not cube complete, so texturing is off (the fragment keeps its white).
  CHECK(drawWithDirection(0.1f, 0.2f, -1.0f) == Rgba{255, 255, 255, 255});
  solidFace(5, 250, 10, 20);
  CHECK(drawWithDirection(0.1f, 0.2f, -1.0f) == Rgba{250, 10, 20, 255});
  CHECK(drawWithDirection(0.1f, -3.0f, 0.5f) == Rgba{120, 100, 200, 255});  // -y, face 3
  CHECK(drawWithDirection(2.0f, 0.5f, 0.5f) == Rgba{0, 100, 200, 255});     // +x, face 0
  // The cube map takes precedence over GL_TEXTURE_2D (spec 3.8.15).
  glEnable(GL_TEXTURE_2D);
  CHECK(drawWithDirection(-2.0f, 0.5f, 0.5f) == Rgba{40, 100, 200, 255});
  // A face of another size breaks cube completeness.
  const GLenum positiveZ = GL_TEXTURE_CUBE_MAP_POSITIVE_Z;
  glTexImage2D(positiveZ, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  glDisable(GL_TEXTURE_2D);
  CHECK(drawWithDirection(-2.0f, 0.5f, 0.5f) == Rgba{255, 255, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("GL_NORMAL_MAP and GL_REFLECTION_MAP generate eye-space vectors") {
  ScopedContext context(4, 4);
  // The raster position carries the generated coordinates of unit 0.
  for (GLenum coord : {GL_S, GL_T, GL_R}) glTexGeni(coord, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glNormal3f(0.0f, 0.6f, 0.8f);
  glRasterPos3f(0.0f, 0.0f, -0.5f);
  GLfloat tc[4];
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tc);
  CHECK(tc[0] == doctest::Approx(0.0f));
  CHECK(tc[1] == doctest::Approx(0.6f));
  CHECK(tc[2] == doctest::Approx(0.8f));
  CHECK(tc[3] == 1.0f);
  // Looking down -z at a surface facing +z: the reflection points back at the eye.
  for (GLenum coord : {GL_S, GL_T, GL_R}) glTexGeni(coord, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glRasterPos3f(0.0f, 0.0f, -0.5f);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tc);
  CHECK(tc[0] == doctest::Approx(0.0f));
  CHECK(tc[1] == doctest::Approx(0.0f));
  CHECK(tc[2] == doctest::Approx(1.0f));
  CHECK(glGetError() == GL_NO_ERROR);
}
