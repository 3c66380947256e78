// GL_GLASS_pipeline_statistics in an OSMesa program: the entry points found by name as a program
// loading them would find them, hand-computed counts of known scenes, and the caller's buffer
// byte for byte the same with a query active (docs/teaching.md).
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glass_statistics.h>
#include <GL/osmesa.h>

#include <cstring>
#include <vector>

#include "osmesa_test_scene.h"

namespace {

constexpr int kSize = 32;

GLuint resultOf(GLuint query, GLenum pname) {
  GLuint value = ~0u;
  glGetQueryObjectuivGLASS(query, pname, &value);
  return value;
}

// A 32 x 32 buffer bound to a fresh RGBA context; the context is destroyed with the object.
struct BoundContext {
  OSMesaContext ctx = osmesa_test::createContext(OSMESA_RGBA);
  std::vector<unsigned char> buffer = std::vector<unsigned char>(kSize * kSize * 4, 0);
  BoundContext() { REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)); }
  ~BoundContext() { OSMesaDestroyContext(ctx); }
  BoundContext(const BoundContext&) = delete;
  BoundContext& operator=(const BoundContext&) = delete;
};

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

}  // namespace

TEST_CASE("GL_GLASS_pipeline_statistics: listed, its entry points found by OSMesaGetProcAddress") {
  BoundContext bound;
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  REQUIRE(extensions != nullptr);
  CHECK(std::strstr(extensions, "GL_GLASS_pipeline_statistics") != nullptr);
  for (const char* name : {"glGenQueriesGLASS", "glDeleteQueriesGLASS", "glIsQueryGLASS", "glBeginQueryGLASS",
                           "glEndQueryGLASS", "glGetQueryivGLASS", "glGetQueryObjectuivGLASS",
                           "glGetQueryObjectui64vGLASS"}) {
    CAPTURE(name);
    const bool found = OSMesaGetProcAddress(name) != nullptr;
    CHECK(found);
  }
  const bool same = reinterpret_cast<void (*)()>(OSMesaGetProcAddress("glBeginQueryGLASS")) ==
                    reinterpret_cast<void (*)()>(&glBeginQueryGLASS);
  CHECK(same);
}

TEST_CASE("GL_GLASS_pipeline_statistics in OSMesa: a back face culled, one clipped away, a quad half hidden") {
  BoundContext bound;
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  quad(-1.0f, -1.0f, 1.0f, 0.0f, -0.5f);  // the near bottom half, before the query
  GLuint query = 0;
  glGenQueriesGLASS(1, &query);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, query);
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);  // clockwise: a back face, culled
  glVertex2f(-0.5f, 0.5f);
  glVertex2f(0.5f, -0.5f);
  glVertex2f(-3.0f, 0.0f);  // left of x = -1 entirely: clipped away
  glVertex2f(-2.0f, 0.0f);
  glVertex2f(-2.5f, 0.5f);
  glEnd();
  quad(-1.0f, -1.0f, 1.0f, 1.0f, 0.5f);  // far, over the whole buffer: the bottom half hidden
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(resultOf(query, GL_VERTICES_SUBMITTED_GLASS) == 10);
  CHECK(resultOf(query, GL_PRIMITIVES_SUBMITTED_GLASS) == 4);
  CHECK(resultOf(query, GL_PRIMITIVES_CULLED_GLASS) == 1);
  CHECK(resultOf(query, GL_PRIMITIVES_CLIPPED_AWAY_GLASS) == 1);
  CHECK(resultOf(query, GL_FRAGMENTS_GENERATED_GLASS) == kSize * kSize);
  CHECK(resultOf(query, GL_FRAGMENTS_DEPTH_FAILED_GLASS) == kSize * kSize / 2);
  CHECK(resultOf(query, GL_FRAGMENTS_PASSED_GLASS) == kSize * kSize / 2);
  // Begun twice: the second is refused and the first goes on.
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, query);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, query + 1);
  CHECK(glGetError() == GL_INVALID_OPERATION);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(resultOf(query, GL_VERTICES_SUBMITTED_GLASS) == 0);
}

TEST_CASE("GL_GLASS_pipeline_statistics in OSMesa: the buffer is the same bytes with a query active") {
  std::vector<unsigned char> plain, queried;
  {
    BoundContext bound;
    osmesa_test::drawScene(1);
    plain = bound.buffer;
  }
  {
    BoundContext bound;
    glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 1);
    osmesa_test::drawScene(1);
    glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK(resultOf(1, GL_FRAGMENTS_PASSED_GLASS) > 0);
    CHECK(resultOf(1, GL_TEXEL_READS_GLASS) > 0);  // the scene is textured
    queried = bound.buffer;
  }
  CHECK(plain == queried);
  const std::vector<unsigned char> background(plain.size(), plain[0]);
  CHECK(plain != background);  // something was drawn
}
