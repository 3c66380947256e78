// glPushAttrib / glPopAttrib and the client versions: each group restores what it holds and
// nothing else; stack errors; display lists.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <glass/context.h>

#include <array>
#include <initializer_list>

namespace {

struct ScopedContext {
  GlassContext* ctx;
  ScopedContext() : ctx(glassCreateContext(16, 16)) {
    REQUIRE(ctx != nullptr);
    REQUIRE(glassMakeCurrent(ctx) == 1);
  }
  ~ScopedContext() {
    glassMakeCurrent(nullptr);
    glassDestroyContext(ctx);
  }
};

GLint integer(GLenum pname) {
  GLint v = 0;
  glGetIntegerv(pname, &v);
  return v;
}

GLfloat number(GLenum pname) {
  GLfloat v[16] = {};
  glGetFloatv(pname, v);
  return v[0];
}

}  // namespace

TEST_CASE("glPushAttrib(GL_LIGHTING_BIT) restores lights, materials, model and shade model") {
  ScopedContext scope;
  glPushAttrib(GL_LIGHTING_BIT);
  const GLfloat red[4] = {1, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 30.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glShadeModel(GL_FLAT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  glColorMaterial(GL_FRONT, GL_EMISSION);
  glPopAttrib();
  GLfloat v[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  CHECK(v[0] == doctest::Approx(0.8f));
  glGetLightfv(GL_LIGHT2, GL_SPOT_CUTOFF, v);
  CHECK(v[0] == 180.0f);
  CHECK(integer(GL_LIGHT_MODEL_TWO_SIDE) == GL_FALSE);
  CHECK(integer(GL_SHADE_MODEL) == GL_SMOOTH);
  CHECK(glIsEnabled(GL_LIGHTING) == GL_FALSE);
  CHECK(glIsEnabled(GL_LIGHT3) == GL_FALSE);
  CHECK(integer(GL_COLOR_MATERIAL_PARAMETER) == GL_AMBIENT_AND_DIFFUSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glPushAttrib(GL_ENABLE_BIT) restores every enable, and only enables") {
  ScopedContext scope;
  glEnable(GL_DEPTH_TEST);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT5);
  glEnable(GL_FOG);
  glEnable(GL_CLIP_PLANE2);
  glEnable(GL_CULL_FACE);
  glEnable(GL_NORMALIZE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_STENCIL_TEST);
  glDepthFunc(GL_GREATER);  // not an enable: stays
  glPopAttrib();
  CHECK(glIsEnabled(GL_DEPTH_TEST) == GL_TRUE);
  for (GLenum cap : {GL_BLEND, GL_LIGHTING, GL_LIGHT5, GL_FOG, GL_CLIP_PLANE2, GL_CULL_FACE,
                     GL_NORMALIZE, GL_TEXTURE_2D, GL_STENCIL_TEST}) {
    CHECK(glIsEnabled(cap) == GL_FALSE);
  }
  CHECK(integer(GL_DEPTH_FUNC) == GL_GREATER);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glPushAttrib: colour, depth, stencil, scissor, viewport, transform and fog groups") {
  ScopedContext scope;
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT |
               GL_SCISSOR_BIT | GL_VIEWPORT_BIT | GL_TRANSFORM_BIT | GL_FOG_BIT);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glAlphaFunc(GL_GREATER, 0.5f);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_FALSE);
  glClearDepth(0.25);
  glStencilFunc(GL_EQUAL, 3, 0x0F);
  glStencilOp(GL_ZERO, GL_INCR, GL_DECR);
  glScissor(1, 2, 3, 4);
  glEnable(GL_SCISSOR_TEST);
  glViewport(2, 2, 5, 5);
  glDepthRange(0.2, 0.8);
  glMatrixMode(GL_PROJECTION);
  glEnable(GL_RESCALE_NORMAL);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glEnable(GL_FOG);
  glPopAttrib();

  CHECK(integer(GL_BLEND_SRC) == GL_ONE);
  CHECK(integer(GL_BLEND_DST) == GL_ZERO);
  CHECK(number(GL_COLOR_CLEAR_VALUE) == 0.0f);
  GLboolean mask[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  CHECK(mask[0] == GL_TRUE);
  CHECK(integer(GL_ALPHA_TEST_FUNC) == GL_ALWAYS);
  CHECK(integer(GL_DEPTH_FUNC) == GL_LESS);
  CHECK(integer(GL_DEPTH_WRITEMASK) == GL_TRUE);
  CHECK(number(GL_DEPTH_CLEAR_VALUE) == 1.0f);
  CHECK(integer(GL_STENCIL_FUNC) == GL_ALWAYS);
  CHECK(integer(GL_STENCIL_FAIL) == GL_KEEP);
  CHECK(integer(GL_STENCIL_PASS_DEPTH_FAIL) == GL_KEEP);
  CHECK(glIsEnabled(GL_SCISSOR_TEST) == GL_FALSE);
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box);
  CHECK(box[2] == 16);
  glGetIntegerv(GL_VIEWPORT, box);
  CHECK(box[0] == 0);
  CHECK(box[3] == 16);
  GLfloat range[2];
  glGetFloatv(GL_DEPTH_RANGE, range);
  CHECK(range[0] == 0.0f);
  CHECK(range[1] == 1.0f);
  CHECK(integer(GL_MATRIX_MODE) == GL_MODELVIEW);
  CHECK(glIsEnabled(GL_RESCALE_NORMAL) == GL_FALSE);
  CHECK(integer(GL_FOG_MODE) == GL_EXP);
  CHECK(glIsEnabled(GL_FOG) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glPushAttrib: current, point, line and polygon groups; unsaved groups stay") {
  ScopedContext scope;
  glPushAttrib(GL_CURRENT_BIT | GL_POINT_BIT | GL_LINE_BIT | GL_POLYGON_BIT);
  glColor3f(0.25f, 0.5f, 0.75f);
  glNormal3f(1.0f, 0.0f, 0.0f);
  glPointSize(4.0f);
  glLineWidth(3.0f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0F0F);
  glCullFace(GL_FRONT);
  glFrontFace(GL_CW);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glPolygonOffset(1.0f, 2.0f);
  glShadeModel(GL_FLAT);  // lighting group: not saved here
  glPopAttrib();
  GLfloat color[4];
  glGetFloatv(GL_CURRENT_COLOR, color);
  CHECK(color[0] == 1.0f);
  GLfloat normal[3];
  glGetFloatv(GL_CURRENT_NORMAL, normal);
  CHECK(normal[2] == 1.0f);
  CHECK(number(GL_POINT_SIZE) == 1.0f);
  CHECK(number(GL_LINE_WIDTH) == 1.0f);
  CHECK(glIsEnabled(GL_LINE_STIPPLE) == GL_FALSE);
  CHECK(integer(GL_LINE_STIPPLE_PATTERN) == 0xFFFF);
  CHECK(integer(GL_CULL_FACE_MODE) == GL_BACK);
  CHECK(integer(GL_FRONT_FACE) == GL_CCW);
  GLint modes[2];
  glGetIntegerv(GL_POLYGON_MODE, modes);
  CHECK(modes[0] == GL_FILL);
  CHECK(number(GL_POLYGON_OFFSET_UNITS) == 0.0f);
  CHECK(integer(GL_SHADE_MODEL) == GL_FLAT);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glPushAttrib: overflow, underflow, depth queries and glBegin") {
  ScopedContext scope;
  const GLint max = integer(GL_MAX_ATTRIB_STACK_DEPTH);
  CHECK(max >= 16);
  for (int i = 0; i < max; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(integer(GL_ATTRIB_STACK_DEPTH) == max);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  CHECK(glGetError() == GL_STACK_OVERFLOW);
  CHECK(integer(GL_ATTRIB_STACK_DEPTH) == max);
  for (int i = 0; i < max; ++i) glPopAttrib();
  CHECK(glGetError() == GL_NO_ERROR);
  glPopAttrib();
  CHECK(glGetError() == GL_STACK_UNDERFLOW);

  glBegin(GL_POINTS);
  glPushAttrib(GL_CURRENT_BIT);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
  CHECK(integer(GL_ATTRIB_STACK_DEPTH) == 0);
}

TEST_CASE("glPushAttrib and glPopAttrib are compiled into display lists") {
  ScopedContext scope;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPushAttrib(GL_POINT_BIT);
  glPointSize(5.0f);
  glPopAttrib();
  glEndList();
  CHECK(integer(GL_ATTRIB_STACK_DEPTH) == 0);
  glPointSize(2.0f);
  glCallList(list);
  CHECK(number(GL_POINT_SIZE) == 2.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("glPushClientAttrib restores pixel store and vertex arrays") {
  ScopedContext scope;
  CHECK(integer(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH) >= 16);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  CHECK(integer(GL_CLIENT_ATTRIB_STACK_DEPTH) == 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnableClientState(GL_VERTEX_ARRAY);
  glPopClientAttrib();
  CHECK(integer(GL_UNPACK_ALIGNMENT) == 4);
  CHECK(glIsEnabled(GL_VERTEX_ARRAY) == GL_FALSE);
  glPopClientAttrib();
  CHECK(glGetError() == GL_STACK_UNDERFLOW);
}

TEST_CASE("glPopAttrib leaves colour-material parameters holding the current colour") {
  ScopedContext scope;
  const GLfloat yellow[4] = {0.7f, 0.6f, 0.1f, 1.0f}, red[4] = {0.8f, 0.1f, 0.1f, 1.0f};
  const GLfloat blue[4] = {0.1f, 0.2f, 0.9f, 1.0f};
  const auto material = [](GLenum face, GLenum pname) {
    std::array<GLfloat, 4> v{};
    glGetMaterialfv(face, pname, v.data());
    return v;
  };
  const auto asArray = [](const GLfloat* c) { return std::array<GLfloat, 4>{c[0], c[1], c[2], c[3]}; };
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor4fv(yellow);

  // The material comes back yellow, the current colour stays red: the tracked ones are red.
  glPushAttrib(GL_LIGHTING_BIT);
  glColor4fv(red);
  glPopAttrib();
  CHECK(material(GL_FRONT, GL_DIFFUSE) == asArray(red));
  CHECK(material(GL_BACK, GL_AMBIENT) == asArray(red));

  // The colour comes back (red), the material stays blue: red again.
  glPushAttrib(GL_CURRENT_BIT);
  glColor4fv(blue);
  CHECK(material(GL_FRONT, GL_AMBIENT) == asArray(blue));
  glPopAttrib();
  CHECK(material(GL_FRONT, GL_AMBIENT) == asArray(red));

  // A parameter not tracked keeps what the pop brought back.
  const GLfloat grey[4] = {0.3f, 0.3f, 0.3f, 1.0f};
  glPushAttrib(GL_LIGHTING_BIT);
  glMaterialfv(GL_FRONT, GL_SPECULAR, grey);
  glPopAttrib();
  CHECK(material(GL_FRONT, GL_SPECULAR) == std::array<GLfloat, 4>{0.0f, 0.0f, 0.0f, 1.0f});
  CHECK(glGetError() == GL_NO_ERROR);
}
