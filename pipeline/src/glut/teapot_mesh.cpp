// The Utah teapot as freeglut 3 builds it, so that glutSolidTeapot and glutWireTeapot draw the
// same triangles and lines with glass as with freeglut (Mesa's reference images use freeglut).
//
// The data: Newell's teapot in the arrangement freeglut 3 uses: ten bicubic patches over 129
// control points (z up, standing on z = 0). The rim, the two body patches, the two lid patches
// and the bottom cover one quadrant and are copied into the other three by turning about the
// vertical axis; the handle and spout patches cover one side and are mirrored to the other.
//
// The arithmetic follows freeglut's, in float and in the same order, because the pictures are
// compared pixel by pixel: control points are turned to y up and scaled first,
//   (x, y, z) -> (x * size / 2, (z - 1.575) * size / 2, -y * size / 2),
// then each patch is evaluated on an n x n grid (n = 8 solid, 10 wire) from tabulated Bernstein
// polynomials and their derivatives; the normal is the normalized cross product of the two
// partial derivatives (along the patch's second index, then its first); the copies turn or
// mirror the evaluated points and normals. Solid grid quads become triangles (a, b, c), (a, c, d)
// with a = (r, c), b = (r + 1, c), c = (r + 1, c + 1), d = (r, c + 1); the wire teapot is line
// strips along each grid direction, all patches' first direction first.
#include <cmath>
#include <cstddef>

#include "glut/shape_mesh.h"

namespace glass::gl::glut {

namespace {

constexpr int kPatchCount = 10;
constexpr int kTurnedPatches = 6;  // the first six are copied into all four quadrants
constexpr float kCentreHeight = 1.575f;

constexpr int kPatches[kPatchCount][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},                  // rim
    {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27},        // body
    {24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39},
    {40, 41, 42, 40, 43, 44, 45, 46, 47, 47, 47, 47, 48, 49, 50, 51},        // lid
    {48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63},
    {64, 64, 64, 64, 65, 66, 67, 68, 69, 70, 71, 72, 39, 38, 37, 36},        // bottom
    {73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88},        // handle
    {85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100},
    {101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116},  // spout
    {113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128},
};

constexpr float kControlPoints[129][3] = {
    {1.4f, 0.0f, 2.4f}, {1.4f, -0.784f, 2.4f}, {0.784f, -1.4f, 2.4f},
    {0.0f, -1.4f, 2.4f}, {1.3375f, 0.0f, 2.53125f}, {1.3375f, -0.749f, 2.53125f},
    {0.749f, -1.3375f, 2.53125f}, {0.0f, -1.3375f, 2.53125f}, {1.4375f, 0.0f, 2.53125f},
    {1.4375f, -0.805f, 2.53125f}, {0.805f, -1.4375f, 2.53125f}, {0.0f, -1.4375f, 2.53125f},
    {1.5f, 0.0f, 2.4f}, {1.5f, -0.84f, 2.4f}, {0.84f, -1.5f, 2.4f},
    {0.0f, -1.5f, 2.4f}, {1.75f, 0.0f, 1.875f}, {1.75f, -0.98f, 1.875f},
    {0.98f, -1.75f, 1.875f}, {0.0f, -1.75f, 1.875f}, {2.0f, 0.0f, 1.35f},
    {2.0f, -1.12f, 1.35f}, {1.12f, -2.0f, 1.35f}, {0.0f, -2.0f, 1.35f},
    {2.0f, 0.0f, 0.9f}, {2.0f, -1.12f, 0.9f}, {1.12f, -2.0f, 0.9f},
    {0.0f, -2.0f, 0.9f}, {2.0f, 0.0f, 0.45f}, {2.0f, -1.12f, 0.45f},
    {1.12f, -2.0f, 0.45f}, {0.0f, -2.0f, 0.45f}, {1.5f, 0.0f, 0.225f},
    {1.5f, -0.84f, 0.225f}, {0.84f, -1.5f, 0.225f}, {0.0f, -1.5f, 0.225f},
    {1.5f, 0.0f, 0.15f}, {1.5f, -0.84f, 0.15f}, {0.84f, -1.5f, 0.15f},
    {0.0f, -1.5f, 0.15f}, {0.0f, 0.0f, 3.15f}, {0.0f, -0.002f, 3.15f},
    {0.002f, 0.0f, 3.15f}, {0.8f, 0.0f, 3.15f}, {0.8f, -0.45f, 3.15f},
    {0.45f, -0.8f, 3.15f}, {0.0f, -0.8f, 3.15f}, {0.0f, 0.0f, 2.85f},
    {0.2f, 0.0f, 2.7f}, {0.2f, -0.112f, 2.7f}, {0.112f, -0.2f, 2.7f},
    {0.0f, -0.2f, 2.7f}, {0.4f, 0.0f, 2.55f}, {0.4f, -0.224f, 2.55f},
    {0.224f, -0.4f, 2.55f}, {0.0f, -0.4f, 2.55f}, {1.3f, 0.0f, 2.55f},
    {1.3f, -0.728f, 2.55f}, {0.728f, -1.3f, 2.55f}, {0.0f, -1.3f, 2.55f},
    {1.3f, 0.0f, 2.4f}, {1.3f, -0.728f, 2.4f}, {0.728f, -1.3f, 2.4f},
    {0.0f, -1.3f, 2.4f}, {0.0f, 0.0f, 0.0f}, {0.0f, -1.425f, 0.0f},
    {0.798f, -1.425f, 0.0f}, {1.425f, -0.798f, 0.0f}, {1.425f, 0.0f, 0.0f},
    {0.0f, -1.5f, 0.075f}, {0.84f, -1.5f, 0.075f}, {1.5f, -0.84f, 0.075f},
    {1.5f, 0.0f, 0.075f}, {-1.6f, 0.0f, 2.025f}, {-1.6f, -0.3f, 2.025f},
    {-1.5f, -0.3f, 2.25f}, {-1.5f, 0.0f, 2.25f}, {-2.3f, 0.0f, 2.025f},
    {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f}, {-2.5f, 0.0f, 2.25f},
    {-2.7f, 0.0f, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3.0f, -0.3f, 2.25f},
    {-3.0f, 0.0f, 2.25f}, {-2.7f, 0.0f, 1.8f}, {-2.7f, -0.3f, 1.8f},
    {-3.0f, -0.3f, 1.8f}, {-3.0f, 0.0f, 1.8f}, {-2.7f, 0.0f, 1.575f},
    {-2.7f, -0.3f, 1.575f}, {-3.0f, -0.3f, 1.35f}, {-3.0f, 0.0f, 1.35f},
    {-2.5f, 0.0f, 1.125f}, {-2.5f, -0.3f, 1.125f}, {-2.65f, -0.3f, 0.9375f},
    {-2.65f, 0.0f, 0.9375f}, {-2.0f, 0.0f, 0.9f}, {-2.0f, -0.3f, 0.9f},
    {-1.9f, -0.3f, 0.6f}, {-1.9f, 0.0f, 0.6f}, {1.7f, 0.0f, 1.425f},
    {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f}, {1.7f, 0.0f, 0.6f},
    {2.6f, 0.0f, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f},
    {3.1f, 0.0f, 0.825f}, {2.3f, 0.0f, 2.1f}, {2.3f, -0.25f, 2.1f},
    {2.4f, -0.25f, 2.025f}, {2.4f, 0.0f, 2.025f}, {2.7f, 0.0f, 2.4f},
    {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0.0f, 2.4f},
    {2.8f, 0.0f, 2.475f}, {2.8f, -0.25f, 2.475f}, {3.525f, -0.25f, 2.49375f},
    {3.525f, 0.0f, 2.49375f}, {2.9f, 0.0f, 2.475f}, {2.9f, -0.15f, 2.475f},
    {3.45f, -0.15f, 2.5125f}, {3.45f, 0.0f, 2.5125f}, {2.8f, 0.0f, 2.4f},
    {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f}, {3.2f, 0.0f, 2.4f},
};

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

}  // namespace

ShapeMesh teapotMesh(float size, bool wire) {
  const int n = wire ? 10 : 8;
  const BernsteinTable bernstein = bernsteinTable(n);
  ShapeMesh mesh;
  Grid points, normals;
  for (int p = 0; p < kPatchCount; ++p) {
    float cp[4][4][3];
    for (int i = 0; i < 16; ++i) {
      const float* source = kControlPoints[kPatches[p][i]];
      cp[i / 4][i % 4][0] = source[0] * size / 2.0f;
      cp[i / 4][i % 4][1] = (source[2] - kCentreHeight) * size / 2.0f;
      cp[i / 4][i % 4][2] = -source[1] * size / 2.0f;
    }
    evaluatePatch(cp, n, bernstein, points, normals);
    if (p == 3) fixCollapsedRow(normals, n, 1.0f);
    if (p == 5) fixCollapsedRow(normals, n, -1.0f);
    if (p < kTurnedPatches) {
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

}  // namespace glass::gl::glut
