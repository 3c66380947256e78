// glGet round trips (spec 6.1): what a command sets is what glGet returns, with the conversions
// of spec 6.1.2 between booleans, integers and floats; initial values as in the state tables.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <climits>
#include <cstring>
#include <string>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

GLint getInteger(GLenum pname) {
  GLint v[16] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

GLfloat getFloat(GLenum pname) {
  GLfloat v[16] = {};
  glGetFloatv(pname, v);
  return v[0];
}

bool getBoolean(GLenum pname) {
  GLboolean v[16] = {};
  glGetBooleanv(pname, v);
  return v[0] == GL_TRUE;
}

}  // namespace

TEST_CASE("pipeline state: initial values of a new context") {
  ScopedContext context(40, 30);
  GLint v[4];
  glGetIntegerv(GL_VIEWPORT, v);
  CHECK((v[0] == 0 && v[1] == 0 && v[2] == 40 && v[3] == 30));
  glGetIntegerv(GL_SCISSOR_BOX, v);
  CHECK((v[0] == 0 && v[1] == 0 && v[2] == 40 && v[3] == 30));
  GLfloat f[4];
  glGetFloatv(GL_CURRENT_COLOR, f);
  CHECK((f[0] == 1 && f[1] == 1 && f[2] == 1 && f[3] == 1));
  glGetFloatv(GL_CURRENT_NORMAL, f);
  CHECK((f[0] == 0 && f[1] == 0 && f[2] == 1));
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
  CHECK((f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 1));
  glGetFloatv(GL_DEPTH_RANGE, f);
  CHECK((f[0] == 0 && f[1] == 1));
  CHECK(getBoolean(GL_EDGE_FLAG));
  CHECK(getInteger(GL_MATRIX_MODE) == GL_MODELVIEW);
  CHECK(getInteger(GL_MODELVIEW_STACK_DEPTH) == 1);
  CHECK(getInteger(GL_SHADE_MODEL) == GL_SMOOTH);
  CHECK(getInteger(GL_FRONT_FACE) == GL_CCW);
  CHECK(getInteger(GL_CULL_FACE_MODE) == GL_BACK);
  CHECK(getInteger(GL_DEPTH_FUNC) == GL_LESS);
  CHECK(getInteger(GL_BLEND_SRC) == GL_ONE);
  CHECK(getInteger(GL_BLEND_DST) == GL_ZERO);
  CHECK(getInteger(GL_LOGIC_OP_MODE) == GL_COPY);
  CHECK(getInteger(GL_STENCIL_FUNC) == GL_ALWAYS);
  CHECK(getInteger(GL_STENCIL_VALUE_MASK) == 255);  // all ones, in the 8 bits of the buffer
  CHECK(getInteger(GL_PACK_ALIGNMENT) == 4);
  CHECK(getInteger(GL_UNPACK_ALIGNMENT) == 4);
  CHECK(getFloat(GL_POINT_SIZE) == 1.0f);
  CHECK(getFloat(GL_LINE_WIDTH) == 1.0f);
  CHECK(getInteger(GL_DEPTH_BITS) >= 24);
  CHECK(getInteger(GL_STENCIL_BITS) == 8);
  CHECK(getInteger(GL_RED_BITS) == 8);
  CHECK(getInteger(GL_ALPHA_BITS) == 8);
  CHECK(getInteger(GL_MAX_CLIP_PLANES) >= 6);
  CHECK(getInteger(GL_MAX_LIST_NESTING) >= 64);
  CHECK(getBoolean(GL_DITHER));
  CHECK(!getBoolean(GL_DEPTH_TEST));
  CHECK(!getBoolean(GL_CULL_FACE));
  CHECK(glIsEnabled(GL_DITHER) == GL_TRUE);
  CHECK(glIsEnabled(GL_BLEND) == GL_FALSE);
  CHECK(glIsEnabled(GL_VERTEX_ARRAY) == GL_FALSE);
  GLboolean mask[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  CHECK((mask[0] && mask[1] && mask[2] && mask[3]));
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline state: enables round-trip through glIsEnabled and glGetBooleanv") {
  ScopedContext context;
  const GLenum caps[] = {GL_ALPHA_TEST, GL_BLEND, GL_COLOR_LOGIC_OP, GL_CULL_FACE, GL_DEPTH_TEST,
                         GL_DITHER, GL_LINE_STIPPLE, GL_NORMALIZE, GL_RESCALE_NORMAL,
                         GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT,
                         GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_CLIP_PLANE0, GL_CLIP_PLANE5,
                         GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_POLYGON_SMOOTH};
  for (GLenum cap : caps) {
    CAPTURE(cap);
    glEnable(cap);
    CHECK(glIsEnabled(cap) == GL_TRUE);
    CHECK(getBoolean(cap));
    CHECK(getInteger(cap) == 1);
    glDisable(cap);
    CHECK(glIsEnabled(cap) == GL_FALSE);
    CHECK(!getBoolean(cap));
  }
  glEnableClientState(GL_COLOR_ARRAY);
  CHECK(glIsEnabled(GL_COLOR_ARRAY) == GL_TRUE);
  glDisableClientState(GL_COLOR_ARRAY);
  CHECK(glIsEnabled(GL_COLOR_ARRAY) == GL_FALSE);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline state: values round-trip, converted as spec 6.1.2 says") {
  ScopedContext context(100, 80);
  GLint i4[4];
  GLfloat f4[4];
  GLdouble d4[4];

  glViewport(5, 6, 70, 50);
  glGetIntegerv(GL_VIEWPORT, i4);
  CHECK((i4[0] == 5 && i4[1] == 6 && i4[2] == 70 && i4[3] == 50));
  glGetFloatv(GL_VIEWPORT, f4);
  CHECK(f4[2] == 70.0f);
  glViewport(0, 0, 1 << 20, 10);  // clamped to GL_MAX_VIEWPORT_DIMS
  GLint maxDims[2];
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxDims);
  glGetIntegerv(GL_VIEWPORT, i4);
  CHECK(i4[2] == maxDims[0]);

  glDepthRange(0.25, 2.0);  // clamped to [0, 1]
  glGetDoublev(GL_DEPTH_RANGE, d4);
  CHECK((d4[0] == 0.25 && d4[1] == 1.0));
  glGetIntegerv(GL_DEPTH_RANGE, i4);  // normalized: 1.0 is the largest integer
  CHECK(i4[1] == INT_MAX);

  glColor4f(0.5f, 0.25f, 1.0f, 0.0f);
  glGetFloatv(GL_CURRENT_COLOR, f4);
  CHECK((f4[0] == 0.5f && f4[1] == 0.25f && f4[2] == 1.0f && f4[3] == 0.0f));
  glGetIntegerv(GL_CURRENT_COLOR, i4);
  CHECK(i4[2] == INT_MAX);
  CHECK(i4[3] == 0);
  CHECK(i4[0] == doctest::Approx(INT_MAX / 2.0).epsilon(1e-6));
  glColor3ub(255, 0, 51);
  glGetFloatv(GL_CURRENT_COLOR, f4);
  CHECK((f4[0] == 1.0f && f4[1] == 0.0f && f4[2] == doctest::Approx(0.2f) && f4[3] == 1.0f));
  glColor3b(127, -128, 0);  // signed: (2c + 1) / 255
  glGetFloatv(GL_CURRENT_COLOR, f4);
  CHECK((f4[0] == 1.0f && f4[1] == -1.0f && f4[2] == doctest::Approx(1.0f / 255.0f)));

  glNormal3f(0.0f, -1.0f, 0.5f);
  glGetFloatv(GL_CURRENT_NORMAL, f4);
  CHECK((f4[0] == 0.0f && f4[1] == -1.0f && f4[2] == 0.5f));
  glGetIntegerv(GL_CURRENT_NORMAL, i4);
  CHECK(i4[1] == INT_MIN);
  glNormal3s(32767, 0, 0);
  glGetFloatv(GL_CURRENT_NORMAL, f4);
  CHECK(f4[0] == 1.0f);

  glTexCoord2f(0.5f, 2.0f);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f4);
  CHECK((f4[0] == 0.5f && f4[1] == 2.0f && f4[2] == 0.0f && f4[3] == 1.0f));
  glTexCoord4i(1, 2, 3, 4);
  glGetIntegerv(GL_CURRENT_TEXTURE_COORDS, i4);
  CHECK((i4[0] == 1 && i4[1] == 2 && i4[2] == 3 && i4[3] == 4));

  glEdgeFlag(GL_FALSE);
  CHECK(!getBoolean(GL_EDGE_FLAG));
  glEdgeFlag(GL_TRUE);

  glClearColor(0.0f, 0.5f, 2.0f, -1.0f);  // clamped
  glGetFloatv(GL_COLOR_CLEAR_VALUE, f4);
  CHECK((f4[0] == 0.0f && f4[1] == 0.5f && f4[2] == 1.0f && f4[3] == 0.0f));
  glClearDepth(0.75);
  CHECK(getFloat(GL_DEPTH_CLEAR_VALUE) == 0.75f);
  glClearStencil(7);
  CHECK(getInteger(GL_STENCIL_CLEAR_VALUE) == 7);

  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  GLboolean b4[4];
  glGetBooleanv(GL_COLOR_WRITEMASK, b4);
  CHECK((b4[0] == GL_TRUE && b4[1] == GL_FALSE && b4[2] == GL_TRUE && b4[3] == GL_FALSE));
  glDepthMask(GL_FALSE);
  CHECK(!getBoolean(GL_DEPTH_WRITEMASK));
  glStencilMask(0x3C);
  CHECK(getInteger(GL_STENCIL_WRITEMASK) == 0x3C);

  glPointSize(3.5f);
  CHECK(getFloat(GL_POINT_SIZE) == 3.5f);
  CHECK(getInteger(GL_POINT_SIZE) == 4);  // floats round to the nearest integer
  glLineWidth(2.0f);
  CHECK(getFloat(GL_LINE_WIDTH) == 2.0f);
  glLineStipple(300, 0xABCD);
  CHECK(getInteger(GL_LINE_STIPPLE_REPEAT) == 256);  // clamped to [1, 256]
  CHECK(getInteger(GL_LINE_STIPPLE_PATTERN) == 0xABCD);
  glShadeModel(GL_FLAT);
  CHECK(getInteger(GL_SHADE_MODEL) == GL_FLAT);
  glShadeModel(GL_PHONG_WIN);
  CHECK(getInteger(GL_SHADE_MODEL) == GL_PHONG_WIN);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glGetIntegerv(GL_POLYGON_MODE, i4);
  CHECK((i4[0] == GL_LINE && i4[1] == GL_POINT));
  glCullFace(GL_FRONT_AND_BACK);
  CHECK(getInteger(GL_CULL_FACE_MODE) == GL_FRONT_AND_BACK);
  glFrontFace(GL_CW);
  CHECK(getInteger(GL_FRONT_FACE) == GL_CW);
  glPolygonOffset(1.5f, -2.0f);
  CHECK(getFloat(GL_POLYGON_OFFSET_FACTOR) == 1.5f);
  CHECK(getFloat(GL_POLYGON_OFFSET_UNITS) == -2.0f);

  glScissor(1, 2, 3, 4);
  glGetIntegerv(GL_SCISSOR_BOX, i4);
  CHECK((i4[0] == 1 && i4[1] == 2 && i4[2] == 3 && i4[3] == 4));
  glAlphaFunc(GL_GEQUAL, 1.5f);  // the reference is clamped
  CHECK(getInteger(GL_ALPHA_TEST_FUNC) == GL_GEQUAL);
  CHECK(getFloat(GL_ALPHA_TEST_REF) == 1.0f);
  glStencilFunc(GL_NOTEQUAL, 300, 0x0F);  // the reference is clamped to [0, 255]
  CHECK(getInteger(GL_STENCIL_FUNC) == GL_NOTEQUAL);
  CHECK(getInteger(GL_STENCIL_REF) == 255);
  CHECK(getInteger(GL_STENCIL_VALUE_MASK) == 0x0F);
  glStencilOp(GL_INCR, GL_DECR_WRAP, GL_INVERT);
  CHECK(getInteger(GL_STENCIL_FAIL) == GL_INCR);
  CHECK(getInteger(GL_STENCIL_PASS_DEPTH_FAIL) == GL_DECR_WRAP);
  CHECK(getInteger(GL_STENCIL_PASS_DEPTH_PASS) == GL_INVERT);
  glDepthFunc(GL_GEQUAL);
  CHECK(getInteger(GL_DEPTH_FUNC) == GL_GEQUAL);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  CHECK(getInteger(GL_BLEND_SRC) == GL_SRC_ALPHA);
  CHECK(getInteger(GL_BLEND_DST) == GL_ONE_MINUS_SRC_ALPHA);
  glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_DST_ALPHA, GL_CONSTANT_ALPHA);
  CHECK(getInteger(GL_BLEND_SRC_RGB) == GL_ONE);
  CHECK(getInteger(GL_BLEND_SRC_ALPHA) == GL_DST_ALPHA);
  CHECK(getInteger(GL_BLEND_DST_ALPHA) == GL_CONSTANT_ALPHA);
  glBlendEquation(GL_MAX);
  CHECK(getInteger(GL_BLEND_EQUATION) == GL_MAX);
  glBlendColor(0.25f, 0.5f, 0.75f, 1.0f);
  glGetFloatv(GL_BLEND_COLOR, f4);
  CHECK((f4[0] == 0.25f && f4[3] == 1.0f));
  glLogicOp(GL_XOR);
  CHECK(getInteger(GL_LOGIC_OP_MODE) == GL_XOR);

  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  CHECK(getInteger(GL_PERSPECTIVE_CORRECTION_HINT) == GL_NICEST);
  glHint(GL_PHONG_HINT_WIN, GL_FASTEST);
  CHECK(getInteger(GL_PHONG_HINT_WIN) == GL_FASTEST);

  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, 17);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  CHECK(getInteger(GL_PACK_ALIGNMENT) == 8);
  CHECK(getInteger(GL_PACK_ROW_LENGTH) == 17);
  CHECK(getInteger(GL_UNPACK_SKIP_PIXELS) == 3);
  CHECK(getBoolean(GL_UNPACK_SWAP_BYTES));

  const GLshort vertices[8] = {};
  glVertexPointer(2, GL_SHORT, 4, vertices);
  CHECK(getInteger(GL_VERTEX_ARRAY_SIZE) == 2);
  CHECK(getInteger(GL_VERTEX_ARRAY_TYPE) == GL_SHORT);
  CHECK(getInteger(GL_VERTEX_ARRAY_STRIDE) == 4);
  GLvoid* pointer = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer);
  CHECK(pointer == vertices);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, vertices);
  CHECK(getInteger(GL_COLOR_ARRAY_SIZE) == 3);
  CHECK(getInteger(GL_COLOR_ARRAY_TYPE) == GL_UNSIGNED_BYTE);
  glNormalPointer(GL_BYTE, 6, vertices);
  CHECK(getInteger(GL_NORMAL_ARRAY_TYPE) == GL_BYTE);
  CHECK(getInteger(GL_NORMAL_ARRAY_STRIDE) == 6);
  glTexCoordPointer(1, GL_DOUBLE, 0, vertices);
  CHECK(getInteger(GL_TEXTURE_COORD_ARRAY_SIZE) == 1);
  CHECK(getInteger(GL_TEXTURE_COORD_ARRAY_TYPE) == GL_DOUBLE);

  const GLdouble plane[4] = {1, 2, 3, 4};
  glLoadIdentity();
  glTranslatef(0, 0, -2);  // the plane is stored in eye space: p M^-1
  glClipPlane(GL_CLIP_PLANE2, plane);
  glGetClipPlane(GL_CLIP_PLANE2, d4);
  CHECK((d4[0] == 1 && d4[1] == 2 && d4[2] == 3 && d4[3] == doctest::Approx(4 + 3 * 2)));

  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline state: glGetString") {
  ScopedContext context;
  const std::string vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  const std::string version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  CHECK(vendor == "glass");
  CHECK(glGetString(GL_RENDERER) != nullptr);
  CHECK(version.rfind("1.", 0) == 0);  // "<major>.<minor> ..."
  CHECK(extensions.find("GL_WIN_phong_shading") != std::string::npos);
}
