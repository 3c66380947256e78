// GLU 1.3's utility additions: gluCheckExtension, gluUnProject4, gluBuild*MipmapLevels,
// gluBuild3DMipmaps (every level, as libGLU builds them), and the error strings of the tessellator.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glu.h>

#include <cstring>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

const GLubyte* text(const char* s) { return reinterpret_cast<const GLubyte*>(s); }

GLint levelWidth(GLenum target, GLint level) {
  GLint width = -1;
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &width);
  return width;
}

}  // namespace

TEST_CASE("gluCheckExtension matches whole names only") {
  const GLubyte* list = text("GL_ARB_multitexture GL_EXT_abgr  GL_EXT_blend_color");
  CHECK(gluCheckExtension(text("GL_EXT_abgr"), list) == GL_TRUE);
  CHECK(gluCheckExtension(text("GL_EXT_blend_color"), list) == GL_TRUE);
  CHECK(gluCheckExtension(text("GL_ARB_multitexture"), list) == GL_TRUE);
  CHECK(gluCheckExtension(text("GL_EXT_blend"), list) == GL_FALSE);
  CHECK(gluCheckExtension(text("abgr"), list) == GL_FALSE);
  CHECK(gluCheckExtension(text(""), list) == GL_FALSE);
  CHECK(gluCheckExtension(text("GL_EXT_abgr GL_EXT_blend_color"), list) == GL_FALSE);
  CHECK(gluCheckExtension(text("GL_EXT_abgr"), nullptr) == GL_FALSE);
}

TEST_CASE("gluUnProject4 inverts the projection without dividing by w") {
  GLdouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const GLint view[4] = {0, 0, 100, 50};
  GLdouble x, y, z, w;
  // Window (75, 25) is NDC (0.5, 0); depth 0.5 of [0, 1] is 0; w 2 scales everything.
  REQUIRE(gluUnProject4(75, 25, 0.5, 2.0, identity, identity, view, 0.0, 1.0, &x, &y, &z, &w) ==
          GLU_TRUE);
  CHECK(x == doctest::Approx(0.5));
  CHECK(y == doctest::Approx(0.0));
  CHECK(z == doctest::Approx(0.0));
  CHECK(w == doctest::Approx(2.0));
  // The depth range: 0.75 in [0.5, 1] is NDC 0.
  REQUIRE(gluUnProject4(75, 25, 0.75, 1.0, identity, identity, view, 0.5, 1.0, &x, &y, &z, &w) ==
          GLU_TRUE);
  CHECK(z == doctest::Approx(0.0));
  GLdouble singular[16] = {};
  CHECK(gluUnProject4(0, 0, 0, 1, singular, identity, view, 0, 1, &x, &y, &z, &w) == GLU_FALSE);
}

TEST_CASE("gluBuild2DMipmapLevels loads levels base to max from the given level") {
  ScopedContext context;
  std::vector<GLubyte> image(8 * 4 * 4, 200);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  // The image is level 1 (8 x 4); levels 1 .. 4 exist below it; load 2 .. 3 only.
  CHECK(gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, 1, 2, 3,
                               image.data()) == 0);
  CHECK(levelWidth(GL_TEXTURE_2D, 1) == 0);
  CHECK(levelWidth(GL_TEXTURE_2D, 2) == 4);
  CHECK(levelWidth(GL_TEXTURE_2D, 3) == 2);
  CHECK(levelWidth(GL_TEXTURE_2D, 4) == 0);
  // base below level, max beyond the last level (1 + log2 8 = 4), max below base.
  CHECK(gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, 1, 0, 3,
                               image.data()) == GLU_INVALID_VALUE);
  CHECK(gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, 1, 1, 5,
                               image.data()) == GLU_INVALID_VALUE);
  CHECK(gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0, 2, 1,
                               image.data()) == GLU_INVALID_VALUE);
  CHECK(gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 8, 4, 0x1234, GL_UNSIGNED_BYTE, 0, 0, 1,
                               image.data()) == GLU_INVALID_ENUM);
  CHECK(gluBuild1DMipmapLevels(GL_TEXTURE_1D, GL_RGBA, 8, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3,
                               image.data()) == 0);
  CHECK(levelWidth(GL_TEXTURE_1D, 3) == 1);
  CHECK(glGetError() == GL_NO_ERROR);
  glDeleteTextures(1, &texture);
}

TEST_CASE("gluBuild3DMipmaps checks its arguments, then loads every level of the 3D texture, as libGLU builds them") {
  ScopedContext context;
  std::vector<GLubyte> image(4 * 4 * 4 * 4, 0);
  CHECK(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.data()) == GLU_INVALID_VALUE);
  CHECK(gluBuild3DMipmaps(GL_TEXTURE_2D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.data()) == GLU_INVALID_ENUM);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.data()) == 0);
  CHECK(glGetError() == GL_NO_ERROR);
  GLint depth = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &depth);
  CHECK(depth == 4);
  // The smaller levels down to 1 x 1 x 1, each texel the average of the 2 x 2 x 2 block above it.
  for (size_t i = 0; i < image.size(); i += 4) image[i] = (i / 4) % 2 == 0 ? 255 : 51;  // red
  CHECK(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.data()) == 0);
  for (int level = 1; level <= 2; ++level) {
    GLint side = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_DEPTH, &side);
    CHECK(side == 4 >> level);
  }
  GLubyte smallest[4] = {};
  glGetTexImage(GL_TEXTURE_3D, 2, GL_RGBA, GL_UNSIGNED_BYTE, smallest);
  CHECK(smallest[0] == 153);  // (255 + 51) / 2
  GLint generate = GL_TRUE;
  glGetTexParameteriv(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, &generate);
  CHECK(generate == GL_FALSE);  // GLU builds the levels itself
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0, 1,
                               0, image.data()) == GLU_INVALID_VALUE);

  // Sides that are not powers of two are resampled to GLU's nearest ones: 6 x 5 x 3 -> 8 x 4 x 4,
  // then halved down to 1 x 1 x 1 (level 3); a uniform image stays uniform.
  const std::vector<GLubyte> uniform(6 * 5 * 3 * 4, 200);
  CHECK(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, 6, 5, 3, GL_RGBA, GL_UNSIGNED_BYTE, uniform.data()) == 0);
  CHECK(glGetError() == GL_NO_ERROR);
  GLint height = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &height);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &depth);
  CHECK(levelWidth(GL_TEXTURE_3D, 0) == 8);
  CHECK(height == 4);
  CHECK(depth == 4);
  CHECK(levelWidth(GL_TEXTURE_3D, 3) == 1);
  glGetTexImage(GL_TEXTURE_3D, 3, GL_RGBA, GL_UNSIGNED_BYTE, smallest);
  CHECK(smallest[0] == 200);

  // gluBuild3DMipmapLevels builds the chain from its level, loading base to max.
  GLuint levels = 0;
  glGenTextures(1, &levels);
  glBindTexture(GL_TEXTURE_3D, levels);
  CHECK(gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, 4, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0, 1, 2, image.data()) ==
        0);
  CHECK(levelWidth(GL_TEXTURE_3D, 0) == 0);  // below base: not loaded
  CHECK(levelWidth(GL_TEXTURE_3D, 1) == 2);
  glGetTexImage(GL_TEXTURE_3D, 2, GL_RGBA, GL_UNSIGNED_BYTE, smallest);
  CHECK(smallest[0] == 153);
  CHECK(glGetError() == GL_NO_ERROR);
  glDeleteTextures(1, &levels);
}

TEST_CASE("gluErrorString knows the tessellator's and the NURBS errors") {
  const char* combine = reinterpret_cast<const char*>(gluErrorString(GLU_TESS_NEED_COMBINE_CALLBACK));
  REQUIRE(combine != nullptr);
  CHECK(std::strstr(combine, "combine") != nullptr);
  CHECK(gluErrorString(GLU_TESS_MISSING_BEGIN_POLYGON) != nullptr);
  CHECK(gluErrorString(GLU_NURBS_ERROR1) != nullptr);
  CHECK(gluErrorString(GLU_NURBS_ERROR37) != nullptr);
  CHECK(gluErrorString(GLU_NURBS_ERROR37 + 1) == nullptr);
}
