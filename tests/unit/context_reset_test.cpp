// glassResetContext: every piece of GL state back to a new context's value, while display lists,
// texture objects, the buffers' contents, the flush callback, the teaching view and being current
// are kept.
#include <GL/gl.h>
#include <GL/glext.h>
#include <doctest/doctest.h>
#include <glass/context.h>

#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

// Every value glGetFloatv and glIsEnabled give for any enum that has one (a sweep of the whole
// 16-bit enum range, so that state added later is compared too), and the state behind the other
// query functions: lights, materials, texture environment and generation, clip planes, the
// default textures' parameters and images, evaluator maps, pixel maps and the stipple.
std::map<std::string, std::vector<float>> everyState() {
  std::map<std::string, std::vector<float>> state;
  constexpr float kUnset = -12345.0f;
  std::vector<float> values(1024);
  for (GLenum pname = 0; pname < 0x10000; ++pname) {
    std::fill(values.begin(), values.end(), kUnset);
    glGetFloatv(pname, values.data());
    if (glGetError() == GL_NO_ERROR) {
      std::vector<float> given;
      for (float v : values)
        if (v != kUnset) given.push_back(v);
      state["get " + std::to_string(pname)] = given;
    }
    const GLboolean enabled = glIsEnabled(pname);
    if (glGetError() == GL_NO_ERROR) state["enabled " + std::to_string(pname)] = {static_cast<float>(enabled)};
  }
  const auto query = [&](const std::string &name, auto &&get) {
    std::fill(values.begin(), values.end(), kUnset);
    get(values.data());
    std::vector<float> given;
    for (float v : values)
      if (v != kUnset) given.push_back(v);
    state[name] = given;
    CHECK_MESSAGE(glGetError() == GL_NO_ERROR, name);
  };
  const GLenum lightParameters[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                    GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                    GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION};
  for (int light = 0; light < 8; ++light)
    for (GLenum p : lightParameters)
      query("light " + std::to_string(light) + " " + std::to_string(p),
            [&](float *v) { glGetLightfv(GL_LIGHT0 + static_cast<GLenum>(light), p, v); });
  for (GLenum face : {GL_FRONT, GL_BACK})
    for (GLenum p : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_COLOR_INDEXES})
      query("material " + std::to_string(face) + " " + std::to_string(p),
            [&](float *v) { glGetMaterialfv(face, p, v); });
  for (int unit = 0; unit < 2; ++unit) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    for (GLenum p : {GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_RGB_SCALE})
      query("env " + std::to_string(unit) + " " + std::to_string(p),
            [&](float *v) { glGetTexEnvfv(GL_TEXTURE_ENV, p, v); });
    for (GLenum coord : {GL_S, GL_T, GL_R, GL_Q})
      for (GLenum p : {GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE})
        query("texgen " + std::to_string(unit) + " " + std::to_string(coord) + " " + std::to_string(p),
              [&](float *v) { glGetTexGenfv(coord, p, v); });
  }
  glActiveTexture(GL_TEXTURE0);
  for (GLenum plane = GL_CLIP_PLANE0; plane < GL_CLIP_PLANE0 + 6; ++plane)
    query("clip plane " + std::to_string(plane), [&](float *v) {
      double equation[4] = {kUnset, kUnset, kUnset, kUnset};
      glGetClipPlane(plane, equation);
      for (int i = 0; i < 4; ++i) v[i] = static_cast<float>(equation[i]);
    });
  for (GLenum target : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D}) {
    for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
                     GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY, GL_GENERATE_MIPMAP, GL_TEXTURE_MAX_LEVEL})
      query("texture " + std::to_string(target) + " " + std::to_string(p),
            [&](float *v) { glGetTexParameterfv(target, p, v); });
    for (GLenum p : {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_INTERNAL_FORMAT})
      query("texture level " + std::to_string(target) + " " + std::to_string(p),
            [&](float *v) { glGetTexLevelParameterfv(target, 0, p, v); });
  }
  for (GLenum map : {GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP2_VERTEX_3, GL_MAP2_NORMAL})
    for (GLenum p : {GL_ORDER, GL_DOMAIN, GL_COEFF})
      query("map " + std::to_string(map) + " " + std::to_string(p), [&](float *v) { glGetMapfv(map, p, v); });
  query("pixel map R to R", [&](float *v) { glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, v); });
  query("polygon stipple", [&](float *v) {
    GLubyte mask[128];
    std::memset(mask, 7, sizeof mask);
    glGetPolygonStipple(mask);
    for (int i = 0; i < 128; ++i) v[i] = mask[i];
  });
  return state;
}

// Changes as much state as a frame can: every group of glPushAttrib and glPushClientAttrib, the
// matrix and attribute stacks, the default textures, the maps, selection mode, a pending error,
// and it stops inside glBegin.
void changeEveryKindOfState(GLuint *selectBuffer) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_FOG);
  glEnable(GL_BLEND);
  glEnable(GL_CULL_FACE);
  glEnable(GL_CLIP_PLANE2);
  glEnable(GL_POLYGON_STIPPLE);
  const float red[4] = {1, 0, 0, 1};
  glLightfv(GL_LIGHT3, GL_DIFFUSE, red);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30.0f);
  glMaterialfv(GL_BACK, GL_EMISSION, red);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glColorMaterial(GL_FRONT, GL_SPECULAR);
  glShadeModel(GL_FLAT);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glDepthRange(0.2, 0.7);
  glBlendFunc(GL_ONE, GL_ONE);
  glAlphaFunc(GL_GEQUAL, 0.5f);
  glStencilFunc(GL_EQUAL, 3, 0x0F);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(0.5);
  glClearStencil(9);
  glClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
  glViewport(1, 1, 2, 2);
  glScissor(0, 1, 1, 1);
  glFogf(GL_FOG_DENSITY, 0.3f);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glHint(GL_FOG_HINT, GL_NICEST);
  glPointSize(3);
  glLineWidth(2);
  glLineStipple(2, 0xF0F0);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonOffset(1, 2);
  glFrontFace(GL_CW);
  GLubyte stipple[128];
  std::memset(stipple, 0x55, sizeof stipple);
  glPolygonStipple(stipple);
  const double plane[4] = {1, 2, 3, 4};
  glClipPlane(GL_CLIP_PLANE2, plane);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glActiveTexture(GL_TEXTURE0);
  // The default 2D texture (name 0) gets an image and parameters: a new context's has neither.
  glBindTexture(GL_TEXTURE_2D, 0);
  const unsigned char texel[4] = {1, 2, 3, 4};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  const float points[6] = {0, 0, 0, 1, 1, 1};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
  glMapGrid1f(4, 0, 1);
  const float map[2] = {0.5f, 0.25f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, map);
  glPixelTransferf(GL_RED_SCALE, 2);
  glPixelZoom(2, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  static const float vertices[3] = {1, 2, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glColor3f(0.5f, 0.25f, 1);
  glNormal3f(1, 0, 0);
  glTexCoord2f(0.5f, 0.5f);
  glEdgeFlag(GL_FALSE);
  glRasterPos2f(0.25f, 0.25f);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glOrtho(-2, 2, -2, 2, -2, 2);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 2, 2);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glTranslatef(1, 2, 3);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glListBase(5);
  glSelectBuffer(8, selectBuffer);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(4);
  glEnable(0x1234);  // a pending GL_INVALID_ENUM
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
}

} // namespace

TEST_CASE("glassResetContext: every GL state as in a new context, objects and pixels kept") {
  GlassContext *fresh = glassCreateContext(4, 4);
  REQUIRE(fresh != nullptr);
  REQUIRE(glassMakeCurrent(fresh) == 1);
  const auto initial = everyState();
  glassDestroyContext(fresh);

  GlassContext *ctx = glassCreateContext(4, 4);
  REQUIRE(ctx != nullptr);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  const auto before = everyState();
  REQUIRE(before == initial);  // the sweep itself sees the same in any new context
  REQUIRE(before.size() > 300);

  // Objects a frame makes: a texture and a display list that draws with it.
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  const unsigned char green[4] = {0, 255, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, texture);
  glRectf(-1, -1, 1, 1);
  glEndList();
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();

  int flushes = 0;
  glassSetFlushCallback(ctx, [](GlassContext *, void *count) { ++*static_cast<int *>(count); }, &flushes);
  REQUIRE(glassSetView(ctx, "depth") == 1);
  GLuint selectBuffer[8];
  changeEveryKindOfState(selectBuffer);
  glEnd();
  glGetError();
  CHECK(everyState() != initial);
  changeEveryKindOfState(selectBuffer);  // and reset inside glBegin

  REQUIRE(glassResetContext(ctx) == 1);
  CHECK(glassGetCurrentContext() == ctx);
  CHECK(glGetError() == GL_NO_ERROR);  // the pending error went with the old state
  const auto after = everyState();
  CHECK(after.size() == initial.size());
  for (const auto &[name, values] : initial) {
    const auto found = after.find(name);
    REQUIRE_MESSAGE(found != after.end(), name);
    CHECK_MESSAGE(found->second == values, name);
  }

  // Kept: the colour buffer's pixels, the view, the callback, the objects.
  REQUIRE(glassGetView(ctx) != nullptr);
  CHECK(std::string(glassGetView(ctx)) == "depth");
  REQUIRE(glassSetView(ctx, nullptr) == 1);
  const unsigned char *pixels = glassGetColorBuffer(ctx);
  CHECK((pixels[0] == 0 && pixels[1] == 0 && pixels[2] == 255));
  CHECK(glIsList(list) == GL_TRUE);
  CHECK(glIsTexture(texture) == GL_TRUE);
  glCallList(list);
  glFlush();
  CHECK(flushes == 1);
  pixels = glassGetColorBuffer(ctx);
  CHECK((pixels[0] == 0 && pixels[1] == 255 && pixels[2] == 0));

  // Not current: reset, then made current, it is as new too.
  glassMakeCurrent(nullptr);
  REQUIRE(glassResetContext(ctx) == 1);
  CHECK(glassGetCurrentContext() == nullptr);
  REQUIRE(glassMakeCurrent(ctx) == 1);
  CHECK(glIsList(list) == GL_TRUE);
  CHECK(everyState() == initial);
  glassDestroyContext(ctx);
  CHECK(glassResetContext(nullptr) == 0);
}
