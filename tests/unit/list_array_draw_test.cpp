// glDrawArrays and glDrawElements compiled into a display list keep their elements' values
// (spec 5.4) and replay them through the batched vertex path (vertex/vertex_arrays.cpp,
// replayCompiledDraw). The picture must be the one the reference gives: the same elements sent
// one by one with glArrayElement between glBegin and glEnd, compiled into a display list too
// (inside a list, quads are split as Mesa's display lists split them: primitive_assembly.cpp).
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

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

enum class Way { List, ListOfElements };

// The colour buffer after drawing the triangles (and the indexed quads) the given way.
std::vector<uint8_t> draw(Way way) {
  ScopedContext context(kSize, kSize);
  const Arrays a = makeArrays();
  setUpState(a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  if (way == Way::List) {
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
  glCallList(list);
  std::vector<uint8_t> pixels(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  CHECK(glGetError() == GL_NO_ERROR);
  return pixels;
}

}  // namespace

TEST_CASE("list_array_draws_replay_like_array_elements") {
  const std::vector<uint8_t> oneByOne = draw(Way::ListOfElements);
  const std::vector<uint8_t> list = draw(Way::List);
  CHECK(list == oneByOne);
  // Something was drawn: many pixels differ from the clear colour.
  int drawn = 0;
  for (size_t p = 0; p < list.size(); p += 4) drawn += list[p] != 0 || list[p + 1] != 0 || list[p + 2] != 0;
  CHECK(drawn > kSize * kSize / 4);
}
