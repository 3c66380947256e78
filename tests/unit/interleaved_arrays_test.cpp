// glInterleavedArrays (spec 2.8, table 2.5): each of the fourteen layouts sets the arrays it names
// with the right sizes, types, offsets and stride, and disables the others.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

struct Layout {
  GLenum format;
  int texCoords, colors;
  GLenum colorType;
  bool normal;
  int vertices;
  int colorOffset, normalOffset, vertexOffset, stride;  // in bytes
};

constexpr int f = 4;
const Layout kLayouts[] = {
    {GL_V2F, 0, 0, 0, false, 2, 0, 0, 0, 2 * f},
    {GL_V3F, 0, 0, 0, false, 3, 0, 0, 0, 3 * f},
    {GL_C4UB_V2F, 0, 4, GL_UNSIGNED_BYTE, false, 2, 0, 0, 4, 4 + 2 * f},
    {GL_C4UB_V3F, 0, 4, GL_UNSIGNED_BYTE, false, 3, 0, 0, 4, 4 + 3 * f},
    {GL_C3F_V3F, 0, 3, GL_FLOAT, false, 3, 0, 0, 3 * f, 6 * f},
    {GL_N3F_V3F, 0, 0, 0, true, 3, 0, 0, 3 * f, 6 * f},
    {GL_C4F_N3F_V3F, 0, 4, GL_FLOAT, true, 3, 0, 4 * f, 7 * f, 10 * f},
    {GL_T2F_V3F, 2, 0, 0, false, 3, 0, 0, 2 * f, 5 * f},
    {GL_T4F_V4F, 4, 0, 0, false, 4, 0, 0, 4 * f, 8 * f},
    {GL_T2F_C4UB_V3F, 2, 4, GL_UNSIGNED_BYTE, false, 3, 2 * f, 0, 4 + 2 * f, 4 + 5 * f},
    {GL_T2F_C3F_V3F, 2, 3, GL_FLOAT, false, 3, 2 * f, 0, 5 * f, 8 * f},
    {GL_T2F_N3F_V3F, 2, 0, 0, true, 3, 0, 2 * f, 5 * f, 8 * f},
    {GL_T2F_C4F_N3F_V3F, 2, 4, GL_FLOAT, true, 3, 2 * f, 6 * f, 9 * f, 12 * f},
    {GL_T4F_C4F_N3F_V4F, 4, 4, GL_FLOAT, true, 4, 4 * f, 8 * f, 11 * f, 15 * f},
};

GLint integer(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

const void* pointer(GLenum pname) {
  GLvoid* p = nullptr;
  glGetPointerv(pname, &p);
  return p;
}

}  // namespace

TEST_CASE("interleaved arrays: the fourteen layouts of table 2.5") {
  ScopedContext context(8, 8);
  const unsigned char data[256] = {};
  for (const Layout& l : kLayouts) {
    CAPTURE(l.format);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glInterleavedArrays(l.format, 0, data);
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK_FALSE(glIsEnabled(GL_EDGE_FLAG_ARRAY));
    CHECK(glIsEnabled(GL_VERTEX_ARRAY));
    CHECK(integer(GL_VERTEX_ARRAY_SIZE) == l.vertices);
    CHECK(integer(GL_VERTEX_ARRAY_TYPE) == GL_FLOAT);
    CHECK(integer(GL_VERTEX_ARRAY_STRIDE) == l.stride);
    CHECK(pointer(GL_VERTEX_ARRAY_POINTER) == data + l.vertexOffset);
    CHECK(static_cast<bool>(glIsEnabled(GL_TEXTURE_COORD_ARRAY)) == (l.texCoords > 0));
    if (l.texCoords > 0) {
      CHECK(integer(GL_TEXTURE_COORD_ARRAY_SIZE) == l.texCoords);
      CHECK(pointer(GL_TEXTURE_COORD_ARRAY_POINTER) == data);
    }
    CHECK(static_cast<bool>(glIsEnabled(GL_COLOR_ARRAY)) == (l.colors > 0));
    if (l.colors > 0) {
      CHECK(integer(GL_COLOR_ARRAY_SIZE) == l.colors);
      CHECK(integer(GL_COLOR_ARRAY_TYPE) == static_cast<GLint>(l.colorType));
      CHECK(pointer(GL_COLOR_ARRAY_POINTER) == data + l.colorOffset);
    }
    CHECK(static_cast<bool>(glIsEnabled(GL_NORMAL_ARRAY)) == l.normal);
    if (l.normal) CHECK(pointer(GL_NORMAL_ARRAY_POINTER) == data + l.normalOffset);
  }
  // A stride given replaces the layout's own.
  glInterleavedArrays(GL_C3F_V3F, 40, data);
  CHECK(integer(GL_VERTEX_ARRAY_STRIDE) == 40);
  CHECK(integer(GL_COLOR_ARRAY_STRIDE) == 40);
}

TEST_CASE("interleaved arrays: drawing from an interleaved block") {
  ScopedContext context(8, 8);
  glass::test::pixelProjection(8, 8);
  // GL_T2F_C4UB_V3F: s, t, r, g, b, a (bytes), x, y, z; points at pixel centres.
  struct Vertex {
    float s, t;
    uint8_t rgba[4];
    float x, y, z;
  };
  static_assert(sizeof(Vertex) == 4 + 5 * 4, "the layout of GL_T2F_C4UB_V3F");
  const Vertex vertices[2] = {{0, 0, {255, 0, 0, 255}, 1.5f, 1.5f, 0}, {0, 0, {0, 0, 255, 255}, 5.5f, 6.5f, 0}};
  glInterleavedArrays(GL_T2F_C4UB_V3F, 0, vertices);
  glDrawArrays(GL_POINTS, 0, 2);
  CHECK(glass::test::pixelAt(1, 1) == glass::test::Rgba{255, 0, 0, 255});
  CHECK(glass::test::pixelAt(5, 6) == glass::test::Rgba{0, 0, 255, 255});
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("interleaved arrays: errors") {
  ScopedContext context(8, 8);
  const float data[4] = {};
  glInterleavedArrays(GL_RGBA, 0, data);
  CHECK(glGetError() == GL_INVALID_ENUM);
  glInterleavedArrays(GL_V2F, -4, data);
  CHECK(glGetError() == GL_INVALID_VALUE);
  glBegin(GL_POINTS);
  glInterleavedArrays(GL_V2F, 0, data);
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);
}
