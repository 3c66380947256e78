// glLight, glLightModel, glMaterial, glColorMaterial and glFog through the C API: stored values,
// the transformation of positions and directions, colour material tracking, queries and the
// errors the specification lists.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <climits>
#include <cmath>
#include <limits>

namespace {

// A current 8 x 8 context for the length of a test.
struct ScopedContext {
  GlassContext* ctx;
  ScopedContext() : ctx(glassCreateContext(8, 8)) {
    REQUIRE(ctx != nullptr);
    REQUIRE(glassMakeCurrent(ctx) == 1);
  }
  ~ScopedContext() {
    glassMakeCurrent(nullptr);
    glassDestroyContext(ctx);
  }
};

void checkVector(const GLfloat* got, float x, float y, float z, float w) {
  CHECK(got[0] == doctest::Approx(x));
  CHECK(got[1] == doctest::Approx(y));
  CHECK(got[2] == doctest::Approx(z));
  CHECK(got[3] == doctest::Approx(w));
}

}  // namespace

TEST_CASE("glLight: defaults of table 2.10, GL_LIGHT0 white, the others black") {
  ScopedContext scope;
  GLfloat v[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
  checkVector(v, 1, 1, 1, 1);
  glGetLightfv(GL_LIGHT5, GL_DIFFUSE, v);
  checkVector(v, 0, 0, 0, 1);
  glGetLightfv(GL_LIGHT7, GL_POSITION, v);
  checkVector(v, 0, 0, 1, 0);
  glGetLightfv(GL_LIGHT2, GL_SPOT_CUTOFF, v);
  CHECK(v[0] == 180.0f);
  GLint maxLights = 0;
  glGetIntegerv(GL_MAX_LIGHTS, &maxLights);
  CHECK(maxLights >= 8);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glLight: the position takes the modelview matrix, the spot direction its 3x3 part") {
  ScopedContext scope;
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1.0f, 2.0f, 3.0f);
  glRotatef(90.0f, 0.0f, 0.0f, 1.0f);  // x -> y, y -> -x
  const GLfloat position[4] = {1.0f, 0.0f, 0.0f, 1.0f};
  const GLfloat direction[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  const GLfloat spot[3] = {0.0f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT1, GL_POSITION, position);
  glLightfv(GL_LIGHT2, GL_POSITION, direction);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot);
  GLfloat v[4];
  glGetLightfv(GL_LIGHT1, GL_POSITION, v);
  checkVector(v, 1.0f, 3.0f, 3.0f, 1.0f);  // rotated to (0, 1, 0), then translated
  glGetLightfv(GL_LIGHT2, GL_POSITION, v);
  checkVector(v, 0.0f, 1.0f, 0.0f, 0.0f);  // a direction: no translation
  glGetLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, v);
  CHECK(v[0] == doctest::Approx(-1.0f));
  CHECK(v[1] == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(v[2] == doctest::Approx(0.0f));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glLight: errors") {
  ScopedContext scope;
  glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glLightf(GL_LIGHT0, GL_POSITION, 1.0f);  // not a one-value parameter
  CHECK(glGetError() == GL_INVALID_ENUM);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
  CHECK(glGetError() == GL_NO_ERROR);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -0.5f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  GLfloat v[4] = {};
  glGetLightfv(GL_LIGHT0, GL_SHININESS, v);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glBegin(GL_TRIANGLES);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 1.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("glLightiv and glGetLightiv: colours map the integer range onto [-1, 1]") {
  ScopedContext scope;
  const GLint color[4] = {INT_MAX, 0, INT_MIN, INT_MAX};
  glLightiv(GL_LIGHT3, GL_AMBIENT, color);
  GLfloat v[4];
  glGetLightfv(GL_LIGHT3, GL_AMBIENT, v);
  CHECK(v[0] == doctest::Approx(1.0f));
  CHECK(v[1] == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(v[2] == doctest::Approx(-1.0f));
  GLint back[4];
  glGetLightiv(GL_LIGHT3, GL_AMBIENT, back);
  CHECK(back[0] == INT_MAX);
  glLighti(GL_LIGHT3, GL_SPOT_CUTOFF, 45);
  glGetLightiv(GL_LIGHT3, GL_SPOT_CUTOFF, back);
  CHECK(back[0] == 45);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glLightModel: values, queries and errors") {
  ScopedContext scope;
  const GLfloat ambient[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 5);
  glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 1.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  GLfloat v[4];
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  checkVector(v, 0.1f, 0.2f, 0.3f, 0.4f);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
  CHECK(b == GL_TRUE);
  glGetBooleanv(GL_LIGHT_MODEL_LOCAL_VIEWER, &b);
  CHECK(b == GL_TRUE);
  GLint control = 0;
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &control);
  CHECK(control == GL_SEPARATE_SPECULAR_COLOR);
  CHECK(glGetError() == GL_NO_ERROR);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FLAT);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 1.0f);  // a vector parameter through the scalar call
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("glMaterial: faces, parameters, queries and errors") {
  ScopedContext scope;
  const GLfloat red[4] = {1.0f, 0.0f, 0.0f, 0.5f};
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64.0f);
  GLfloat v[4];
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, v);
  checkVector(v, 1, 0, 0, 0.5f);
  glGetMaterialfv(GL_BACK, GL_AMBIENT, v);
  checkVector(v, 1, 0, 0, 0.5f);
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  checkVector(v, 0.8f, 0.8f, 0.8f, 1.0f);  // the front is untouched
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  CHECK(v[0] == 64.0f);
  CHECK(glGetError() == GL_NO_ERROR);

  glMaterialf(GL_FRONT, GL_SHININESS, 129.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glMaterialf(GL_FRONT, GL_DIFFUSE, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glMaterialfv(GL_LEFT, GL_DIFFUSE, red);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glGetMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, v);
  CHECK(glGetError() == GL_INVALID_ENUM);

  // glMaterial is allowed between glBegin and glEnd (spec 2.6.3).
  glBegin(GL_POINTS);
  glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
  glEnd();
  CHECK(glGetError() == GL_NO_ERROR);
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  CHECK(v[0] == 10.0f);
}

TEST_CASE("glColorMaterial: the named parameters follow the current colour while enabled") {
  ScopedContext scope;
  GLint face = 0, mode = 0;
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &face);
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &mode);
  CHECK(face == GL_FRONT_AND_BACK);
  CHECK(mode == GL_AMBIENT_AND_DIFFUSE);

  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glColorMaterial(GL_BACK, GL_SPECULAR);
  glEnable(GL_COLOR_MATERIAL);
  GLfloat v[4];
  // Spec 2.13.3: from the moment colour material is enabled, the parameter is the current colour.
  glGetMaterialfv(GL_BACK, GL_SPECULAR, v);
  checkVector(v, 0.1f, 0.2f, 0.3f, 0.4f);
  glColor3f(0.5f, 0.6f, 0.7f);
  glGetMaterialfv(GL_BACK, GL_SPECULAR, v);
  checkVector(v, 0.5f, 0.6f, 0.7f, 1.0f);
  glGetMaterialfv(GL_FRONT, GL_SPECULAR, v);
  checkVector(v, 0.0f, 0.0f, 0.0f, 1.0f);  // the other face is not tracked
  // While tracked, glMaterial does not change the parameter.
  const GLfloat green[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  glMaterialfv(GL_BACK, GL_SPECULAR, green);
  glGetMaterialfv(GL_BACK, GL_SPECULAR, v);
  checkVector(v, 0.5f, 0.6f, 0.7f, 1.0f);
  // Disabled: the last tracked colour stays, and glColor no longer changes it.
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(1.0f, 1.0f, 1.0f);
  glGetMaterialfv(GL_BACK, GL_SPECULAR, v);
  checkVector(v, 0.5f, 0.6f, 0.7f, 1.0f);
  CHECK(glIsEnabled(GL_COLOR_MATERIAL) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);

  glColorMaterial(GL_FRONT, GL_SHININESS);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("lighting capabilities: glEnable, glIsEnabled and glGet") {
  ScopedContext scope;
  CHECK(glIsEnabled(GL_LIGHTING) == GL_FALSE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT7);
  CHECK(glIsEnabled(GL_LIGHTING) == GL_TRUE);
  CHECK(glIsEnabled(GL_LIGHT7) == GL_TRUE);
  CHECK(glIsEnabled(GL_LIGHT6) == GL_FALSE);
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_LIGHT7, &b);
  CHECK(b == GL_TRUE);
  glEnable(GL_LIGHT0 + 8);
  CHECK(glGetError() == GL_INVALID_ENUM);
}

TEST_CASE("glFog: defaults, values, queries and errors") {
  ScopedContext scope;
  GLint mode = 0;
  glGetIntegerv(GL_FOG_MODE, &mode);
  CHECK(mode == GL_EXP);
  GLfloat v[4];
  glGetFloatv(GL_FOG_DENSITY, v);
  CHECK(v[0] == 1.0f);
  glGetFloatv(GL_FOG_END, v);
  CHECK(v[0] == 1.0f);

  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 9.0f);
  const GLfloat color[4] = {1.5f, 0.5f, -0.5f, 1.0f};
  glFogfv(GL_FOG_COLOR, color);
  glEnable(GL_FOG);
  glGetIntegerv(GL_FOG_MODE, &mode);
  CHECK(mode == GL_LINEAR);
  glGetFloatv(GL_FOG_START, v);
  CHECK(v[0] == 2.0f);
  glGetFloatv(GL_FOG_COLOR, v);
  checkVector(v, 1.0f, 0.5f, 0.0f, 1.0f);  // clamped when given
  CHECK(glIsEnabled(GL_FOG) == GL_TRUE);
  CHECK(glGetError() == GL_NO_ERROR);

  glFogi(GL_FOG_MODE, GL_LINEAR + 1);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glFogf(GL_FOG_DENSITY, -1.0f);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glFogf(GL_FOG_COLOR, 1.0f);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glBegin(GL_LINES);
  glFogf(GL_FOG_START, 0.0f);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}

TEST_CASE("lighting commands are compiled into display lists") {
  ScopedContext scope;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMaterialf(GL_FRONT, GL_SHININESS, 33.0f);
  glLightf(GL_LIGHT4, GL_SPOT_EXPONENT, 7.0f);
  glFogf(GL_FOG_DENSITY, 0.25f);
  glEndList();
  GLfloat v[4];
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  CHECK(v[0] == 0.0f);  // compiled, not executed
  glCallList(list);
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  CHECK(v[0] == 33.0f);
  glGetLightfv(GL_LIGHT4, GL_SPOT_EXPONENT, v);
  CHECK(v[0] == 7.0f);
  glGetFloatv(GL_FOG_DENSITY, v);
  CHECK(v[0] == 0.25f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("enums given as floats: values no enum has, NaN and infinities are GL_INVALID_ENUM") {
  ScopedContext scope;
  const float bad[] = {-3.5f, 1e30f, -1e30f, std::numeric_limits<float>::infinity(), std::nanf(""),
                       static_cast<float>(GL_SEPARATE_SPECULAR_COLOR) + 0.5f};
  for (const float value : bad) {
    CAPTURE(value);
    glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, value);
    CHECK(glGetError() == GL_INVALID_ENUM);
    glFogf(GL_FOG_MODE, value);
    CHECK(glGetError() == GL_INVALID_ENUM);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, value);
    CHECK(glGetError() == GL_INVALID_ENUM);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, value);
    CHECK(glGetError() == GL_INVALID_ENUM);
    glTexGenf(GL_S, GL_TEXTURE_GEN_MODE, value);
    CHECK(glGetError() == GL_INVALID_ENUM);
  }
  glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, static_cast<float>(GL_SEPARATE_SPECULAR_COLOR));
  glFogf(GL_FOG_MODE, static_cast<float>(GL_LINEAR));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<float>(GL_NEAREST));
  CHECK(glGetError() == GL_NO_ERROR);
}
