// The Utah teaset as freeglut 3 builds it, so that glutSolidTeapot, glutSolidTeacup,
// glutSolidTeaspoon and their wire forms draw the same triangles and lines with glass as with
// freeglut (Mesa's reference images use freeglut). The patches are glut/teaset_data.h's.
//
// The arithmetic follows freeglut's, in float and in the same order, because the pictures are
// compared pixel by pixel: control points are turned to y up and scaled first,
//   (x, y, z) -> (x * scale / 2, (z - centre height) * scale / 2, -y * scale / 2),
// (scale = size for the teapot, size / 2.5 for the teacup and the teaspoon) then each patch is
// evaluated on an n x n grid (n = 8 solid, 10 wire) from tabulated Bernstein polynomials and
// their derivatives; the normal is the normalized cross product of the two partial derivatives
// (along the patch's second index, then its first); the copies turn or mirror the evaluated
// points and normals. Solid grid quads become triangles (a, b, c), (a, c, d) with a = (r, c),
// b = (r + 1, c), c = (r + 1, c + 1), d = (r, c + 1); the wire forms are line strips along each
// grid direction, all patches' first direction first.
#include <cmath>
#include <cstddef>

#include "glut/shape_mesh.h"
#include "glut/teaset_data.h"

namespace glass::gl::glut {

namespace {

// The cubic Bernstein polynomials B_i(x) and their derivatives at the n grid values x = s/(n-1).
struct BernsteinTable {
  float value[10][4];
  float derivative[10][4];
};

BernsteinTable bernsteinTable(int n) {
  BernsteinTable table{};
  for (int s = 0; s < n; ++s) {
    const float x = static_cast<float>(s) / (static_cast<float>(n) - 1.0f);
    const float inv = 1.0f - x;
    const float inv2 = inv * inv;
    const float x2 = x * x;
    table.value[s][0] = inv * inv2;
    table.derivative[s][0] = -3 * inv2;
    table.value[s][1] = 3 * x * inv2;
    table.derivative[s][1] = 3 * inv2 - 6 * x * inv;
    table.value[s][2] = 3 * x2 * inv;
    table.derivative[s][2] = 6 * x * inv - 3 * x2;
    table.value[s][3] = x * x2;
    table.derivative[s][3] = 3 * x2;
  }
  return table;
}

using Grid = std::vector<float>;  // n * n points, x y z each, row-major (row = first index)

// Evaluates one patch on the grid: points and unit normals.
void evaluatePatch(const float cp[4][4][3], int n, const BernsteinTable& b, Grid& points, Grid& normals) {
  points.assign(static_cast<std::size_t>(n * n * 3), 0.0f);
  normals.assign(static_cast<std::size_t>(n * n * 3), 0.0f);
  for (int u = 0, o = 0; u < n; ++u) {
    for (int v = 0; v < n; ++v, o += 3) {
      float tangentV[3] = {0, 0, 0}, tangentU[3] = {0, 0, 0};
      for (int i = 0; i < 4; ++i) {
        float row[3] = {0, 0, 0}, rowDerivative[3] = {0, 0, 0};
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 3; ++k) {
            row[k] += b.value[v][j] * cp[i][j][k];
            rowDerivative[k] += b.derivative[v][j] * cp[i][j][k];
          }
        for (int k = 0; k < 3; ++k) {
          points[static_cast<std::size_t>(o + k)] += b.value[u][i] * row[k];
          tangentV[k] += b.value[u][i] * rowDerivative[k];
          tangentU[k] += b.derivative[u][i] * row[k];
        }
      }
      float* normal = &normals[static_cast<std::size_t>(o)];
      normal[0] = tangentV[1] * tangentU[2] - tangentV[2] * tangentU[1];
      normal[1] = tangentV[2] * tangentU[0] - tangentV[0] * tangentU[2];
      normal[2] = tangentV[0] * tangentU[1] - tangentV[1] * tangentU[0];
      // The length in double, rounded to float, as C's sqrt of a float expression gives.
      const float length = static_cast<float>(
          std::sqrt(static_cast<double>(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2])));
      for (int k = 0; k < 3; ++k) normal[k] /= length;
    }
  }
}

// Where a patch's first row collapses to a point (the top of the lid, the middle of the bottom)
// the cross product vanishes; freeglut sets that row's normals straight up or down.
void fixCollapsedRow(Grid& normals, int n, float up) {
  for (int o = 0; o < n * 3; o += 3) {
    normals[static_cast<std::size_t>(o)] = 0.0f;
    normals[static_cast<std::size_t>(o + 1)] = up;
    normals[static_cast<std::size_t>(o + 2)] = 0.0f;
  }
}

// Appends a grid turned about the y axis by quarter turns (0 to 3).
void appendTurned(ShapeMesh& mesh, const Grid& points, const Grid& normals, int quarterTurns) {
  auto turn = [quarterTurns](const float* p, float out[3]) {
    switch (quarterTurns) {
      case 0: out[0] = p[0]; out[1] = p[1]; out[2] = p[2]; break;
      case 1: out[0] = p[2]; out[1] = p[1]; out[2] = -p[0]; break;
      case 2: out[0] = -p[0]; out[1] = p[1]; out[2] = -p[2]; break;
      default: out[0] = -p[2]; out[1] = p[1]; out[2] = p[0]; break;
    }
  };
  for (std::size_t o = 0; o < points.size(); o += 3) {
    float p[3], q[3];
    turn(&points[o], p);
    turn(&normals[o], q);
    mesh.addVertex(p[0], p[1], p[2], q[0], q[1], q[2]);
  }
}

// Appends a grid mirrored in the plane z = 0, its rows in reverse order to keep the winding.
void appendMirrored(ShapeMesh& mesh, const Grid& points, const Grid& normals, int n) {
  for (int u = 0; u < n; ++u)
    for (int v = 0; v < n; ++v) {
      const std::size_t o = static_cast<std::size_t>(((n - 1 - u) * n + v) * 3);
      mesh.addVertex(points[o], points[o + 1], -points[o + 2], normals[o], normals[o + 1], -normals[o + 2]);
    }
}

// The mesh of one piece at `scale`, as freeglut's fghTeaset makes it.
ShapeMesh teasetMesh(const TeasetPiece& piece, float scale, bool wire) {
  const int n = wire ? 10 : 8;
  const BernsteinTable bernstein = bernsteinTable(n);
  constexpr int kTurnedPatches = 6;  // with turnsAndMirrors, the first six go into all four quadrants
  ShapeMesh mesh;
  Grid points, normals;
  for (int p = 0; p < static_cast<int>(piece.patches.size()); ++p) {
    float cp[4][4][3];
    for (int i = 0; i < 16; ++i) {
      const float* source = piece.controlPoints[static_cast<std::size_t>(piece.patches[static_cast<std::size_t>(p)][i])];
      cp[i / 4][i % 4][0] = source[0] * scale / 2.0f;
      cp[i / 4][i % 4][1] = (source[2] - piece.centreHeight) * scale / 2.0f;
      cp[i / 4][i % 4][2] = -source[1] * scale / 2.0f;
    }
    evaluatePatch(cp, n, bernstein, points, normals);
    if (piece.fixesCollapsedRows && p == 3) fixCollapsedRow(normals, n, 1.0f);
    if (piece.fixesCollapsedRows && p == 5) fixCollapsedRow(normals, n, -1.0f);
    if (!piece.turnsAndMirrors) {
      appendTurned(mesh, points, normals, 0);
    } else if (p < kTurnedPatches) {
      for (int turn = 0; turn < 4; ++turn) appendTurned(mesh, points, normals, turn);
    } else {
      appendTurned(mesh, points, normals, 0);
      appendMirrored(mesh, points, normals, n);
    }
  }

  const int patches = mesh.vertexCount() / (n * n);
  if (wire) {
    // Strips along the first index at each second index, for every patch; then the other way.
    for (int patch = 0; patch < patches; ++patch)
      for (int c = 0; c < n; ++c) {
        ShapeMesh::Draw strip{GL_LINE_STRIP, {}};
        for (int r = 0; r < n; ++r) strip.indices.push_back(patch * n * n + r * n + c);
        mesh.draws.push_back(std::move(strip));
      }
    for (int patch = 0; patch < patches; ++patch)
      for (int r = 0; r < n; ++r) {
        ShapeMesh::Draw strip{GL_LINE_STRIP, {}};
        for (int c = 0; c < n; ++c) strip.indices.push_back(patch * n * n + r * n + c);
        mesh.draws.push_back(std::move(strip));
      }
    return mesh;
  }

  // Texture coordinates run over each patch: s along the first index, t along the second.
  for (int patch = 0; patch < patches; ++patch)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        mesh.texCoords.insert(mesh.texCoords.end(), {static_cast<float>(r) / (static_cast<float>(n) - 1.0f),
                                                     static_cast<float>(c) / (static_cast<float>(n) - 1.0f)});
  ShapeMesh::Draw triangles{GL_TRIANGLES, {}};
  for (int patch = 0; patch < patches; ++patch)
    for (int r = 0; r < n - 1; ++r)
      for (int c = 0; c < n - 1; ++c) {
        const int a = patch * n * n + r * n + c;
        const int b = a + n;
        triangles.indices.insert(triangles.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
      }
  mesh.draws.push_back(std::move(triangles));
  return mesh;
}

}  // namespace

ShapeMesh teapotMesh(float size, bool wire) { return teasetMesh(kTeapot, size, wire); }
ShapeMesh teacupMesh(float size, bool wire) { return teasetMesh(kTeacup, size / 2.5f, wire); }
ShapeMesh teaspoonMesh(float size, bool wire) { return teasetMesh(kTeaspoon, size / 2.5f, wire); }

}  // namespace glass::gl::glut
