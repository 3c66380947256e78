// Immediate mode with colour material, across the vertex stage's batches. Inside glBegin/glEnd
// the vertices are gathered and lit with their own colours, and colour material's tracked
// parameters are brought up to date once, at glEnd (vertex/gathered_vertices.h). These tests pin
// down what must not change because of that: the picture (against the same triangles drawn from
// arrays), the material and current colour glGet reads after glEnd and after a glColor outside
// glBegin/glEnd, glMaterial between vertices, the errors of glGet between vertices, and the
// material the next lit raster position is lit with.
#include <doctest/doctest.h>

#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "pipeline_test_support.h"

namespace {

using glass::test::readFramebuffer;
using glass::test::ScopedContext;

constexpr int kSize = 64;
// More vertices than a batch holds (64), so that the primitive runs through several batches.
constexpr int kVertexCount = 3 * 47;
// A glMaterial comes before this vertex (the start of a triangle, so that arrays can split there).
constexpr int kMaterialChangeAt = 3 * 23;

struct Vertices {
  std::vector<GLfloat> positions, normals;
  std::vector<GLubyte> colors;
};

Vertices makeVertices() {
  Vertices v;
  for (int i = 0; i < kVertexCount; ++i) {
    const double a = i * 2.39996;  // the golden angle: vertices spread over the disc
    const double r = 0.2 + 0.05 * (i * 37 % 16);
    v.positions.push_back(static_cast<GLfloat>(r * std::cos(a)));
    v.positions.push_back(static_cast<GLfloat>(r * std::sin(a)));
    v.positions.push_back(static_cast<GLfloat>(-0.1 * (i % 5)));
    const double n[3] = {std::cos(a) * 0.6, std::sin(a) * 0.6, 0.8};
    for (double c : n) v.normals.push_back(static_cast<GLfloat>(c));
    v.colors.push_back(static_cast<GLubyte>(i * 53 % 256));
    v.colors.push_back(static_cast<GLubyte>(i * 101 % 256));
    v.colors.push_back(static_cast<GLubyte>(i * 29 % 256));
    v.colors.push_back(static_cast<GLubyte>(128 + i % 128));
  }
  return v;
}

const GLfloat kFirstSpecular[4] = {0.3f, 0.3f, 0.3f, 1.0f};
const GLfloat kSecondSpecular[4] = {0.9f, 0.5f, 0.1f, 1.0f};
const GLfloat kIgnoredDiffuse[4] = {0.1f, 0.9f, 0.4f, 1.0f};  // tracked: glMaterial must not set it

void setUpLighting() {
  static const GLfloat light0[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  static const GLfloat light1[4] = {-1.0f, 0.5f, 2.0f, 1.0f};
  static const GLfloat diffuse1[4] = {0.4f, 0.6f, 0.9f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light0);
  glLightfv(GL_LIGHT1, GL_POSITION, light1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse1);
  glLightfv(GL_LIGHT1, GL_SPECULAR, diffuse1);
  glMaterialfv(GL_FRONT, GL_SPECULAR, kFirstSpecular);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHTING);
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);  // the colour before glBegin, different from every vertex's
  glClear(GL_COLOR_BUFFER_BIT);
}

std::vector<GLfloat> materialOf(GLenum pname) {
  std::vector<GLfloat> m(4, -1.0f);
  glGetMaterialfv(GL_FRONT, pname, m.data());
  return m;
}

std::vector<GLfloat> currentColor() {
  std::vector<GLfloat> c(4, -1.0f);
  glGetFloatv(GL_CURRENT_COLOR, c.data());
  return c;
}

std::vector<GLfloat> rasterColor() {
  std::vector<GLfloat> c(4, -1.0f);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c.data());
  return c;
}

std::vector<GLfloat> ubyteColor(const GLubyte* c) {
  return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f};
}

}  // namespace

TEST_CASE("immediate mode with colour material: glMaterial and glGet between vertices, state after glEnd") {
  const Vertices v = makeVertices();
  const GLubyte* lastColor = &v.colors[4 * (kVertexCount - 1)];

  // The triangles from arrays, the glMaterial between two draws.
  std::vector<uint8_t> expected;
  {
    ScopedContext context(kSize, kSize);
    setUpLighting();
    glVertexPointer(3, GL_FLOAT, 0, v.positions.data());
    glNormalPointer(GL_FLOAT, 0, v.normals.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, v.colors.data());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, kMaterialChangeAt);
    glMaterialfv(GL_FRONT, GL_SPECULAR, kSecondSpecular);
    glDrawArrays(GL_TRIANGLES, kMaterialChangeAt, kVertexCount - kMaterialChangeAt);
    CHECK(glGetError() == GL_NO_ERROR);
    expected = readFramebuffer(kSize, kSize);
  }
  // The raster colour of a lit glRasterPos whose tracked material took the last colour outside
  // glBegin/glEnd (with the last normal, which is current after glEnd too).
  std::vector<GLfloat> expectedRasterColor;
  {
    ScopedContext context(kSize, kSize);
    setUpLighting();
    glMaterialfv(GL_FRONT, GL_SPECULAR, kSecondSpecular);
    glColor4ubv(lastColor);
    glNormal3fv(&v.normals[3 * (kVertexCount - 1)]);
    glRasterPos3f(0.1f, 0.2f, 0.0f);
    expectedRasterColor = rasterColor();
    CHECK(glGetError() == GL_NO_ERROR);
  }

  ScopedContext context(kSize, kSize);
  setUpLighting();
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < kVertexCount; ++i) {
    if (i == kMaterialChangeAt) {
      glMaterialfv(GL_FRONT, GL_DIFFUSE, kIgnoredDiffuse);
      glMaterialfv(GL_FRONT, GL_SPECULAR, kSecondSpecular);
    }
    if (i == kMaterialChangeAt + 1) {
      // glGet is an error between glBegin and glEnd and leaves its results alone.
      GLfloat untouched[4] = {-2.0f, -2.0f, -2.0f, -2.0f};
      glGetMaterialfv(GL_FRONT, GL_DIFFUSE, untouched);
      CHECK(untouched[0] == -2.0f);
      glGetFloatv(GL_CURRENT_COLOR, untouched);
      CHECK(untouched[0] == -2.0f);
      // A colour no vertex takes: the next glColor replaces it.
      glColor4f(1.0f, 0.0f, 1.0f, 1.0f);
    }
    glColor4ubv(&v.colors[4 * i]);
    glNormal3fv(&v.normals[3 * i]);
    glVertex3fv(&v.positions[3 * i]);
  }
  glEnd();
  CHECK(glGetError() == GL_INVALID_OPERATION);  // the two glGet calls
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(readFramebuffer(kSize, kSize) == expected);

  // After glEnd the tracked parameters hold the last colour; the others what glMaterial set.
  CHECK(currentColor() == ubyteColor(lastColor));
  CHECK(materialOf(GL_AMBIENT) == ubyteColor(lastColor));
  CHECK(materialOf(GL_DIFFUSE) == ubyteColor(lastColor));
  CHECK(materialOf(GL_SPECULAR) == std::vector<GLfloat>(kSecondSpecular, kSecondSpecular + 4));

  // A lit raster position reads the stored material.
  glRasterPos3f(0.1f, 0.2f, 0.0f);
  CHECK(rasterColor() == expectedRasterColor);

  // A glColor after glEnd is tracked at once again.
  glColor4f(0.5f, 0.25f, 1.0f, 0.5f);
  const std::vector<GLfloat> after = {0.5f, 0.25f, 1.0f, 0.5f};
  CHECK(materialOf(GL_DIFFUSE) == after);
  CHECK(materialOf(GL_AMBIENT) == after);
  CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("immediate mode with colour material: a display list's glBegin/glEnd leaves the material tracking its last colour") {
  const Vertices v = makeVertices();
  ScopedContext context(kSize, kSize);
  setUpLighting();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 6; ++i) {
    glColor4ubv(&v.colors[4 * i]);
    glNormal3fv(&v.normals[3 * i]);
    glVertex3fv(&v.positions[3 * i]);
  }
  glEnd();
  glEndList();
  // Compiling neither drew nor changed the material.
  CHECK(materialOf(GL_DIFFUSE) == std::vector<GLfloat>{0.25f, 0.5f, 0.75f, 1.0f});
  glCallList(list);
  CHECK(materialOf(GL_DIFFUSE) == ubyteColor(&v.colors[4 * 5]));
  CHECK(currentColor() == ubyteColor(&v.colors[4 * 5]));
  glDeleteLists(list, 1);
  CHECK(glGetError() == GL_NO_ERROR);
}
