// Vertex arrays (spec 2.8) give the same pixels as the same vertices in immediate mode, for
// glDrawArrays, glDrawElements with each index type, glArrayElement, strides and component types.
#include <GL/gl.h>
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "pipeline_test_support.h"

using glass::test::readFramebuffer;
using glass::test::ScopedContext;

namespace {

constexpr int kSize = 48;

// A fan of triangles with coloured vertices, in interleaved records.
struct Vertex {
  GLshort position[2];
  GLubyte color[4];
  GLfloat texCoord[2];
};

std::vector<Vertex> meshVertices() {
  std::vector<Vertex> v;
  for (int i = 0; i < 9; ++i) {
    const double a = i * 0.7;
    Vertex vertex{};
    vertex.position[0] = static_cast<GLshort>(24 + std::lround(20 * std::cos(a)) * (i % 2 ? 1 : -1) / 2 + (i % 3));
    vertex.position[1] = static_cast<GLshort>(24 + std::lround(20 * std::sin(a)));
    vertex.color[0] = static_cast<GLubyte>(30 * i);
    vertex.color[1] = static_cast<GLubyte>(255 - 25 * i);
    vertex.color[2] = static_cast<GLubyte>(i * 77 % 256);
    vertex.color[3] = 255;
    vertex.texCoord[0] = static_cast<GLfloat>(i);
    v.push_back(vertex);
  }
  return v;
}

const GLenum kModes[] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                         GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};

void sendImmediate(GLenum mode, const std::vector<Vertex>& v, const std::vector<int>& order) {
  glBegin(mode);
  for (int i : order) {
    glColor4ub(v[i].color[0], v[i].color[1], v[i].color[2], v[i].color[3]);
    glVertex2s(v[i].position[0], v[i].position[1]);
  }
  glEnd();
}

std::vector<uint8_t> renderImmediate(GLenum mode, const std::vector<Vertex>& v,
                                     const std::vector<int>& order) {
  glClear(GL_COLOR_BUFFER_BIT);
  sendImmediate(mode, v, order);
  return readFramebuffer(kSize, kSize);
}

// What glDrawElements must draw: the same vertices in immediate mode, except that indexed quads
// are split along v1-v3 as Mesa splits them (primitive_assembly.cpp, drawQuads), which immediate
// mode does inside a display list.
std::vector<uint8_t> renderIndexedExpectation(GLenum mode, const std::vector<Vertex>& v,
                                              const std::vector<int>& order) {
  if (mode != GL_QUADS) return renderImmediate(mode, v, order);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  sendImmediate(mode, v, order);
  glEndList();
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(list);
  glDeleteLists(list, 1);
  return readFramebuffer(kSize, kSize);
}

}  // namespace

TEST_CASE("pipeline arrays: vertex arrays draw exactly what immediate mode draws") {
  ScopedContext context(kSize, kSize);
  glass::test::pixelProjection(kSize, kSize);
  const std::vector<Vertex> v = meshVertices();
  glVertexPointer(2, GL_SHORT, sizeof(Vertex), &v[0].position);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), &v[0].color);
  glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), &v[0].texCoord);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);

  const std::vector<int> inOrder = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<int> shuffled = {8, 3, 5, 0, 7, 2, 6, 1, 4};
  for (GLenum mode : kModes) {
    CAPTURE(mode);
    const std::vector<uint8_t> expected = renderImmediate(mode, v, inOrder);

    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(mode, 0, 9);
    CHECK(readFramebuffer(kSize, kSize) == expected);

    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(mode);
    for (int i : inOrder) glArrayElement(i);
    glEnd();
    CHECK(readFramebuffer(kSize, kSize) == expected);

    const std::vector<uint8_t> expectedShuffled = renderIndexedExpectation(mode, v, shuffled);
    const std::vector<GLubyte> indices8(shuffled.begin(), shuffled.end());
    const std::vector<GLushort> indices16(shuffled.begin(), shuffled.end());
    const std::vector<GLuint> indices32(shuffled.begin(), shuffled.end());
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(mode, 9, GL_UNSIGNED_BYTE, indices8.data());
    CHECK(readFramebuffer(kSize, kSize) == expectedShuffled);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(mode, 9, GL_UNSIGNED_SHORT, indices16.data());
    CHECK(readFramebuffer(kSize, kSize) == expectedShuffled);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(mode, 9, GL_UNSIGNED_INT, indices32.data());
    CHECK(readFramebuffer(kSize, kSize) == expectedShuffled);
  }

  // After a draw, the current attributes are those of the last element (spec 2.8).
  GLfloat texCoord[4];
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, texCoord);
  CHECK(texCoord[0] == 4.0f);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("pipeline arrays: component types convert as the immediate commands do") {
  ScopedContext context(kSize, kSize);
  glass::test::pixelProjection(kSize, kSize);
  // The same triangle as floats, doubles and ints; colours as floats, unsigned shorts and bytes.
  const GLfloat positionsF[6] = {2, 2, 40, 6, 10, 44};
  const GLdouble positionsD[6] = {2, 2, 40, 6, 10, 44};
  const GLint positionsI[6] = {2, 2, 40, 6, 10, 44};
  const GLfloat colorsF[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const GLushort colorsUS[9] = {65535, 0, 0, 0, 65535, 0, 0, 0, 65535};
  const GLbyte colorsB[9] = {127, -128, -128, -128, 127, -128, -128, -128, 127};

  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0), glVertex2f(2, 2);
  glColor3f(0, 1, 0), glVertex2f(40, 6);
  glColor3f(0, 0, 1), glVertex2f(10, 44);
  glEnd();
  const std::vector<uint8_t> expected = readFramebuffer(kSize, kSize);

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  const struct {
    GLenum vertexType;
    const void* vertices;
    GLenum colorType;
    const void* colors;
  } cases[] = {{GL_FLOAT, positionsF, GL_FLOAT, colorsF},
               {GL_DOUBLE, positionsD, GL_UNSIGNED_SHORT, colorsUS},
               {GL_INT, positionsI, GL_BYTE, colorsB}};
  for (const auto& c : cases) {
    CAPTURE(c.vertexType);
    glVertexPointer(2, c.vertexType, 0, c.vertices);
    glColorPointer(3, c.colorType, 0, c.colors);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK(readFramebuffer(kSize, kSize) == expected);
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

TEST_CASE("pipeline arrays: long triangle lists draw every triangle across the vertex batches, with edge flags") {
  // More vertices than a batch of the vertex stage holds (kVertexBatch), and a count that is not
  // a multiple of it or of 3, so that triangles straddle batches and the last one is incomplete.
  ScopedContext context(kSize, kSize);
  glass::test::pixelProjection(kSize, kSize);
  std::vector<Vertex> v;
  for (int i = 0; i < 3 * 97 + 2; ++i) {
    const double a = i * 2.39996;  // the golden angle: vertices spread over the disc
    const double r = 4.0 + (i * 37 % 19);
    Vertex vertex{};
    vertex.position[0] = static_cast<GLshort>(24 + std::lround(r * std::cos(a)));
    vertex.position[1] = static_cast<GLshort>(24 + std::lround(r * std::sin(a)));
    vertex.color[0] = static_cast<GLubyte>(i * 53 % 256);
    vertex.color[1] = static_cast<GLubyte>(i * 101 % 256);
    vertex.color[2] = static_cast<GLubyte>(i * 29 % 256);
    vertex.color[3] = 255;
    v.push_back(vertex);
  }
  std::vector<GLboolean> edgeFlags(v.size());
  for (size_t i = 0; i < v.size(); ++i) edgeFlags[i] = (i * 7 % 3) != 0 ? GL_TRUE : GL_FALSE;
  std::vector<GLuint> indices(v.size());
  for (size_t i = 0; i < v.size(); ++i) indices[i] = static_cast<GLuint>(i * 5 % v.size());  // 5 is prime to the count
  const int count = static_cast<int>(v.size());
  glVertexPointer(2, GL_SHORT, sizeof(Vertex), &v[0].position);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), &v[0].color);
  glEdgeFlagPointer(0, edgeFlags.data());
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);

  for (const GLenum polygonMode : {GL_FILL, GL_LINE}) {
    CAPTURE(polygonMode);
    glPolygonMode(GL_FRONT_AND_BACK, polygonMode);
    // Each triangle in a glBegin/glEnd of its own: vertex by vertex through the assembly.
    auto oneByOne = [&](auto indexOf) {
      glClear(GL_COLOR_BUFFER_BIT);
      for (int t = 0; t + 3 <= count; t += 3) {
        glBegin(GL_TRIANGLES);
        for (int k = t; k < t + 3; ++k) {
          const Vertex& x = v[indexOf(k)];
          glEdgeFlag(edgeFlags[indexOf(k)]);
          glColor4ub(x.color[0], x.color[1], x.color[2], x.color[3]);
          glVertex2s(x.position[0], x.position[1]);
        }
        glEnd();
      }
      glEdgeFlag(GL_TRUE);
      return readFramebuffer(kSize, kSize);
    };
    const std::vector<uint8_t> expected = oneByOne([](int k) { return k; });
    const std::vector<uint8_t> expectedIndexed = oneByOne([&](int k) { return static_cast<int>(indices[k]); });

    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, count);
    CHECK(readFramebuffer(kSize, kSize) == expected);

    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < count; ++i) glArrayElement(i);
    glEnd();
    CHECK(readFramebuffer(kSize, kSize) == expected);

    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, indices.data());
    CHECK(readFramebuffer(kSize, kSize) == expectedIndexed);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  CHECK(glGetError() == GL_NO_ERROR);
}
