// Creating contexts (OSMesaCreateContextAttribs's rules), sharing display lists, binding to
// buffers of other sizes, the depth and colour buffer queries, OSMesaGetProcAddress.
#include <GL/glu.h>
#include <dlfcn.h>
#include <doctest/doctest.h>

#include <cstring>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "osmesa_test_scene.h"

using osmesa_test::createContext;

TEST_CASE("OSMesaCreateContextAttribs: the compatibility profile up to glass's version") {
  const int defaults[] = {0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(defaults, nullptr);
  CHECK(ctx != nullptr);
  OSMesaDestroyContext(ctx);

  const int compat13[] = {OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 32, OSMESA_STENCIL_BITS, 8,
                          OSMESA_ACCUM_BITS, 16, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                          OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  ctx = OSMesaCreateContextAttribs(compat13, nullptr);
  REQUIRE(ctx != nullptr);
  std::vector<uint8_t> buffer(8 * 8 * 4);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 8, 8));
  GLint value = 0;
  OSMesaGetIntegerv(OSMESA_FORMAT, &value);
  CHECK(value == OSMESA_BGRA);
  int major = 0, minor = 0;
  REQUIRE(std::sscanf(reinterpret_cast<const char*>(glGetString(GL_VERSION)), "%d.%d", &major, &minor) == 2);
  CHECK(major * 10 + minor >= 13);
  OSMesaDestroyContext(ctx);

  const int core[] = {OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                      OSMESA_CONTEXT_MINOR_VERSION, 2, 0};
  const int tooNew[] = {OSMESA_CONTEXT_MAJOR_VERSION, major, OSMESA_CONTEXT_MINOR_VERSION, minor + 1, 0};
  const int gl3[] = {OSMESA_CONTEXT_MAJOR_VERSION, 3, 0};
  const int unknown[] = {0x1234, 1, 0};
  const int negative[] = {OSMESA_DEPTH_BITS, -1, 0};
  const int colourIndex[] = {OSMESA_FORMAT, OSMESA_COLOR_INDEX, 0};
  const int badProfile[] = {OSMESA_PROFILE, 7, 0};
  const int badVersion[] = {OSMESA_CONTEXT_MAJOR_VERSION, 0, 0};
  for (const int* attributes : {core, tooNew, gl3, unknown, negative, colourIndex, badProfile, badVersion}) {
    CAPTURE(attributes[0]);
    CHECK(OSMesaCreateContextAttribs(attributes, nullptr) == nullptr);
  }
  CHECK(OSMesaCreateContext(0x1234, nullptr) == nullptr);
  CHECK(OSMesaCreateContextExt(OSMESA_RGBA, 24, -8, 0, nullptr) == nullptr);
  OSMesaPostprocess(nullptr, "pp_jimenezmlaa", 1);  // not supported: a message, nothing else
}

TEST_CASE("display lists are shared with the sharelist context, not with others") {
  std::vector<uint8_t> a(8 * 8 * 4), b(8 * 8 * 4), c(8 * 8 * 4);
  OSMesaContext first = createContext(OSMESA_RGBA);
  REQUIRE(OSMesaMakeCurrent(first, a.data(), GL_UNSIGNED_BYTE, 8, 8));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEndList();

  OSMesaContext sharing = OSMesaCreateContext(OSMESA_RGBA, first);
  OSMesaContext separate = createContext(OSMESA_RGBA);
  REQUIRE(sharing != nullptr);
  REQUIRE(OSMesaMakeCurrent(sharing, b.data(), GL_UNSIGNED_BYTE, 8, 8));
  CHECK(glIsList(list));
  glCallList(list);
  glFinish();
  CHECK(b[2] == 255);
  // A list made in the second context is the first's too.
  const GLuint second = glGenLists(1);
  CHECK(second != list);
  glNewList(second, GL_COMPILE);
  glEndList();
  REQUIRE(OSMesaMakeCurrent(separate, c.data(), GL_UNSIGNED_BYTE, 8, 8));
  CHECK(!glIsList(list));
  CHECK(!glIsList(second));
  REQUIRE(OSMesaMakeCurrent(first, a.data(), GL_UNSIGNED_BYTE, 8, 8));
  CHECK(glIsList(second));
  // The table outlives the context that made it.
  OSMesaDestroyContext(first);
  REQUIRE(OSMesaMakeCurrent(sharing, b.data(), GL_UNSIGNED_BYTE, 8, 8));
  CHECK(glIsList(list));
  OSMesaDestroyContext(sharing);
  OSMesaDestroyContext(separate);
}

TEST_CASE("binding a context to buffers of other sizes") {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);  // with accumulation
  REQUIRE(ctx != nullptr);
  std::vector<uint8_t> small(40 * 30 * 4, 0), large(120 * 90 * 4, 0);
  REQUIRE(OSMesaMakeCurrent(ctx, small.data(), GL_UNSIGNED_BYTE, 40, 30));
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  CHECK(viewport[2] == 40);  // the first binding sets the viewport
  CHECK(viewport[3] == 30);
  osmesa_test::drawScene(1);
  const std::vector<uint8_t> smallPicture = small;

  REQUIRE(OSMesaMakeCurrent(ctx, large.data(), GL_UNSIGNED_BYTE, 120, 90));
  glGetIntegerv(GL_VIEWPORT, viewport);
  CHECK(viewport[2] == 40);  // later bindings do not
  GLint width = 0, height = 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, &width);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &height);
  CHECK(width == 120);
  CHECK(height == 90);
  osmesa_test::drawScene(2);  // sets the viewport from OSMESA_WIDTH/HEIGHT
  CHECK(large == osmesa_test::renderRGBA(120, 90, 2));
  CHECK(small == smallPicture);  // the old buffer is not written after it was left

  // And back: the same bytes as a fresh context of that size (rendered first: renderRGBA makes
  // its own context current).
  const std::vector<uint8_t> fresh = osmesa_test::renderRGBA(40, 30, 1);
  REQUIRE(OSMesaMakeCurrent(ctx, small.data(), GL_UNSIGNED_BYTE, 40, 30));
  osmesa_test::drawScene(1);
  CHECK(small == fresh);
  // The accumulation buffer follows the size.
  glClearAccum(0.5f, 0.5f, 0.5f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  glFinish();
  CHECK(glGetError() == GL_NO_ERROR);
  const int grey = small[(29 * 40 + 39) * 4];
  CHECK(grey >= 127);  // 0.5, through 16-bit accumulation
  CHECK(grey <= 128);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("OSMesaGetColorBuffer and OSMesaGetDepthBuffer") {
  OSMesaContext ctx = createContext(OSMESA_RGB);
  GLint width = -1, height = -1, format = -1, bytes = -1;
  void* pointer = &width;
  CHECK(!OSMesaGetColorBuffer(ctx, &width, &height, &format, &pointer));  // never bound
  CHECK(pointer == nullptr);
  CHECK(!OSMesaGetDepthBuffer(ctx, &width, &height, &bytes, &pointer));
  CHECK(!OSMesaGetColorBuffer(nullptr, &width, &height, &format, &pointer));

  std::vector<uint8_t> buffer(10 * 6 * 3, 0);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 10, 6));
  glClearColor(1.0f, 0.5f, 0.0f, 1.0f);
  glClearDepth(0.5);
  glClearStencil(5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // Without glFinish: OSMesaGetColorBuffer gives the picture drawn so far.
  REQUIRE(OSMesaGetColorBuffer(ctx, &width, &height, &format, &pointer));
  CHECK(width == 10);
  CHECK(height == 6);
  CHECK(format == OSMESA_RGB);
  CHECK(pointer == buffer.data());
  CHECK(buffer[0] == 255);
  CHECK(buffer[1] == 128);

  REQUIRE(OSMesaGetDepthBuffer(ctx, &width, &height, &bytes, &pointer));
  CHECK(width == 10);
  CHECK(height == 6);
  CHECK(bytes == 4);
  const auto* depth = static_cast<const uint32_t*>(pointer);
  CHECK((depth[0] & 0xFFFFFFu) == 0x800000u);  // 0.5 * (2^24 - 1), rounded
  CHECK((depth[0] >> 24) == 5u);
  // The copy is refreshed at glFinish.
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glFinish();
  CHECK((depth[59] & 0xFFFFFFu) == 0xFFFFFFu);
  OSMesaDestroyContext(ctx);
}

TEST_CASE("OSMesaMakeCurrent(NULL) releases, leaving the picture in the buffer") {
  OSMesaContext ctx = createContext(OSMESA_RGBA);
  std::vector<uint8_t> buffer(4 * 4 * 4, 0);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 4, 4));
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0));
  CHECK(OSMesaGetCurrentContext() == nullptr);
  CHECK(buffer[1] == 255);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);  // no context: nothing happens
  glClear(GL_COLOR_BUFFER_BIT);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(buffer[0] == 0);
  OSMesaDestroyContext(ctx);
}

namespace {

// The GL entry points <GL/gl.h> declares.
std::set<std::string> declaredEntryPoints() {
  std::ifstream header(std::string(GLASS_SOURCE_DIR) + "/pipeline/include/GL/gl.h");
  REQUIRE(header);
  const std::string text((std::istreambuf_iterator<char>(header)), std::istreambuf_iterator<char>());
  const std::regex declaration(R"(GLAPIENTRY\s+(gl[A-Z][A-Za-z0-9_]*)\s*\()");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), declaration); it != std::sregex_iterator(); ++it) {
    names.insert((*it)[1]);
  }
  return names;
}

}  // namespace

TEST_CASE("OSMesaGetProcAddress: every GL entry point and OSMesa function, nothing else") {
  const std::set<std::string> names = declaredEntryPoints();
  CHECK(names.size() > 450);
  int missing = 0;
  for (const std::string& name : names) {
    CAPTURE(name);
    const OSMESAproc address = OSMesaGetProcAddress(name.c_str());
    if (!address) ++missing;
    CHECK(reinterpret_cast<void*>(address) == dlsym(RTLD_DEFAULT, name.c_str()));
  }
  CHECK(missing == 0);
  const auto address = [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); };
  CHECK(address("glBegin") == reinterpret_cast<void*>(&glBegin));
  CHECK(address("OSMesaMakeCurrent") == reinterpret_cast<void*>(&OSMesaMakeCurrent));
  CHECK(address("OSMesaGetProcAddress") == reinterpret_cast<void*>(&OSMesaGetProcAddress));
  for (const char* other : {"gluSphere", "glutSolidTeapot", "glassCreateContext", "glNotAFunction",
                            "malloc", "OSMesaNothing", "", "gl"}) {
    CAPTURE(other);
    CHECK(address(other) == nullptr);
  }
  CHECK(address(nullptr) == nullptr);
}
