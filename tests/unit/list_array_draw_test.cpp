// glDrawArrays and glDrawElements compiled into a display list keep their elements' values
// (spec 5.4) and replay them through the batched vertex path (vertex/vertex_arrays.cpp,
// replayCompiledDraw). The picture must be the one the reference gives: the same elements sent
// one by one with glArrayElement between glBegin and glEnd, compiled into a display list too
// (inside a list, quads are split as Mesa's display lists split them: primitive_assembly.cpp).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "core/fast_paths.h"
#include "pipeline_test_support.h"

using glass::test::ScopedContext;

namespace {

constexpr int kSize = 64;
constexpr int kVertices = 96;

struct Arrays {
  std::vector<GLfloat> positions;
  std::vector<GLshort> normals;
  std::vector<GLubyte> colors;
  std::vector<GLfloat> texCoords;
  std::vector<GLuint> indices;
};

// Overlapping triangles of pseudo-random positions, normals, colours and texture coordinates.
Arrays makeArrays() {
  Arrays a;
  uint32_t state = 12345u;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  for (int i = 0; i < kVertices; ++i) {
    a.positions.insert(a.positions.end(), {next() * 2.0f - 1.0f, next() * 2.0f - 1.0f, next() - 0.5f});
    for (int k = 0; k < 3; ++k) a.normals.push_back(static_cast<GLshort>((next() * 2.0f - 1.0f) * 32767.0f));
    for (int k = 0; k < 4; ++k) a.colors.push_back(static_cast<GLubyte>(next() * 255.0f));
    a.texCoords.insert(a.texCoords.end(), {next() * 3.0f, next() * 3.0f});
  }
  for (int i = 0; i < kVertices; ++i) a.indices.push_back(static_cast<GLuint>((i * 37) % kVertices));
  return a;
}

void setUpState(const Arrays& a) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  const GLfloat position1[4] = {-1.0f, 0.5f, 1.0f, 0.0f};
  const GLfloat diffuse1[4] = {0.3f, 0.6f, 0.9f, 1.0f};
  glLightfv(GL_LIGHT1, GL_POSITION, position1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse1);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
  const GLfloat specular[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
  const GLubyte texels[4 * 4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
                                     90, 90, 90, 255, 200, 100, 0, 255, 0, 100, 200, 255, 30, 60, 90, 255,
                                     255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
                                     90, 90, 90, 255, 200, 100, 0, 255, 0, 100, 200, 255, 30, 60, 90, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, a.positions.data());
  glNormalPointer(GL_SHORT, 0, a.normals.data());
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, a.colors.data());
  glTexCoordPointer(2, GL_FLOAT, 0, a.texCoords.data());
}

// The colour buffer after calling the list, which must raise no error.
std::vector<uint8_t> calledPicture(GLuint list) {
  glCallList(list);
  std::vector<uint8_t> pixels = glass::test::readFramebuffer(kSize, kSize);
  CHECK(glGetError() == GL_NO_ERROR);
  return pixels;
}

// List: glDrawArrays and glDrawElements compiled (their elements read a batch at a time);
// ListByReference: the same compiled with the fast paths off (read one element at a time by
// readElement), replayed with them on; ListOfElements: glArrayElement compiled.
enum class Way { List, ListByReference, ListOfElements };

// The colour buffer after drawing the triangles (and the indexed quads) the given way.
std::vector<uint8_t> draw(Way way) {
  ScopedContext context(kSize, kSize);
  const Arrays a = makeArrays();
  setUpState(a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  if (way != Way::ListOfElements) {
    glass::gl::ScopedFastPaths paths(way == Way::List);
    glDrawArrays(GL_TRIANGLES, 0, kVertices);
    glDrawElements(GL_QUADS, kVertices, GL_UNSIGNED_INT, a.indices.data());
  } else {
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < kVertices; ++i) glArrayElement(i);
    glEnd();
    glBegin(GL_QUADS);
    for (const GLuint i : a.indices) glArrayElement(static_cast<GLint>(i));
    glEnd();
  }
  glEndList();
  return calledPicture(list);
}

}  // namespace

TEST_CASE("list_array_draws_replay_like_array_elements") {
  const std::vector<uint8_t> oneByOne = draw(Way::ListOfElements);
  const std::vector<uint8_t> list = draw(Way::List);
  CHECK(list == oneByOne);
  CHECK(draw(Way::ListByReference) == oneByOne);
  // Something was drawn: many pixels differ from the clear colour.
  int drawn = 0;
  for (size_t p = 0; p < list.size(); p += 4) drawn += list[p] != 0 || list[p + 1] != 0 || list[p + 2] != 0;
  CHECK(drawn > kSize * kSize / 4);
}

// The other attributes a compiled draw keeps, read a batch at a time and one element at a time:
// secondary colours and fog coordinates of other types, and edge flags (polygons drawn as
// lines), over more elements than a batch holds, the same picture either way.
TEST_CASE("list_array_draws_keep_every_attribute_read_by_batches") {
  constexpr int kCount = 150;  // quads: three batches, the last one partial
  std::vector<GLdouble> positions;
  std::vector<GLubyte> secondary;
  std::vector<GLdouble> fog;
  std::vector<GLboolean> flags;
  uint32_t state = 99u;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  for (int i = 0; i < kCount; ++i) {
    positions.insert(positions.end(), {next() * 2.0 - 1.0, next() * 2.0 - 1.0, next() - 0.5});
    for (int k = 0; k < 3; ++k) secondary.push_back(static_cast<GLubyte>(next() * 255.0f));
    fog.push_back(next() * 10.0);
    flags.push_back(next() < 0.7f ? GL_TRUE : GL_FALSE);
  }
  const auto picture = [&](bool fastCompile) {
    ScopedContext context(kSize, kSize);
    glEnable(GL_COLOR_SUM);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 10.0f);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glEnableClientState(GL_FOG_COORDINATE_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glVertexPointer(3, GL_DOUBLE, 0, positions.data());
    glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, secondary.data());
    glFogCoordPointer(GL_DOUBLE, 0, fog.data());
    glEdgeFlagPointer(0, flags.data());
    glColor3f(0.2f, 0.3f, 0.1f);
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    {
      glass::gl::ScopedFastPaths paths(fastCompile);
      glDrawArrays(GL_QUADS, 0, kCount - 2);
    }
    glEndList();
    return calledPicture(list);
  };
  const std::vector<uint8_t> batched = picture(true);
  CHECK(batched == picture(false));
  int drawn = 0;
  for (size_t p = 0; p < batched.size(); p += 4) drawn += batched[p] != 0 || batched[p + 1] != 0 || batched[p + 2] != 0;
  CHECK(drawn > kSize * 4);
}
