// glass's GLUT shapes against freeglut 3, vertex by vertex.
//
// This program links freeglut but not libglass. freeglut draws its shapes through vertex arrays;
// the program defines the array entry points freeglut calls (glVertexPointer, glDrawElements,
// ...), so each draw call is recorded here as its primitive mode and the list of
// (position, normal) pairs it sends. glass's meshes (compiled straight into this program) are
// expanded the same way, and the two lists are compared.
//
// freeglut's shape functions need no window, only glutInit's "initialised" flag, which they
// check through its error handler: with glutInitErrorFunc installed they report and carry on.
#include <GL/freeglut.h>
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "glut/shape_mesh.h"

namespace {

struct Primitive {
  GLenum mode;
  std::vector<float> data;  // x, y, z, nx, ny, nz per vertex
};

std::vector<Primitive> g_recorded;
const GLfloat* g_positions = nullptr;
const GLfloat* g_normals = nullptr;

void recordVertex(Primitive& p, int k) {
  for (int c = 0; c < 3; ++c) p.data.push_back(g_positions[3 * k + c]);
  for (int c = 0; c < 3; ++c) p.data.push_back(g_normals[3 * k + c]);
}

std::vector<Primitive> expand(const glass::gl::glut::ShapeMesh& mesh) {
  std::vector<Primitive> out;
  for (const auto& d : mesh.draws) {
    Primitive p{d.mode, {}};
    for (int k : d.indices) {
      for (int c = 0; c < 3; ++c) p.data.push_back(mesh.positions[3 * k + c]);
      for (int c = 0; c < 3; ++c) p.data.push_back(mesh.normals[3 * k + c]);
    }
    out.push_back(p);
  }
  return out;
}

void ignoreMessage(const char*, va_list) {}

std::vector<Primitive> freeglut(const std::function<void()>& draw) {
  glutInitErrorFunc(ignoreMessage);
  glutInitWarningFunc(ignoreMessage);
  g_recorded.clear();
  draw();
  return g_recorded;
}

// Round shapes must agree bit for bit. The polyhedra's corners and normals are computed here
// from their definitions, where freeglut lists decimal constants: they may differ in the last
// bit of a float, so they are compared within 2e-7.
void checkSame(const std::vector<Primitive>& expected, const std::vector<Primitive>& actual,
               float tolerance, float normalTolerance = -1.0f) {
  if (normalTolerance < 0.0f) normalTolerance = tolerance;
  REQUIRE(expected.size() == actual.size());
  REQUIRE(!expected.empty());
  for (size_t p = 0; p < expected.size(); ++p) {
    INFO("primitive " << p);
    CHECK(expected[p].mode == actual[p].mode);
    REQUIRE(expected[p].data.size() == actual[p].data.size());
    for (size_t k = 0; k < expected[p].data.size(); ++k) {
      const float e = expected[p].data[k], a = actual[p].data[k];
      if (std::isnan(e) && std::isnan(a)) continue;  // a normal of a collapsed patch corner, 0/0 in both
      const float allowed = k % 6 < 3 ? tolerance : normalTolerance;
      if (allowed == 0.0f ? e != a : std::fabs(e - a) > allowed) {
        INFO("vertex " << k / 6 << " component " << k % 6 << ": freeglut " << e << ", glass " << a);
        CHECK(false);
        return;
      }
    }
  }
}

}  // namespace

extern "C" {
void glEnableClientState(GLenum) {}
void glDisableClientState(GLenum) {}
void glVertexPointer(GLint, GLenum, GLsizei, const GLvoid* p) {
  g_positions = static_cast<const GLfloat*>(p);
}
void glNormalPointer(GLenum, GLsizei, const GLvoid* p) {
  g_normals = static_cast<const GLfloat*>(p);
}
void glTexCoordPointer(GLint, GLenum, GLsizei, const GLvoid*) {}
void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  Primitive p{mode, {}};
  for (int k = first; k < first + count; ++k) recordVertex(p, k);
  g_recorded.push_back(p);
}
void glDrawElements(GLenum mode, GLsizei count, GLenum, const GLvoid* indices) {
  Primitive p{mode, {}};
  const GLushort* idx = static_cast<const GLushort*>(indices);
  for (int k = 0; k < count; ++k) recordVertex(p, idx[k]);
  g_recorded.push_back(p);
}
}

namespace shapes = glass::gl::glut;

TEST_CASE("GLUT round shapes match freeglut bit for bit") {
  for (bool wire : {false, true}) {
    INFO("wire " << wire);
    const struct {
      double r;
      int slices, stacks;
    } spheres[] = {{1.0, 16, 8}, {0.7, 5, 2}, {2.5, 31, 17}};
    for (const auto& s : spheres) {
      INFO("sphere " << s.r << " " << s.slices << " " << s.stacks);
      checkSame(freeglut([&] {
                  wire ? glutWireSphere(s.r, s.slices, s.stacks)
                       : glutSolidSphere(s.r, s.slices, s.stacks);
                }),
                expand(shapes::sphereMesh(static_cast<float>(s.r), s.slices, s.stacks, wire)),
                0.0f);
    }
    const struct {
      double b, h;
      int slices, stacks;
    } cones[] = {{1.0, 2.0, 16, 4}, {0.3, 0.7, 3, 1}, {1.7, 0.9, 20, 7}};
    for (const auto& c : cones) {
      INFO("cone/cylinder " << c.b << " " << c.h << " " << c.slices << " " << c.stacks);
      checkSame(freeglut([&] {
                  wire ? glutWireCone(c.b, c.h, c.slices, c.stacks)
                       : glutSolidCone(c.b, c.h, c.slices, c.stacks);
                }),
                expand(shapes::coneMesh(static_cast<float>(c.b), static_cast<float>(c.h), c.slices,
                                        c.stacks, wire)),
                0.0f);
      checkSame(freeglut([&] {
                  wire ? glutWireCylinder(c.b, c.h, c.slices, c.stacks)
                       : glutSolidCylinder(c.b, c.h, c.slices, c.stacks);
                }),
                expand(shapes::cylinderMesh(static_cast<float>(c.b), static_cast<float>(c.h),
                                            c.slices, c.stacks, wire)),
                0.0f);
    }
    const struct {
      double inner, outer;
      int sides, rings;
    } tori[] = {{0.3, 1.0, 8, 16}, {0.5, 0.9, 3, 2}, {0.25, 2.0, 13, 29}};
    for (const auto& t : tori) {
      INFO("torus " << t.inner << " " << t.outer << " " << t.sides << " " << t.rings);
      checkSame(freeglut([&] {
                  wire ? glutWireTorus(t.inner, t.outer, t.sides, t.rings)
                       : glutSolidTorus(t.inner, t.outer, t.sides, t.rings);
                }),
                expand(shapes::torusMesh(static_cast<float>(t.inner), static_cast<float>(t.outer),
                                         t.sides, t.rings, wire)),
                0.0f);
    }
  }
}

TEST_CASE("GLUT polyhedra match freeglut") {
  for (bool wire : {false, true}) {
    INFO("wire " << wire);
    for (double size : {1.0, 2.5}) {
      INFO("cube " << size);
      checkSame(freeglut([&] { wire ? glutWireCube(size) : glutSolidCube(size); }),
                expand(shapes::cubeMesh(static_cast<float>(size), wire)), 0.0f);
    }
    INFO("tetrahedron");
    checkSame(freeglut([&] { wire ? glutWireTetrahedron() : glutSolidTetrahedron(); }),
              expand(shapes::tetrahedronMesh(wire)), 2e-7f);
    INFO("octahedron");
    checkSame(freeglut([&] { wire ? glutWireOctahedron() : glutSolidOctahedron(); }),
              expand(shapes::octahedronMesh(wire)), 2e-7f);
    INFO("dodecahedron");
    checkSame(freeglut([&] { wire ? glutWireDodecahedron() : glutSolidDodecahedron(); }),
              expand(shapes::dodecahedronMesh(wire)), 2e-7f);
    INFO("icosahedron");
    checkSame(freeglut([&] { wire ? glutWireIcosahedron() : glutSolidIcosahedron(); }),
              expand(shapes::icosahedronMesh(wire)), 2e-7f);
  }
}

TEST_CASE("GLUT shapes: counts freeglut cannot build give nothing") {
  CHECK(shapes::sphereMesh(1.0f, 8, 1, false).draws.empty());
  CHECK(shapes::sphereMesh(1.0f, 0, 8, true).draws.empty());
  CHECK(shapes::coneMesh(1.0f, 1.0f, 8, 0, false).draws.empty());
  CHECK(shapes::torusMesh(0.2f, 1.0f, 1, 8, false).draws.empty());
}

TEST_CASE("freeglut's rhombic dodecahedron and Sierpinski sponge match freeglut") {
  for (bool wire : {false, true}) {
    INFO("wire " << wire);
    checkSame(freeglut([&] {
                wire ? glutWireRhombicDodecahedron() : glutSolidRhombicDodecahedron();
              }),
              expand(shapes::rhombicDodecahedronMesh(wire)), 2e-7f);
    for (int levels : {0, 1, 3}) {
      double offset[3] = {0.25, -0.5, 1.0};
      const double scale = 1.5;
      INFO("sponge " << levels);
      checkSame(freeglut([&] {
                  wire ? glutWireSierpinskiSponge(levels, offset, scale)
                       : glutSolidSierpinskiSponge(levels, offset, scale);
                }),
                expand(shapes::sierpinskiSpongeMesh(levels, offset, static_cast<float>(scale),
                                                    wire)),
                4e-7f);
    }
  }
  CHECK(shapes::sierpinskiSpongeMesh(-1, std::array<double, 3>{}.data(), 1.0f, false)
            .draws.empty());
}

// freeglut computes a piece's normals on its first call only and keeps them for later sizes
// (its cache), where glass computes them for each size: the first size agrees bit for bit, later
// ones in their points, and their normals differ by the rounding of the points they were made
// from: up to 1e-3 next to nearly collapsed patch corners, where the cross product
// of two short tangents cancels, below 2e-6 elsewhere.
TEST_CASE("the teapot, teacup and teaspoon match freeglut") {
  for (bool wire : {false, true}) {
    INFO("wire " << wire);
    for (double size : {1.0, 0.35, 2.5}) {
      INFO("size " << size);
      const float normals = size == 1.0 ? 0.0f : 1e-3f;
      checkSame(freeglut([&] { wire ? glutWireTeapot(size) : glutSolidTeapot(size); }),
                expand(shapes::teapotMesh(static_cast<float>(size), wire)), 0.0f, normals);
      checkSame(freeglut([&] { wire ? glutWireTeacup(size) : glutSolidTeacup(size); }),
                expand(shapes::teacupMesh(static_cast<float>(size), wire)), 0.0f, normals);
      checkSame(freeglut([&] { wire ? glutWireTeaspoon(size) : glutSolidTeaspoon(size); }),
                expand(shapes::teaspoonMesh(static_cast<float>(size), wire)), 0.0f, normals);
    }
  }
}
