// Vertices without a window position: w_c = 0 (the clip-space origin, which lies on every frustum
// plane and so passes clipping), NaN and infinite coordinates. Each primitive that needs such a
// vertex's window position draws nothing and sets no error (spec 2.1.1: undefined results, but
// no interruption), on every path: points, lines, wide, stippled and smooth ones, polygons in
// every mode, the raster position with glBitmap and glDrawPixels, feedback and selection, and the
// tiled rasterizer fed such window coordinates directly.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "glass/raster/clip.h"
#include "glass/raster/framebuffer.h"
#include "glass/raster/tiled_rasterizer.h"
#include "pipeline_test_support.h"
#include "raster_test_support.h"

using glass::test::ScopedContext;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Clip coordinates equal object coordinates (identity matrices); the buffer starts black.
void resetToIdentity() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
}

size_t litPixels(const ScopedContext& c) {
  const std::vector<uint8_t> pixels = glass::test::readFramebuffer(c.width(), c.height());
  size_t lit = 0;
  for (size_t i = 0; i < pixels.size(); i += 4) lit += pixels[i] != 0;
  return lit;
}

struct Vertex4 {
  float x, y, z, w;
};

// The vertices that have no window position, each with a well-behaved companion vertex.
const Vertex4 kUnprojectable[] = {
    {0, 0, 0, 0}, {kNaN, 0, 0, 1}, {0, 0, 0, kNaN}, {kInf, 0, 0, 1}, {0, -kInf, 0, 1},
    {0, 0, 0, kInf}, {kInf, kInf, kInf, kInf}, {0.5f, 0.5f, kNaN, 1}};

}  // namespace

TEST_CASE("non-finite vertices: clipping puts them outside every plane and drops their primitives") {
  using namespace glass::raster;
  using glass::raster::test::clipVertex;
  const ClipSettings settings;
  CHECK(outcode(clipVertex(0, 0, 0, 0), settings) == 0u);  // the origin is inside (spec 2.12)
  for (const ClipVertex& v : {clipVertex(kNaN, 0, 0, 1), clipVertex(0, kInf, 0, 1),
                              clipVertex(0, 0, 0, kInf), clipVertex(0, 0, -kInf, 1)}) {
    CHECK(outcode(v, settings) == (0x3Fu | kNotFinite));
    CHECK_FALSE(pointInside(v, settings));
    ClipVertex a = clipVertex(0, 0, 0, 1), b = v;
    CHECK_FALSE(clipLine(a, b, settings));
    a = clipVertex(0, 0, 0, 1);
    b = v;
    CHECK_FALSE(clipLine(b, a, settings));
    const ClipVertex triangle[3] = {clipVertex(0, 0, 0, 1), clipVertex(0.5f, 0, 0, 1), v};
    ClipVertex out[kMaxClippedPolygonVertices + 3];
    CHECK(clipPolygon(triangle, 3, settings, out) == 0);
  }
}

TEST_CASE("non-finite vertices: points, lines and polygons through them draw nothing") {
  ScopedContext context(32, 32);
  struct Setting {
    const char* name;
    void (*apply)();
  };
  const Setting settings[] = {
      {"plain", [] {}},
      {"wide", [] {
         glLineWidth(5);
         glPointSize(5);
       }},
      {"stippled", [] {
         glEnable(GL_LINE_STIPPLE);
         glLineStipple(1, 0x0F0F);
       }},
      {"smooth", [] {
         glEnable(GL_POINT_SMOOTH);
         glEnable(GL_LINE_SMOOTH);
         glEnable(GL_BLEND);
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
         glLineWidth(3);
         glPointSize(4);
       }},
      {"smooth stippled", [] {
         glEnable(GL_LINE_SMOOTH);
         glEnable(GL_LINE_STIPPLE);
         glLineStipple(2, 0x3333);
       }},
      {"attenuated points", [] {
         const GLfloat attenuation[3] = {0, 1, 0};
         glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
         glPointSize(8);
       }},
      {"polygon lines", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); }},
      {"polygon points", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_POINT); }},
      {"polygon offset", [] {
         glEnable(GL_POLYGON_OFFSET_FILL);
         glPolygonOffset(1, 1);
       }},
  };
  // With v0 bad and v1, v2, v3 good: what the primitives without v0 draw. A segment or triangle
  // with v0 draws nothing, the others are unaffected (a strip's stipple counter only advances
  // with fragments, so it is the same).
  struct Case {
    GLenum mode;
    GLenum expectedMode;
    std::vector<int> expectedVertices;
  };
  const std::vector<Case> fillCases = {
      {GL_POINTS, GL_POINTS, {1, 2, 3}},        {GL_LINES, GL_LINES, {2, 3}},
      {GL_LINE_STRIP, GL_LINE_STRIP, {1, 2, 3}}, {GL_LINE_LOOP, GL_LINE_STRIP, {1, 2, 3}},
      {GL_TRIANGLES, GL_POINTS, {}},            {GL_TRIANGLE_FAN, GL_POINTS, {}},
      // A quad that needs clipping is drawn as the triangles (0, 1, 3) and (1, 2, 3), as Mesa
      // splits it (primitive_assembly.cpp); the second has no bad vertex. (The clip-space origin
      // needs no clipping: that quad is split along 0-2, and both its triangles have it.)
      {GL_QUADS, GL_TRIANGLES, {1, 2, 3}},      {GL_POLYGON, GL_POINTS, {}}};
  const Vertex4 good[4] = {{0, 0, 0, 1}, {0.5f, 0.5f, 0, 1}, {-0.5f, 0.75f, 0, 1}, {-0.5f, -0.5f, 0, 1}};
  for (const Setting& setting : settings) {
    const bool polygonLines = std::string(setting.name) == "polygon lines";
    const bool polygonPoints = std::string(setting.name) == "polygon points";
    std::vector<Case> cases = fillCases;
    if (polygonLines || polygonPoints) {  // the edges (or vertices) of triangle v0 v1 v2 without v0
      cases = {{GL_TRIANGLES, polygonLines ? GLenum(GL_LINES) : GLenum(GL_POINTS), {1, 2}}};
    }
    for (const Vertex4& bad : kUnprojectable) {
      for (const Case& c : cases) {
        const std::string settingName = setting.name;
        CAPTURE(settingName);
        CAPTURE(c.mode);
        CAPTURE(bad.x);
        CAPTURE(bad.z);
        CAPTURE(bad.w);
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        setting.apply();
        resetToIdentity();
        glBegin(c.mode);
        glVertex4f(bad.x, bad.y, bad.z, bad.w);
        for (int i = 1; i < 4; ++i) glVertex4f(good[i].x, good[i].y, good[i].z, good[i].w);
        glEnd();
        const std::vector<uint8_t> drawn = glass::test::readFramebuffer(context.width(), context.height());
        CHECK(glGetError() == GL_NO_ERROR);

        resetToIdentity();
        glBegin(c.expectedMode);
        const bool unclippedQuad = c.mode == GL_QUADS && bad.w == 0.0f;
        for (int i : c.expectedVertices)
          if (!unclippedQuad) glVertex4f(good[i].x, good[i].y, good[i].z, good[i].w);
        glEnd();
        const std::vector<uint8_t> expected = glass::test::readFramebuffer(context.width(), context.height());
        CHECK(drawn == expected);
        glPopAttrib();
      }
    }
  }
}

TEST_CASE("non-finite vertices: the segment into the clip-space origin draws nothing") {
  // Every point of a segment from (0, 0, 0, 0) to v other than the origin projects to v's
  // window position, and the segment that crosses w = 0 through the origin is clipped to such a
  // segment: no length, no fragments (and no NaN window coordinates on the way).
  ScopedContext context(32, 32);
  resetToIdentity();
  glLineWidth(3);
  glBegin(GL_LINES);
  glVertex4f(0, 0, 0, 0);
  glVertex4f(0.5f, 0.25f, 0, 1);
  glVertex4f(-1, -0.5f, 0, -1);
  glVertex4f(1, 0.5f, 0, 1);
  glEnd();
  glFinish();
  CHECK(litPixels(context) == 0);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("non-finite vertices: a raster position without a window position is invalid") {
  ScopedContext context(32, 32);
  for (const Vertex4& bad : kUnprojectable) {
    CAPTURE(bad.x);
    CAPTURE(bad.w);
    resetToIdentity();
    glRasterPos2f(0, 0);
    GLboolean valid = GL_FALSE;
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    REQUIRE(valid == GL_TRUE);
    glRasterPos4f(bad.x, bad.y, bad.z, bad.w);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK(valid == GL_FALSE);
    // 8 rows of one byte each, every row padded to GL_UNPACK_ALIGNMENT (4 by default, GL 1.4
    // section 3.6.4): glBitmap reads 8 x 4 bytes.
    GLubyte bitmap[8 * 4];
    for (GLubyte& row : bitmap) row = 0xFF;
    glBitmap(8, 8, 0, 0, 4, 4, bitmap);
    const GLubyte image[4 * 4 * 4] = {255, 255, 255, 255};
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glFinish();
    CHECK(litPixels(context) == 0);
    CHECK(glGetError() == GL_NO_ERROR);
  }
}

TEST_CASE("non-finite vertices: feedback and selection record nothing for them") {
  ScopedContext context(32, 32);
  resetToIdentity();
  for (const Vertex4& bad : kUnprojectable) {
    CAPTURE(bad.x);
    CAPTURE(bad.w);
    GLfloat feedback[64];
    glFeedbackBuffer(64, GL_3D, feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex4f(bad.x, bad.y, bad.z, bad.w);
    glEnd();
    glBegin(GL_LINES);
    glVertex4f(bad.x, bad.y, bad.z, bad.w);
    glVertex4f(0.5f, 0.5f, 0, 1);
    glEnd();
    glRasterPos4f(bad.x, bad.y, bad.z, bad.w);
    glPassThrough(1);
    CHECK(glRenderMode(GL_RENDER) == 2);  // the pass-through token and its value only

    GLuint names[16];
    glSelectBuffer(16, names);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glBegin(GL_POINTS);
    glVertex4f(bad.x, bad.y, bad.z, bad.w);
    glEnd();
    glRasterPos4f(bad.x, bad.y, bad.z, bad.w);
    CHECK(glRenderMode(GL_RENDER) == 0);  // no hit
    CHECK(glGetError() == GL_NO_ERROR);
  }
}

TEST_CASE("non-finite vertices: the tiled rasterizer bins nothing for window coordinates it cannot draw") {
  using namespace glass::raster;
  Framebuffer framebuffer(128, 128);
  test::RecordingSink sink;
  for (int threads : {1, 2}) {
    TiledRasterizer tiles(framebuffer, threads);
    LineSettings line;
    line.bounds = {0, 0, 128, 128};
    line.framebufferHeight = 128;
    line.width = 3;
    PointSettings point;
    point.bounds = line.bounds;
    point.size = 3;
    for (float bad : {kNaN, kInf, -kInf, 1e30f}) {
      WindowVertex a{}, b{};
      a.x = 10;
      a.y = 10;
      b.x = bad;
      b.y = 20;
      tiles.line(a, b, line, sink);
      tiles.line(b, a, line, sink);
      tiles.point(b, point, sink);
      std::swap(b.x, b.y);
      tiles.point(b, point, sink);
      // A good point whose size is not a number draws as size 1; an infinite one is clamped.
      point.size = bad;
      tiles.point(a, point, sink);
      point.size = 3;
    }
    tiles.finish();
    // Only the good point with a bad size: NaN and -inf as size 1, inf and 1e30 as the largest
    // size, which covers the framebuffer.
    CHECK(sink.writesAt(10, 10) == 4);
    CHECK(sink.writesAt(11, 10) == 2);
    CHECK(sink.writesAt(127, 0) == 2);
    CHECK(sink.writes.size() == 128u * 128u);
    sink.clear();
  }
}
