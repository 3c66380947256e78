// GLUT's round shapes (sphere, cone, cylinder, torus) with freeglut 3's vertices, normals and
// draw calls. All four are grids of vertices on circles; the circles come from one table of
// float sines and cosines per direction of travel, computed as freeglut computes it.
#include <cmath>
#include <numbers>
#include <vector>

#include "glut/shape_mesh.h"
#include "glass/geometry/portable_math.h"

namespace glass::gl::glut {
namespace {

// sin and cos of the angles k * step, k = 0 .. |n|, with step = 2 pi / n (pi / n for a half
// circle) in float. A negative n runs the circle the other way. The last entry closes the
// circle exactly (or is exactly (0, -1) for a half circle).
struct CircleTable {
  std::vector<float> sine, cosine;
  CircleTable(int n, bool halfCircle) {
    const int size = n < 0 ? -n : n;
    const float step = static_cast<float>(halfCircle ? 1 : 2) *
                       static_cast<float>(std::numbers::pi) / static_cast<float>(n == 0 ? 1 : n);
    sine.resize(size + 1);
    cosine.resize(size + 1);
    sine[0] = 0.0f;
    cosine[0] = 1.0f;
    for (int k = 1; k < size; ++k) {
      const double angle = step * static_cast<float>(k);
      sine[k] = static_cast<float>(portable::sin(angle));
      cosine[k] = static_cast<float>(portable::cos(angle));
    }
    sine[size] = halfCircle ? 0.0f : sine[0];
    cosine[size] = halfCircle ? -1.0f : cosine[0];
  }
};

// A triangle strip or line primitive over consecutive index pairs.
ShapeMesh::Draw draw(GLenum mode) { return {mode, {}}; }

}  // namespace

// Sphere: the north pole, then stacks - 1 rings of `slices` vertices from north to south (each
// ring runs clockwise seen from +z), then the south pole. A vertex's normal is its direction.
ShapeMesh sphereMesh(float radius, int slices, int stacks, bool wire) {
  ShapeMesh mesh;
  if (slices <= 0 || stacks < 2) return mesh;
  const CircleTable around(-slices, false), down(stacks, true);
  mesh.addVertex(0.0f, 0.0f, radius, 0.0f, 0.0f, 1.0f);
  for (int i = 1; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const float x = around.cosine[j] * down.sine[i];
      const float y = around.sine[j] * down.sine[i];
      const float z = down.cosine[i];
      mesh.addVertex(x * radius, y * radius, z * radius, x, y, z);
    }
  }
  mesh.addVertex(0.0f, 0.0f, -radius, 0.0f, 0.0f, -1.0f);
  const int south = mesh.vertexCount() - 1;
  auto ring = [slices](int i) { return 1 + i * slices; };  // first vertex of ring i (0-based)

  if (wire) {
    // Meridians (pole to pole), then the rings as loops.
    for (int j = 0; j < slices; ++j) {
      ShapeMesh::Draw line = draw(GL_LINE_STRIP);
      line.indices.push_back(0);
      for (int i = 0; i < stacks - 1; ++i) line.indices.push_back(ring(i) + j);
      line.indices.push_back(south);
      mesh.draws.push_back(line);
    }
    for (int i = 0; i < stacks - 1; ++i) {
      ShapeMesh::Draw loop = draw(GL_LINE_LOOP);
      for (int j = 0; j < slices; ++j) loop.indices.push_back(ring(i) + j);
      mesh.draws.push_back(loop);
    }
    return mesh;
  }
  // One strip per stack: the north cap, the bands, the south cap; each closes on its first pair.
  ShapeMesh::Draw cap = draw(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; ++j) cap.indices.insert(cap.indices.end(), {1 + j % slices, 0});
  mesh.draws.push_back(cap);
  for (int i = 0; i < stacks - 2; ++i) {
    ShapeMesh::Draw band = draw(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      band.indices.insert(band.indices.end(), {ring(i + 1) + j % slices, ring(i) + j % slices});
    }
    mesh.draws.push_back(band);
  }
  ShapeMesh::Draw southCap = draw(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; ++j) {
    southCap.indices.insert(southCap.indices.end(), {south, ring(stacks - 2) + j % slices});
  }
  mesh.draws.push_back(southCap);
  return mesh;
}

// Cone: the centre of the base, a ring on the base facing down (-z), then stacks + 1 rings up
// the side with the side's normal, the last one of radius ~0 at the apex.
ShapeMesh coneMesh(float base, float height, int slices, int stacks, bool wire) {
  ShapeMesh mesh;
  if (slices <= 0 || stacks < 1) return mesh;
  const CircleTable around(-slices, false);
  const float zStep = height / static_cast<float>(stacks);
  const float rStep = base / static_cast<float>(stacks);
  // The side normal leans up by the cone's half-angle: (cos * h/L, sin * h/L, base/L).
  const float slantSquared = height * height + base * base;
  const float cosn = static_cast<float>(height / std::sqrt(static_cast<double>(slantSquared)));
  const float sinn = static_cast<float>(base / std::sqrt(static_cast<double>(slantSquared)));

  float z = 0.0f, r = base;
  mesh.addVertex(0.0f, 0.0f, z, 0.0f, 0.0f, -1.0f);
  for (int j = 0; j < slices; ++j) {
    mesh.addVertex(around.cosine[j] * r, around.sine[j] * r, z, 0.0f, 0.0f, -1.0f);
  }
  for (int i = 0; i <= stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      mesh.addVertex(around.cosine[j] * r, around.sine[j] * r, z, around.cosine[j] * cosn,
                     around.sine[j] * cosn, sinn);
    }
    z += zStep;  // freeglut steps in float, so the rings carry its rounding
    r -= rStep;
  }
  auto ring = [slices](int i) { return 1 + (i + 1) * slices; };  // side ring i

  if (wire) {
    // Side lines from the base to the apex ring as GL_LINES, then the rings below the apex.
    ShapeMesh::Draw lines = draw(GL_LINES);
    for (int j = 0; j < slices; ++j) {
      lines.indices.insert(lines.indices.end(), {ring(0) + j, ring(stacks) + j});
    }
    mesh.draws.push_back(lines);
    for (int i = 0; i < stacks; ++i) {
      ShapeMesh::Draw loop = draw(GL_LINE_LOOP);
      for (int j = 0; j < slices; ++j) loop.indices.push_back(ring(i) + j);
      mesh.draws.push_back(loop);
    }
    return mesh;
  }
  ShapeMesh::Draw bottom = draw(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; ++j) {
    bottom.indices.insert(bottom.indices.end(), {0, 1 + j % slices});
  }
  mesh.draws.push_back(bottom);
  for (int i = 0; i < stacks; ++i) {
    ShapeMesh::Draw band = draw(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      band.indices.insert(band.indices.end(), {ring(i) + j % slices, ring(i + 1) + j % slices});
    }
    mesh.draws.push_back(band);
  }
  return mesh;
}

// Cylinder (a freeglut addition to GLUT): the bottom centre and a bottom ring facing -z,
// stacks + 1 side rings facing outwards, a top ring and the top centre facing +z.
ShapeMesh cylinderMesh(float radius, float height, int slices, int stacks, bool wire) {
  ShapeMesh mesh;
  if (slices <= 0 || stacks < 1) return mesh;
  const CircleTable around(-slices, false);
  const float zStep = height / static_cast<float>(stacks);
  float z = 0.0f;
  mesh.addVertex(0.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f);
  for (int j = 0; j < slices; ++j) {
    mesh.addVertex(around.cosine[j] * radius, around.sine[j] * radius, z, 0.0f, 0.0f, -1.0f);
  }
  for (int i = 0; i <= stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      mesh.addVertex(around.cosine[j] * radius, around.sine[j] * radius, z, around.cosine[j],
                     around.sine[j], 0.0f);
    }
    z += zStep;
  }
  z -= zStep;
  for (int j = 0; j < slices; ++j) {
    mesh.addVertex(around.cosine[j] * radius, around.sine[j] * radius, z, 0.0f, 0.0f, 1.0f);
  }
  mesh.addVertex(0.0f, 0.0f, height, 0.0f, 0.0f, 1.0f);
  const int top = mesh.vertexCount() - 1;
  // Side ring i; ring(stacks + 1) is the ring of the top cap.
  auto ring = [slices](int i) { return 1 + (i + 1) * slices; };

  if (wire) {
    ShapeMesh::Draw lines = draw(GL_LINES);
    for (int j = 0; j < slices; ++j) {
      lines.indices.insert(lines.indices.end(), {ring(0) + j, ring(stacks) + j});
    }
    mesh.draws.push_back(lines);
    for (int i = 0; i <= stacks; ++i) {
      ShapeMesh::Draw loop = draw(GL_LINE_LOOP);
      for (int j = 0; j < slices; ++j) loop.indices.push_back(ring(i) + j);
      mesh.draws.push_back(loop);
    }
    return mesh;
  }
  ShapeMesh::Draw bottom = draw(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; ++j) {
    bottom.indices.insert(bottom.indices.end(), {0, 1 + j % slices});
  }
  mesh.draws.push_back(bottom);
  for (int i = 0; i < stacks; ++i) {
    ShapeMesh::Draw band = draw(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; ++j) {
      band.indices.insert(band.indices.end(), {ring(i) + j % slices, ring(i + 1) + j % slices});
    }
    mesh.draws.push_back(band);
  }
  ShapeMesh::Draw cap = draw(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; ++j) {
    cap.indices.insert(cap.indices.end(), {ring(stacks + 1) + j % slices, top});
  }
  mesh.draws.push_back(cap);
  return mesh;
}

// Torus around the z axis: ring j at angle psi_j around z (counter-clockwise), side i at angle
// phi_i around the tube (clockwise), vertex (j, i) at index j * sides + i.
ShapeMesh torusMesh(float innerRadius, float outerRadius, int sides, int rings, bool wire) {
  ShapeMesh mesh;
  if (sides < 2 || rings < 2) return mesh;
  const CircleTable psi(rings, false), phi(-sides, false);
  for (int j = 0; j < rings; ++j) {
    for (int i = 0; i < sides; ++i) {
      const float distance = outerRadius + phi.cosine[i] * innerRadius;
      mesh.addVertex(psi.cosine[j] * distance, psi.sine[j] * distance, phi.sine[i] * innerRadius,
                     psi.cosine[j] * phi.cosine[i], psi.sine[j] * phi.cosine[i], phi.sine[i]);
    }
  }
  auto at = [sides](int j, int i) { return j * sides + i; };

  if (wire) {
    for (int j = 0; j < rings; ++j) {
      ShapeMesh::Draw loop = draw(GL_LINE_LOOP);
      for (int i = 0; i < sides; ++i) loop.indices.push_back(at(j, i));
      mesh.draws.push_back(loop);
    }
    for (int i = 0; i < sides; ++i) {
      ShapeMesh::Draw loop = draw(GL_LINE_LOOP);
      for (int j = 0; j < rings; ++j) loop.indices.push_back(at(j, i));
      mesh.draws.push_back(loop);
    }
    return mesh;
  }
  // One strip per side: around the whole ring between side i and side i + 1 (the last side
  // pairs with side 0).
  for (int i = 0; i < sides; ++i) {
    const int next = i == sides - 1 ? 0 : i + 1;
    ShapeMesh::Draw strip = draw(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= rings; ++j) {
      strip.indices.insert(strip.indices.end(), {at(j % rings, i), at(j % rings, next)});
    }
    mesh.draws.push_back(strip);
  }
  return mesh;
}

}  // namespace glass::gl::glut
