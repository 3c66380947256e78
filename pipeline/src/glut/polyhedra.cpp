// GLUT's Platonic solids, with freeglut 3's vertices, face order, vertex order within each face
// and normals, so a lit solid looks the same drawn by glass or by freeglut.
//
// Every solid is a list of corner points and a list of faces (counter-clockwise seen from
// outside); each face gets its own copy of its corners so that they carry the face normal.
#include <cmath>
#include <initializer_list>

#include "glut/shape_mesh.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::glut {
namespace {

struct Point {
  double x, y, z;
};

// Builds the mesh of a solid with `corners` points and faces of `edges` corners each.
//   normals: one per face (given as doubles, rounded to float once)
//   triangles: how a face of `edges` corners is split into triangles (indices within the face)
ShapeMesh polyhedron(const Point* corners, const int* faces, const Point* normals, int faceCount,
                     int edges, float scale, bool wire, std::initializer_list<int> triangles) {
  ShapeMesh mesh;
  for (int f = 0; f < faceCount; ++f) {
    const Point& n = normals[f];
    for (int k = 0; k < edges; ++k) {
      const Point& p = corners[faces[f * edges + k]];
      mesh.addVertex(scale * static_cast<float>(p.x), scale * static_cast<float>(p.y),
                     scale * static_cast<float>(p.z), static_cast<float>(n.x),
                     static_cast<float>(n.y), static_cast<float>(n.z));
    }
  }
  if (wire) {
    for (int f = 0; f < faceCount; ++f) {
      ShapeMesh::Draw loop{GL_LINE_LOOP, {}};
      for (int k = 0; k < edges; ++k) loop.indices.push_back(f * edges + k);
      mesh.draws.push_back(loop);
    }
  } else {
    ShapeMesh::Draw all{GL_TRIANGLES, {}};
    for (int f = 0; f < faceCount; ++f) {
      for (int k : triangles) all.indices.push_back(f * edges + k);
    }
    mesh.draws.push_back(all);
  }
  return mesh;
}

// The outward normal of triangle (a, b, c) as the plain cross product (b - a) x (c - a), not
// normalized: freeglut's icosahedron uses these (length about 0.958).
Point crossNormal(const Point& a, const Point& b, const Point& c) {
  const Point u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

// Corners of the solids as float values (freeglut stores them in float).
Point floatPoint(double x, double y, double z) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

}  // namespace

ShapeMesh cubeMesh(float size, bool wire) {
  const double h = 0.5;
  const Point corners[8] = {{h, h, h},  {-h, h, h},  {-h, -h, h}, {h, -h, h},
                            {h, -h, -h}, {h, h, -h}, {-h, h, -h}, {-h, -h, -h}};
  const int faces[6 * 4] = {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1,
                            1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5};
  const Point normals[6] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  return polyhedron(corners, faces, normals, 6, 4, size, wire, {0, 1, 2, 0, 2, 3});
}

ShapeMesh tetrahedronMesh(bool wire) {
  // Unit circumradius: one corner on +x, the other three below it at x = -1/3.
  const double s2 = std::sqrt(2.0), s6 = std::sqrt(6.0);
  Point corners[4] = {floatPoint(1, 0, 0), floatPoint(-1.0 / 3, 2 * s2 / 3, 0),
                      floatPoint(-1.0 / 3, -s2 / 3, s6 / 3),
                      floatPoint(-1.0 / 3, -s2 / 3, -s6 / 3)};
  const int faces[4 * 3] = {1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2};
  // The unit normal of a face points away from the corner it leaves out.
  Point normals[4];
  for (int f = 0; f < 4; ++f) normals[f] = {-corners[f].x, -corners[f].y, -corners[f].z};
  return polyhedron(corners, faces, normals, 4, 3, 1.0f, wire, {0, 1, 2});
}

ShapeMesh octahedronMesh(bool wire) {
  const Point corners[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const int faces[8 * 3] = {0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5,
                            3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4};
  // One face per octant, in the order (+,+,+), (+,+,-), (+,-,+), ..., (-,-,-).
  const double s = 1.0 / std::sqrt(3.0);
  Point normals[8];
  for (int f = 0; f < 8; ++f) {
    normals[f] = {(f & 4) ? -s : s, (f & 2) ? -s : s, (f & 1) ? -s : s};
  }
  return polyhedron(corners, faces, normals, 8, 3, 1.0f, wire, {0, 1, 2});
}

ShapeMesh dodecahedronMesh(bool wire) {
  // A cube's corners (+-1, +-1, +-1) plus twelve on the coordinate planes, built from the golden
  // ratio phi: (0, +-phi, +-1/phi), (+-1/phi, 0, +-phi), (+-phi, +-1/phi, 0).
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0, iphi = phi - 1.0;
  const Point corners[20] = {
      floatPoint(0, phi, iphi),   floatPoint(-1, 1, 1),       floatPoint(-iphi, 0, phi),
      floatPoint(iphi, 0, phi),   floatPoint(1, 1, 1),        floatPoint(0, phi, -iphi),
      floatPoint(1, 1, -1),       floatPoint(iphi, 0, -phi),  floatPoint(-iphi, 0, -phi),
      floatPoint(-1, 1, -1),      floatPoint(0, -phi, iphi),  floatPoint(1, -1, 1),
      floatPoint(-1, -1, 1),      floatPoint(0, -phi, -iphi), floatPoint(-1, -1, -1),
      floatPoint(1, -1, -1),      floatPoint(phi, -iphi, 0),  floatPoint(phi, iphi, 0),
      floatPoint(-phi, iphi, 0),  floatPoint(-phi, -iphi, 0)};
  const int faces[12 * 5] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 3,  2,  12,
                             13, 14, 8,  7,  15, 3,  11, 16, 17, 4,  2,  1,  18, 19, 12,
                             7,  6,  17, 16, 15, 8,  14, 19, 18, 9,  17, 6,  5,  0,  4,
                             16, 11, 10, 13, 15, 18, 1,  0,  5,  9,  19, 14, 13, 10, 12};
  // Face normals are the directions (0, +-1, +-phi) and their cyclic shifts, normalized.
  const double a = 1.0 / std::sqrt(1.0 + phi * phi), b = phi * a;
  const Point normals[12] = {{0, a, b},  {0, a, -b},  {0, -a, b},  {0, -a, -b},
                             {b, 0, a},  {-b, 0, a},  {b, 0, -a},  {-b, 0, -a},
                             {a, b, 0},  {a, -b, 0},  {-a, b, 0},  {-a, -b, 0}};
  // A pentagon splits into the fan (0, 1, 2), (0, 2, 4) and the triangle (4, 2, 3).
  return polyhedron(corners, faces, normals, 12, 5, 1.0f, wire, {0, 1, 2, 0, 2, 4, 4, 2, 3});
}

ShapeMesh icosahedronMesh(bool wire) {
  // Two poles on the x axis and two rings of five corners at x = +-1/sqrt(5), radius 2/sqrt(5);
  // the upper ring starts at angle 0 and turns by +72 degrees, the lower one starts at 180 and
  // turns by -72 degrees (angles in the y-z plane, from +y towards +z).
  const double x = 1.0 / std::sqrt(5.0), r = 2.0 / std::sqrt(5.0);
  const double degree = portable::acos(-1.0) / 180.0;
  Point corners[12];
  corners[0] = floatPoint(1, 0, 0);
  corners[11] = floatPoint(-1, 0, 0);
  for (int k = 0; k < 5; ++k) {
    const double up = 72.0 * k * degree, down = (180.0 - 72.0 * k) * degree;
    corners[1 + k] = floatPoint(x, r * portable::cos(up), r * portable::sin(up));
    corners[6 + k] = floatPoint(-x, r * portable::cos(down), r * portable::sin(down));
  }
  // The exact zeros of the axis corners' rings.
  corners[1].z = 0.0;
  corners[6].z = 0.0;
  const int faces[20 * 3] = {0, 1, 2,  0, 2, 3,  0, 3, 4,  0, 4,  5,  0,  5, 1,
                             1, 8, 2,  2, 7, 3,  3, 6, 4,  4, 10, 5,  5,  9, 1,
                             1, 9, 8,  2, 8, 7,  3, 7, 6,  4, 6,  10, 5,  10, 9,
                             11, 9, 10, 11, 8, 9, 11, 7, 8, 11, 6, 7, 11, 10, 6};
  Point normals[20];
  for (int f = 0; f < 20; ++f) {
    normals[f] = crossNormal(corners[faces[3 * f]], corners[faces[3 * f + 1]],
                             corners[faces[3 * f + 2]]);
  }
  return polyhedron(corners, faces, normals, 20, 3, 1.0f, wire, {0, 1, 2});
}

// freeglut's rhombic dodecahedron: the twelve rhombi around the corners (0, 0, +-1),
// (+-s, 0, +-1/2), (0, +-s, +-1/2) and (+-s, +-s, 0) with s = sqrt(2) / 2. The eight slanted faces
// carry freeglut's normals (+-sqrt(2)/4, +-sqrt(2)/4, +-1/2), which are not unit length.
ShapeMesh rhombicDodecahedronMesh(bool wire) {
  const double s = std::sqrt(2.0) / 2.0, a = std::sqrt(2.0) / 4.0;
  const Point corners[14] = {
      floatPoint(0, 0, 1),    floatPoint(s, 0, 0.5),   floatPoint(0, s, 0.5),
      floatPoint(-s, 0, 0.5), floatPoint(0, -s, 0.5),  floatPoint(s, s, 0),
      floatPoint(-s, s, 0),   floatPoint(-s, -s, 0),   floatPoint(s, -s, 0),
      floatPoint(s, 0, -0.5), floatPoint(0, s, -0.5),  floatPoint(-s, 0, -0.5),
      floatPoint(0, -s, -0.5), floatPoint(0, 0, -1)};
  const int faces[12 * 4] = {0, 1, 5,  2,  0, 2,  6,  3,  0, 3,  7,  4,  0, 4,  8,  1,
                             5, 10, 6, 2,  6, 11, 7,  3,  7, 12, 8,  4,  8, 9,  5,  1,
                             5, 9, 13, 10, 6, 10, 13, 11, 7, 11, 13, 12, 8, 12, 13, 9};
  const Point normals[12] = {
      floatPoint(a, a, 0.5),  floatPoint(-a, a, 0.5),  floatPoint(-a, -a, 0.5),
      floatPoint(a, -a, 0.5), {0, 1, 0},               {-1, 0, 0},
      {0, -1, 0},             {1, 0, 0},               floatPoint(a, a, -0.5),
      floatPoint(-a, a, -0.5), floatPoint(-a, -a, -0.5), floatPoint(a, -a, -0.5)};
  return polyhedron(corners, faces, normals, 12, 4, 1.0f, wire, {0, 1, 2, 0, 2, 3});
}

// freeglut's Sierpinski sponge: at level 0 the tetrahedron of glutSolidTetrahedron scaled by
// `scale` and moved by `offset`; each further level replaces it by four tetrahedra of half the
// scale, one at each corner (offset + scale / 2 * corner), in the order of the corners. As in
// freeglut, offsets add up in double and each vertex is offset + scale * corner in float.
ShapeMesh sierpinskiSpongeMesh(int levels, const double offset[3], float scale, bool wire) {
  ShapeMesh mesh;
  if (levels < 0) return mesh;
  const ShapeMesh unit = tetrahedronMesh(false);  // 4 faces x 3 corners, in face order
  const double s2 = std::sqrt(2.0), s6 = std::sqrt(6.0);
  const Point corners[4] = {floatPoint(1, 0, 0), floatPoint(-1.0 / 3, 2 * s2 / 3, 0),
                            floatPoint(-1.0 / 3, -s2 / 3, s6 / 3),
                            floatPoint(-1.0 / 3, -s2 / 3, -s6 / 3)};
  auto emit = [&](auto&& self, int level, const double at[3], float size) -> void {
    if (level == 0) {
      for (int k = 0; k < unit.vertexCount(); ++k) {
        const float* p = &unit.positions[3 * k];
        const float* n = &unit.normals[3 * k];
        mesh.addVertex(static_cast<float>(at[0]) + size * p[0],
                       static_cast<float>(at[1]) + size * p[1],
                       static_cast<float>(at[2]) + size * p[2], n[0], n[1], n[2]);
      }
      return;
    }
    const float half = size / 2.0f;
    for (const Point& c : corners) {
      const double next[3] = {at[0] + half * c.x, at[1] + half * c.y, at[2] + half * c.z};
      self(self, level - 1, next, half);
    }
  };
  emit(emit, levels, offset, scale);
  const int vertices = mesh.vertexCount();
  if (wire) {
    for (int first = 0; first < vertices; first += 3) {
      mesh.draws.push_back({GL_LINE_LOOP, {first, first + 1, first + 2}});
    }
  } else {
    ShapeMesh::Draw all{GL_TRIANGLES, {}};
    for (int k = 0; k < vertices; ++k) all.indices.push_back(k);
    mesh.draws.push_back(all);
  }
  return mesh;
}

}  // namespace glass::gl::glut
