// Texture units (OpenGL 1.3, spec 2.7, 2.8, 3.8.17), GL_COMBINE (3.8.13) and the level-of-detail
// bias (1.4): per-unit state and its queries, the errors, glPushAttrib / glPushClientAttrib,
// display lists, and the combined colour of a fragment.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cstdlib>

#include "pipeline_test_support.h"

using glass::test::pixelAt;
using glass::test::pixelProjection;
using glass::test::Rgba;
using glass::test::ScopedContext;

namespace {

GLint integerState(GLenum pname) {
  GLint v[4] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

GLint envInteger(GLenum pname) {
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, pname, &v);
  return v;
}

// A 1 x 1 texture of one colour, GL_NEAREST, bound to the active unit's GL_TEXTURE_2D and enabled.
GLuint solidTexture(GLenum internalFormat, const GLubyte rgba[4]) {
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), 1, 1, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, rgba);
  glEnable(GL_TEXTURE_2D);
  return name;
}

// Fills the 4 x 4 window with one quad of the given primary colour and reads the middle pixel.
Rgba drawQuad(const GLfloat color[4]) {
  pixelProjection(4, 4);
  glColor4fv(color);
  glRectf(0, 0, 4, 4);
  return pixelAt(2, 2);
}

bool near(int value, int expected) { return std::abs(value - expected) <= 1; }

}  // namespace

TEST_CASE("Each texture unit has its own binding, enables, environment, texgen and matrix") {
  ScopedContext context;
  GLuint names[2];
  glGenTextures(2, names);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glActiveTexture(GL_TEXTURE3);
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE3);
  CHECK(integerState(GL_TEXTURE_BINDING_2D) == 0);
  CHECK(glIsEnabled(GL_TEXTURE_2D) == GL_FALSE);
  CHECK(envInteger(GL_TEXTURE_ENV_MODE) == GL_MODULATE);
  glBindTexture(GL_TEXTURE_2D, names[1]);
  glEnable(GL_TEXTURE_GEN_S);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(1.0f, 2.0f, 3.0f);
  glPushMatrix();
  CHECK(integerState(GL_TEXTURE_STACK_DEPTH) == 2);
  glMultiTexCoord2f(GL_TEXTURE3, 0.5f, 0.25f);

  glActiveTexture(GL_TEXTURE0);
  CHECK(integerState(GL_TEXTURE_BINDING_2D) == static_cast<GLint>(names[0]));
  CHECK(glIsEnabled(GL_TEXTURE_2D) == GL_TRUE);
  CHECK(glIsEnabled(GL_TEXTURE_GEN_S) == GL_FALSE);
  CHECK(envInteger(GL_TEXTURE_ENV_MODE) == GL_DECAL);
  CHECK(integerState(GL_TEXTURE_STACK_DEPTH) == 1);
  GLfloat m[16];
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  CHECK(m[12] == 0.0f);
  GLfloat tc[4];
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.0f);

  glActiveTexture(GL_TEXTURE3);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  CHECK(m[12] == 1.0f);
  CHECK(m[13] == 2.0f);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.5f);
  CHECK(tc[1] == 0.25f);
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  CHECK(mode == GL_SPHERE_MAP);
  CHECK(glIsEnabled(GL_TEXTURE_GEN_S) == GL_TRUE);
  CHECK(glGetError() == GL_NO_ERROR);

  // Deleting a texture bound in two units binds the default texture in both (spec 3.8.12).
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, names[1]);
  glDeleteTextures(1, &names[1]);
  CHECK(integerState(GL_TEXTURE_BINDING_2D) == 0);
  glActiveTexture(GL_TEXTURE3);
  CHECK(integerState(GL_TEXTURE_BINDING_2D) == 0);
}

TEST_CASE("glClientActiveTexture selects the texture coordinate array of a unit") {
  ScopedContext context;
  const GLfloat a[8] = {}, b[8] = {};
  glClientActiveTexture(GL_TEXTURE2);
  CHECK(integerState(GL_CLIENT_ACTIVE_TEXTURE) == GL_TEXTURE2);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(3, GL_SHORT, 6, a);
  glClientActiveTexture(GL_TEXTURE0);
  CHECK(glIsEnabled(GL_TEXTURE_COORD_ARRAY) == GL_FALSE);
  glTexCoordPointer(2, GL_FLOAT, 0, b);
  CHECK(integerState(GL_TEXTURE_COORD_ARRAY_SIZE) == 2);

  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glClientActiveTexture(GL_TEXTURE2);
  CHECK(glIsEnabled(GL_TEXTURE_COORD_ARRAY) == GL_TRUE);
  CHECK(integerState(GL_TEXTURE_COORD_ARRAY_SIZE) == 3);
  CHECK(integerState(GL_TEXTURE_COORD_ARRAY_TYPE) == GL_SHORT);
  CHECK(integerState(GL_TEXTURE_COORD_ARRAY_STRIDE) == 6);
  GLvoid* pointer = nullptr;
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
  CHECK(pointer == a);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glPopClientAttrib();
  CHECK(integerState(GL_CLIENT_ACTIVE_TEXTURE) == GL_TEXTURE0);
  glClientActiveTexture(GL_TEXTURE2);
  CHECK(glIsEnabled(GL_TEXTURE_COORD_ARRAY) == GL_TRUE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("GL_TEXTURE_BIT and GL_ENABLE_BIT save every unit; GL_TEXTURE_BIT the active unit") {
  ScopedContext context;
  glActiveTexture(GL_TEXTURE5);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
  glPushAttrib(GL_TEXTURE_BIT);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_GEN_Q);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glPopAttrib();  // the enables of every unit; the active unit stays GL_TEXTURE1
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE1);
  CHECK(glIsEnabled(GL_TEXTURE_2D) == GL_FALSE);
  glActiveTexture(GL_TEXTURE5);
  CHECK(glIsEnabled(GL_TEXTURE_1D) == GL_TRUE);
  CHECK(glIsEnabled(GL_TEXTURE_GEN_Q) == GL_FALSE);

  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
  glActiveTexture(GL_TEXTURE2);
  glPopAttrib();  // GL_TEXTURE_BIT: the active unit is GL_TEXTURE5 again
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE5);
  CHECK(envInteger(GL_COMBINE_RGB) == GL_DOT3_RGB);
  GLfloat scale = 0.0f;
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, &scale);
  CHECK(scale == 1.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Display lists compile glActiveTexture and glMultiTexCoord, not glClientActiveTexture") {
  ScopedContext context;
  glNewList(1, GL_COMPILE);
  glActiveTexture(GL_TEXTURE2);
  glMultiTexCoord3f(GL_TEXTURE4, 1.0f, 2.0f, 3.0f);
  glClientActiveTexture(GL_TEXTURE6);  // client state: executed now (spec 5.4)
  glEndList();
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE0);
  CHECK(integerState(GL_CLIENT_ACTIVE_TEXTURE) == GL_TEXTURE6);
  glCallList(1);
  CHECK(integerState(GL_ACTIVE_TEXTURE) == GL_TEXTURE2);
  glActiveTexture(GL_TEXTURE4);
  GLfloat tc[4];
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  CHECK(tc[2] == 3.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("GL_COMBINE parameters: defaults, queries and errors") {
  ScopedContext context;
  glActiveTexture(GL_TEXTURE1);
  CHECK(envInteger(GL_COMBINE_RGB) == GL_MODULATE);
  CHECK(envInteger(GL_COMBINE_ALPHA) == GL_MODULATE);
  CHECK(envInteger(GL_SOURCE0_RGB) == GL_TEXTURE);
  CHECK(envInteger(GL_SOURCE1_RGB) == GL_PREVIOUS);
  CHECK(envInteger(GL_SOURCE2_ALPHA) == GL_CONSTANT);
  CHECK(envInteger(GL_OPERAND0_RGB) == GL_SRC_COLOR);
  CHECK(envInteger(GL_OPERAND2_RGB) == GL_SRC_ALPHA);
  CHECK(envInteger(GL_OPERAND1_ALPHA) == GL_SRC_ALPHA);

  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE7);  // the GL 1.4 crossbar
  CHECK(envInteger(GL_SOURCE2_RGB) == GL_TEXTURE7);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE8);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);  // RGB only
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);  // alpha operands are alphas
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 3.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  CHECK(envInteger(GL_SOURCE2_RGB) == GL_TEXTURE7);
  CHECK(envInteger(GL_COMBINE_ALPHA) == GL_MODULATE);

  // The level-of-detail bias of a unit and of a texture (OpenGL 1.4).
  GLfloat value = 0.0f;
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &value);
  CHECK(value == 16.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -2.5f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &value);
  CHECK(value == -2.5f);
  glActiveTexture(GL_TEXTURE0);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &value);
  CHECK(value == 0.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.25f);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &value);
  CHECK(value == 1.25f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Units apply in order, each on the previous unit's result") {
  ScopedContext context(4, 4);
  const GLubyte half[4] = {128, 255, 64, 255};
  const GLubyte quarter[4] = {255, 64, 255, 128};
  glActiveTexture(GL_TEXTURE0);
  solidTexture(GL_RGBA, half);
  glActiveTexture(GL_TEXTURE2);  // unit 1 stays off and passes its input on
  solidTexture(GL_RGBA, quarter);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  const GLfloat color[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  // Unit 0 modulates: (64, 128, 32, 255); unit 2 adds: (255, 192, 255, 128).
  const Rgba p = drawQuad(color);
  CHECK(near(p.r, 255));
  CHECK(near(p.g, 192));
  CHECK(near(p.b, 255));
  CHECK(near(p.a, 128));
}

TEST_CASE("GL_COMBINE functions, sources and scales on one fragment") {
  ScopedContext context(4, 4);
  const GLubyte texel[4] = {204, 102, 51, 153};  // (0.8, 0.4, 0.2, 0.6)
  const GLfloat primary[4] = {0.5f, 0.25f, 1.0f, 0.5f};
  const GLfloat constant[4] = {0.2f, 0.6f, 0.4f, 1.0f};
  solidTexture(GL_RGBA, texel);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR);

  SUBCASE("ADD_SIGNED with RGB_SCALE 2; SUBTRACT of alphas") {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT);
    const Rgba p = drawQuad(primary);
    CHECK(near(p.r, 255));       // 2 (0.8 + 0.5 - 0.5) = 1.6, clamped
    CHECK(near(p.g, 77));        // 2 (0.4 + 0.25 - 0.5) = 0.3
    CHECK(near(p.b, 255));       // 2 (0.2 + 1 - 0.5) = 1.4, clamped
    CHECK(near(p.a, 26));        // 0.6 - 0.5 = 0.1
  }
  SUBCASE("INTERPOLATE with the constant as weight, operands inverted") {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0f);
    const Rgba p = drawQuad(primary);
    CHECK(near(p.r, 112));  // (1 - 0.8) 0.2 + 0.5 (1 - 0.2) = 0.44
    CHECK(near(p.g, 117));  // (1 - 0.4) 0.6 + 0.25 (1 - 0.6) = 0.46
    CHECK(near(p.a, 204));  // 2 (1 - 0.6) = 0.8
  }
  SUBCASE("DOT3_RGBA puts the dot product in every component") {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
    const Rgba p = drawQuad(primary);
    // 4 ((0.8 - .5)(0.5 - .5) + (0.4 - .5)(0.25 - .5) + (0.2 - .5)(1 - .5)) = 4 (0.025 - 0.15) < 0
    CHECK(p.r == 0);
    CHECK(p.a == 0);
  }
  SUBCASE("The crossbar reads another unit's texel") {
    const GLubyte other[4] = {0, 255, 128, 255};
    glActiveTexture(GL_TEXTURE1);
    solidTexture(GL_RGBA, other);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE1);
    const Rgba p = drawQuad(primary);
    CHECK(near(p.r, 128));  // 0 + 0.5
    CHECK(near(p.g, 255));  // 1 + 0.25, clamped
    CHECK(near(p.b, 255));
  }
}

TEST_CASE("The raster position keeps every unit's texture coordinates") {
  ScopedContext context;
  glMultiTexCoord2f(GL_TEXTURE1, 0.5f, 0.75f);
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glScalef(2.0f, 2.0f, 1.0f);
  glRasterPos2f(0.0f, 0.0f);
  GLfloat tc[4];
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 1.0f);
  CHECK(tc[1] == 1.5f);
  glActiveTexture(GL_TEXTURE0);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tc);
  CHECK(tc[0] == 0.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}
