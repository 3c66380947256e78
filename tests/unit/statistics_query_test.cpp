// GL_GLASS_pipeline_statistics: the counts of GLASS_STATS through query objects, without
// GLASS_STATS, on scenes whose counts follow from the geometry; the errors of misuse; and the
// pictures, which a query leaves byte for byte as they are.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glass_statistics.h>
#include <glass/context.h>

#include <vector>

#include "core/context.h"
#include "pipeline_test_support.h"
#include "teaching/frame_statistics.h"

namespace {

using glass::test::takeError;

GLuint64GLASS resultOf(GLuint query, GLenum pname) {
  GLuint64GLASS value = ~0ull;
  glGetQueryObjectui64vGLASS(query, pname, &value);
  return value;
}

// Whether the current context counts anything (it must not while no query is active).
bool counting() { return glass::gl::frameStatisticsFor(*glass::gl::currentContext()) != nullptr; }

}  // namespace

TEST_CASE("A statistics query counts a triangle wholly clipped and a culled back face") {
  glass::test::ScopedContext context(64, 64);
  CHECK(!counting());
  GLuint query = 0;
  glGenQueriesGLASS(1, &query);
  REQUIRE(query != 0);
  CHECK(glIsQueryGLASS(query) == GL_FALSE);  // a name, not yet a query object (GL 1.5)
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, query);
  CHECK(counting());
  CHECK(glIsQueryGLASS(query) == GL_TRUE);
  GLint current = 0;
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_CURRENT_QUERY_GLASS, &current);
  CHECK(current == static_cast<GLint>(query));
  glEnable(GL_CULL_FACE);  // back faces; counter-clockwise is front
  glBegin(GL_TRIANGLES);
  glVertex2f(1.5f, -0.5f);  // right of x = 1 entirely: clipped away
  glVertex2f(2.5f, -0.5f);
  glVertex2f(1.5f, 0.5f);
  glVertex2f(-0.5f, -0.5f);  // clockwise: culled
  glVertex2f(-0.5f, 0.5f);
  glVertex2f(0.5f, -0.5f);
  glEnd();
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(takeError() == GL_NO_ERROR);
  CHECK(!counting());  // no cost once the query is over
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_CURRENT_QUERY_GLASS, &current);
  CHECK(current == 0);

  CHECK(resultOf(query, GL_QUERY_RESULT_AVAILABLE_GLASS) == GL_TRUE);
  CHECK(resultOf(query, GL_VERTICES_SUBMITTED_GLASS) == 6);
  CHECK(resultOf(query, GL_PRIMITIVES_SUBMITTED_GLASS) == 2);
  CHECK(resultOf(query, GL_TRIANGLES_SUBMITTED_GLASS) == 2);
  CHECK(resultOf(query, GL_POINTS_SUBMITTED_GLASS) == 0);
  CHECK(resultOf(query, GL_LINES_SUBMITTED_GLASS) == 0);
  CHECK(resultOf(query, GL_PRIMITIVES_CULLED_GLASS) == 1);
  CHECK(resultOf(query, GL_PRIMITIVES_CLIPPED_AWAY_GLASS) == 1);
  CHECK(resultOf(query, GL_PRIMITIVES_CLIPPED_GLASS) == 0);
  CHECK(resultOf(query, GL_PRIMITIVES_MADE_BY_CLIPPING_GLASS) == 0);
  CHECK(resultOf(query, GL_FRAGMENTS_GENERATED_GLASS) == 0);
  CHECK(resultOf(query, GL_FRAGMENTS_PASSED_GLASS) == 0);
  GLuint small = 99;
  glGetQueryObjectuivGLASS(query, GL_PRIMITIVES_CULLED_GLASS, &small);
  CHECK(small == 1);
  CHECK(takeError() == GL_NO_ERROR);
  glDeleteQueriesGLASS(1, &query);
  CHECK(glIsQueryGLASS(query) == GL_FALSE);
}

TEST_CASE("A statistics query counts a quad half hidden by depth, a cut triangle, and only what it spans") {
  glass::test::ScopedContext context(64, 64);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 1.0f, -0.5f);  // the near left half, before the query
  GLuint queries[2] = {};
  glGenQueriesGLASS(2, queries);
  CHECK(queries[0] != queries[1]);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, queries[0]);
  // The far quad over the whole window: 64 x 64 fragments, the left 32 x 64 behind the near one.
  glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, 0.5f);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  glass::test::rectangleNdc(-1.0f, -1.0f, 1.0f, 1.0f, -0.9f);  // after the query: not counted
  CHECK(resultOf(queries[0], GL_VERTICES_SUBMITTED_GLASS) == 4);
  CHECK(resultOf(queries[0], GL_TRIANGLES_SUBMITTED_GLASS) == 2);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_GENERATED_GLASS) == 4096);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_DEPTH_FAILED_GLASS) == 2048);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_PASSED_GLASS) == 2048);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_SCISSOR_FAILED_GLASS) == 0);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_ALPHA_FAILED_GLASS) == 0);
  CHECK(resultOf(queries[0], GL_FRAGMENTS_STENCIL_FAILED_GLASS) == 0);
  CHECK(resultOf(queries[0], GL_TEXEL_READS_GLASS) == 0);

  // The scissor box's 16 x 16 pixels pass; the rest of the 2048 pixels of the triangle's fan do
  // not. Cut by x = 1 and y = 1: the pentagon (16,16) (64,16) (64,32) (32,64) (16,64), three
  // triangles.
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(16, 16, 16, 16);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, queries[1]);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);
  glVertex2f(1.5f, -0.5f);
  glVertex2f(-0.5f, 1.5f);
  glEnd();
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(resultOf(queries[1], GL_PRIMITIVES_CLIPPED_GLASS) == 1);
  CHECK(resultOf(queries[1], GL_PRIMITIVES_MADE_BY_CLIPPING_GLASS) == 3);
  CHECK(resultOf(queries[1], GL_FRAGMENTS_PASSED_GLASS) == 256);
  // The pixels (i, j), i and j from 16 to 63, whose centres lie inside x + y < 96: i + j <= 94.
  // The centres with i + j = 95 lie on the hypotenuse, a top-right edge that the fill rule
  // leaves out (spec 3.5.1). 48 x 48 less the pairs summing to 95 - k for k = 1 to 32, k each.
  constexpr int pentagon = 48 * 48 - 32 * 33 / 2;
  CHECK(resultOf(queries[1], GL_FRAGMENTS_GENERATED_GLASS) == pentagon);
  CHECK(resultOf(queries[1], GL_FRAGMENTS_SCISSOR_FAILED_GLASS) == pentagon - 256);
  // The same pixels, drawn without the scissor test.
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.5f, -0.5f);
  glVertex2f(1.5f, -0.5f);
  glVertex2f(-0.5f, 1.5f);
  glEnd();
  int drawn = 0;
  const std::vector<uint8_t> pixels = glass::test::readFramebuffer(64, 64);
  for (std::size_t i = 0; i < pixels.size(); i += 4) drawn += pixels[i] == 255 ? 1 : 0;
  CHECK(drawn == pentagon);
  CHECK(takeError() == GL_NO_ERROR);
}

TEST_CASE("Statistics queries: errors of misuse, as GL 1.5 gives them for occlusion queries") {
  glass::test::ScopedContext context(16, 16);
  GLuint64GLASS value = 7;
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);  // none active
  CHECK(takeError() == GL_INVALID_OPERATION);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 0);  // the name 0
  CHECK(takeError() == GL_INVALID_OPERATION);
  glBeginQueryGLASS(GL_TEXTURE_2D, 5);  // not a query target
  CHECK(takeError() == GL_INVALID_ENUM);
  glGetQueryObjectui64vGLASS(5, GL_VERTICES_SUBMITTED_GLASS, &value);  // not a query object
  CHECK(takeError() == GL_INVALID_OPERATION);
  CHECK(value == 7);

  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 5);  // any unused name will do
  CHECK(takeError() == GL_NO_ERROR);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 6);  // one is active already
  CHECK(takeError() == GL_INVALID_OPERATION);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 5);
  CHECK(takeError() == GL_INVALID_OPERATION);
  glGetQueryObjectui64vGLASS(5, GL_VERTICES_SUBMITTED_GLASS, &value);  // still counting
  CHECK(takeError() == GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);  // between glBegin and glEnd: refused
  glEnd();
  CHECK(takeError() == GL_INVALID_OPERATION);
  GLint current = 0;
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_CURRENT_QUERY_GLASS, &current);
  CHECK(current == 5);
  glEndQueryGLASS(GL_TEXTURE_2D);
  CHECK(takeError() == GL_INVALID_ENUM);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(takeError() == GL_NO_ERROR);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);  // ended already
  CHECK(takeError() == GL_INVALID_OPERATION);

  glGetQueryObjectui64vGLASS(5, GL_TEXTURE_2D, &value);  // not a count
  CHECK(takeError() == GL_INVALID_ENUM);
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_TEXTURE_2D, nullptr);
  CHECK(takeError() == GL_INVALID_ENUM);
  GLint bits = 0;
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_QUERY_COUNTER_BITS_GLASS, &bits);
  CHECK(bits == 64);
  GLuint names[1];
  glGenQueriesGLASS(-1, names);
  CHECK(takeError() == GL_INVALID_VALUE);
  glDeleteQueriesGLASS(-1, names);
  CHECK(takeError() == GL_INVALID_VALUE);

  // A deleted active query counts on to glEndQueryGLASS, and its result goes nowhere.
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 8);
  const GLuint eight = 8;
  glDeleteQueriesGLASS(1, &eight);
  CHECK(glIsQueryGLASS(8) == GL_FALSE);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 9);
  CHECK(takeError() == GL_INVALID_OPERATION);
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(takeError() == GL_NO_ERROR);
  glGetQueryObjectui64vGLASS(8, GL_VERTICES_SUBMITTED_GLASS, &value);
  CHECK(takeError() == GL_INVALID_OPERATION);
  CHECK(!counting());
}

TEST_CASE("A statistics query in a display list, and one spanning frames beside GLASS_STATS") {
  glass::test::ScopedEnvironment statistics("GLASS_STATS", "1");
  glass::test::ScopedContext context(64, 64);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 3);
  glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 0.5f, 0.0f);  // 32 x 48 pixels
  glEndList();
  GLint current = -1;
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_CURRENT_QUERY_GLASS, &current);
  CHECK(current == 0);  // compiled, not run
  glCallList(list);
  glGetQueryivGLASS(GL_PIPELINE_STATISTICS_GLASS, GL_CURRENT_QUERY_GLASS, &current);
  CHECK(current == 3);
  glassGetColorBuffer(context.get());  // frame 0 ends: GLASS_STATS reports it
  glass::test::rectangleNdc(-1.0f, -1.0f, 0.0f, 0.5f, 0.0f);
  glFinish();
  const glass::gl::FrameStatistics* frame = glass::gl::frameStatisticsFor(*glass::gl::currentContext());
  REQUIRE(frame != nullptr);
  CHECK(frame->frame == 1);
  CHECK(frame->fragments == 1536);  // GLASS_STATS's frame holds its own frame only
  glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
  CHECK(resultOf(3, GL_VERTICES_SUBMITTED_GLASS) == 8);
  CHECK(resultOf(3, GL_FRAGMENTS_GENERATED_GLASS) == 2 * 1536);
  CHECK(counting());  // GLASS_STATS goes on counting
  CHECK(takeError() == GL_NO_ERROR);
  glDeleteLists(list, 1);
}

TEST_CASE("A statistics query leaves the pictures byte for byte as they are") {
  // Depth, scissor, alpha and stencil tests, a mipmapped texture and blending: every stage whose
  // fast path the counting turns off.
  auto draw = [](bool query) {
    glass::test::ScopedContext context(64, 64);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    std::vector<unsigned char> texels(16 * 16 * 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<unsigned char>(i * 37 % 251);
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    if (query) glBeginQueryGLASS(GL_PIPELINE_STATISTICS_GLASS, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4f(0.9f, 0.5f, 0.1f, 0.7f);
    glass::test::rectangleNdc(-0.8f, -0.8f, 0.4f, 0.6f, 0.2f);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_SCISSOR_TEST);
    glScissor(8, 4, 40, 50);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.3f);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 10);
    glTranslatef(0.0f, 0.0f, -2.0f);
    glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
    glass::test::rectangleNdc(-1.5f, -1.5f, 1.5f, 1.5f, 0.0f);
    if (query) glEndQueryGLASS(GL_PIPELINE_STATISTICS_GLASS);
    CHECK(takeError() == GL_NO_ERROR);
    if (query) CHECK(resultOf(1, GL_TEXEL_READS_GLASS) > 0);
    const unsigned char* shown = glassGetColorBuffer(context.get());
    return std::vector<unsigned char>(shown, shown + 64 * 64 * 4);
  };
  const std::vector<unsigned char> plain = draw(false);
  const std::vector<unsigned char> queried = draw(true);
  CHECK(plain == queried);
}
