// gluTessEndPolygon's work (GLU 1.3 specification, sections 5.1-5.5): the polygon is projected
// onto a plane, tessellated there (glass/geometry/polygon_tessellation.h), and the result goes to
// the callbacks: GL_TRIANGLES (with edge flags when an edge flag callback is set), or one
// GL_LINE_LOOP per boundary loop for GLU_TESS_BOUNDARY_ONLY.
//
// Where the specification leaves the choice to the implementation, glass does what SGI's GLU
// (Mesa's libGLU) does, so that programs see the same callbacks:
//  - A polygon of one contour with at most 100 vertices that is a fan from its first vertex
//    (every fan triangle turns the same way) is output as that fan (GL_TRIANGLE_FAN, or
//    GL_TRIANGLES for 3 vertices), unless an edge flag callback is set.
//  - The plane: perpendicular to the axis along which gluTessNormal's normal is largest; without
//    a normal, one is computed from the vertices, and the orientation is chosen so that the
//    contours' total signed area is positive (so that a clockwise polygon comes out clockwise).
//  - Crossings need the combine callback (else GLU_TESS_NEED_COMBINE_CALLBACK and no output);
//    vertices at the same position are merged through it too when it is set.
#include <array>
#include <cmath>
#include <vector>

#include "glass/geometry/polygon_tessellation.h"
#include "glu/tessellator_object.h"

namespace glass::gl::glu {

namespace {

using Vertex = GLUtesselator::Vertex;
using Contours = std::vector<std::vector<Vertex>>;
using geometry::PlanarPoint;
using geometry::WindingRule;

// SGI's GLU keeps the first contour's vertices in a cache of this size and tries the fan first.
constexpr size_t kFanCacheSize = 100;
// ComputeFanOrientation's answer when the fan's triangles turn both ways.
constexpr int kInconsistent = 2;

WindingRule windingRuleOf(GLenum rule) {
  switch (rule) {
    case GLU_TESS_WINDING_NONZERO: return WindingRule::NonZero;
    case GLU_TESS_WINDING_POSITIVE: return WindingRule::Positive;
    case GLU_TESS_WINDING_NEGATIVE: return WindingRule::Negative;
    case GLU_TESS_WINDING_ABS_GEQ_TWO: return WindingRule::AbsGeqTwo;
    default: return WindingRule::Odd;
  }
}

int longAxis(const double v[3]) {
  int i = 0;
  if (std::abs(v[1]) > std::abs(v[0])) i = 1;
  if (std::abs(v[2]) > std::abs(v[i])) i = 2;
  return i;
}

int shortAxis(const double v[3]) {
  int i = 0;
  if (std::abs(v[1]) < std::abs(v[0])) i = 1;
  if (std::abs(v[2]) < std::abs(v[i])) i = 2;
  return i;
}

// The fan triangles (v0, v[k-1], v[k]). Without `check`, sums their normals into `normal`, each
// turned to agree with the sum so far. With `check`, returns +1 or -1 when every triangle that is
// not degenerate faces along or against `normal`, 0 when all are degenerate, else kInconsistent.
int fanOrientation(const std::vector<Vertex>& v, double normal[3], bool check) {
  if (!check) normal[0] = normal[1] = normal[2] = 0.0;
  int sign = 0;
  double c[3];
  for (int i = 0; i < 3; ++i) c[i] = v[1].coords[i] - v[0].coords[i];
  for (size_t k = 2; k < v.size(); ++k) {
    const double p[3] = {c[0], c[1], c[2]};
    for (int i = 0; i < 3; ++i) c[i] = v[k].coords[i] - v[0].coords[i];
    const double n[3] = {p[1] * c[2] - p[2] * c[1], p[2] * c[0] - p[0] * c[2],
                         p[0] * c[1] - p[1] * c[0]};
    const double dot = n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2];
    if (!check) {
      const double s = dot >= 0.0 ? 1.0 : -1.0;
      for (int i = 0; i < 3; ++i) normal[i] += s * n[i];
    } else if (dot != 0.0) {
      const int turn = dot > 0.0 ? 1 : -1;
      if (sign != 0 && turn != sign) return kInconsistent;
      sign = turn;
    }
  }
  return sign;
}

// The fast path for one contour. Returns false when the contour is not a fan from its first
// vertex, which then goes the general way.
bool renderFan(GLUtesselator& tess, const std::vector<Vertex>& v) {
  if (v.size() < 3) return true;  // degenerate: no output
  double normal[3] = {tess.normal[0], tess.normal[1], tess.normal[2]};
  if (normal[0] == 0.0 && normal[1] == 0.0 && normal[2] == 0.0) fanOrientation(v, normal, false);
  const int sign = fanOrientation(v, normal, true);
  if (sign == kInconsistent) return false;
  if (sign == 0) return true;
  // A fan's winding number is +1 or -1 inside, by its orientation.
  switch (tess.windingRule) {
    case GLU_TESS_WINDING_POSITIVE:
      if (sign < 0) return true;
      break;
    case GLU_TESS_WINDING_NEGATIVE:
      if (sign > 0) return true;
      break;
    case GLU_TESS_WINDING_ABS_GEQ_TWO: return true;
    default: break;
  }
  tess.callBegin(tess.boundaryOnly ? GL_LINE_LOOP
                                   : (v.size() > 3 ? GL_TRIANGLE_FAN : GL_TRIANGLES));
  tess.callVertex(v[0].data);
  if (sign > 0) {
    for (size_t k = 1; k < v.size(); ++k) tess.callVertex(v[k].data);
  } else {
    for (size_t k = v.size() - 1; k > 0; --k) tess.callVertex(v[k].data);
  }
  tess.callEnd();
  return true;
}

// A normal of the polygon: the two vertices furthest apart along some axis, and the third that
// makes the largest triangle with them.
void computeNormal(const Contours& contours, double normal[3]) {
  const Vertex* minVertex[3] = {};
  const Vertex* maxVertex[3] = {};
  double minValue[3], maxValue[3];
  for (int i = 0; i < 3; ++i) {
    minValue[i] = 2.0 * GLU_TESS_MAX_COORD;
    maxValue[i] = -2.0 * GLU_TESS_MAX_COORD;
  }
  for (const auto& contour : contours) {
    for (const Vertex& v : contour) {
      for (int i = 0; i < 3; ++i) {
        if (v.coords[i] < minValue[i]) {
          minValue[i] = v.coords[i];
          minVertex[i] = &v;
        }
        if (v.coords[i] > maxValue[i]) {
          maxValue[i] = v.coords[i];
          maxVertex[i] = &v;
        }
      }
    }
  }
  int i = 0;
  if (maxValue[1] - minValue[1] > maxValue[0] - minValue[0]) i = 1;
  if (maxValue[2] - minValue[2] > maxValue[i] - minValue[i]) i = 2;
  normal[0] = normal[1] = 0.0;
  normal[2] = 1.0;
  if (!(minValue[i] < maxValue[i])) return;  // all vertices at one point: any normal will do

  const Vertex* v1 = minVertex[i];
  const Vertex* v2 = maxVertex[i];
  const double d1[3] = {v1->coords[0] - v2->coords[0], v1->coords[1] - v2->coords[1],
                        v1->coords[2] - v2->coords[2]};
  double maxLength2 = 0.0;
  for (const auto& contour : contours) {
    for (const Vertex& v : contour) {
      const double d2[3] = {v.coords[0] - v2->coords[0], v.coords[1] - v2->coords[1],
                            v.coords[2] - v2->coords[2]};
      const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                           d1[0] * d2[1] - d1[1] * d2[0]};
      const double length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      if (length2 > maxLength2) {
        maxLength2 = length2;
        for (int k = 0; k < 3; ++k) normal[k] = n[k];
      }
    }
  }
  if (maxLength2 <= 0.0) {  // all vertices on a line: any normal perpendicular to it
    normal[0] = normal[1] = normal[2] = 0.0;
    normal[shortAxis(d1)] = 1.0;
  }
}

// The vertices in the plane of projection, contour by contour: perpendicular to the normal's
// longest axis, turned so that looking against the normal the plane's axes are counter-clockwise.
std::vector<std::vector<PlanarPoint>> project(const GLUtesselator& tess,
                                              const Contours& contours) {
  double normal[3] = {tess.normal[0], tess.normal[1], tess.normal[2]};
  const bool computed = normal[0] == 0.0 && normal[1] == 0.0 && normal[2] == 0.0;
  if (computed) computeNormal(contours, normal);
  const int axis = longAxis(normal);
  const int s = (axis + 1) % 3, t = (axis + 2) % 3;
  const double tSign = normal[axis] > 0.0 ? 1.0 : -1.0;
  std::vector<std::vector<PlanarPoint>> planar;
  double area = 0.0;
  for (const auto& contour : contours) {
    std::vector<PlanarPoint> points;
    points.reserve(contour.size());
    for (const Vertex& v : contour) points.push_back({v.coords[s], tSign * v.coords[t]});
    for (size_t k = 0; k < points.size(); ++k) {
      const PlanarPoint& a = points[k];
      const PlanarPoint& b = points[(k + 1) % points.size()];
      area += (a.x - b.x) * (a.y + b.y);
    }
    planar.push_back(std::move(points));
  }
  // A computed normal has no preferred side: take the one that makes the polygon positive.
  if (computed && area < 0.0) {
    for (auto& points : planar) {
      for (PlanarPoint& p : points) p.y = -p.y;
    }
  }
  return planar;
}

void renderGeneral(GLUtesselator& tess, const Contours& contours) {
  const geometry::PolygonTessellation result = geometry::tessellatePolygon(
      project(tess, contours), windingRuleOf(tess.windingRule), tess.boundaryOnly);

  // Data and coordinates of every vertex, the created ones through the combine callback.
  std::vector<void*> data;
  std::vector<std::array<double, 3>> coords;
  for (const auto& contour : contours) {
    for (const Vertex& v : contour) {
      data.push_back(v.data);
      coords.push_back({v.coords[0], v.coords[1], v.coords[2]});
    }
  }
  for (const geometry::CreatedVertex& created : result.created) {
    GLdouble position[3] = {0.0, 0.0, 0.0};
    void* sources[4] = {nullptr, nullptr, nullptr, nullptr};
    GLfloat weights[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; ++k) {
      const int source = created.sources[k];
      if (source < 0) continue;
      sources[k] = data[source];
      weights[k] = static_cast<GLfloat>(created.weights[k]);
      for (int i = 0; i < 3; ++i) position[i] += created.weights[k] * coords[source][i];
    }
    void* out = nullptr;
    tess.callCombine(position, sources, weights, &out);
    if (!out) {
      if (created.isCrossing) {
        tess.reportError(GLU_TESS_NEED_COMBINE_CALLBACK);
        return;
      }
      out = sources[0];
    }
    data.push_back(out);
    coords.push_back({position[0], position[1], position[2]});
  }

  if (tess.boundaryOnly) {
    for (const auto& loop : result.boundaryLoops) {
      tess.callBegin(GL_LINE_LOOP);
      for (int v : loop) tess.callVertex(data[v]);
      tess.callEnd();
    }
    return;
  }
  if (result.triangles.empty()) return;
  const bool flags = tess.hasEdgeFlagCallback();
  int edgeState = -1;  // the flag last reported; -1 reports the first one whatever it is
  tess.callBegin(GL_TRIANGLES);
  for (const geometry::TessellatedTriangle& triangle : result.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (flags && edgeState != static_cast<int>(triangle.boundaryEdge[k])) {
        edgeState = triangle.boundaryEdge[k];
        tess.callEdgeFlag(triangle.boundaryEdge[k]);
      }
      tess.callVertex(data[triangle.vertices[k]]);
    }
  }
  tess.callEnd();
}

}  // namespace

void renderTessellation(GLUtesselator& tess, const Contours& contours) {
  int contoursWithVertices = 0;
  size_t vertexCount = 0;
  const std::vector<Vertex>* only = nullptr;
  for (const auto& contour : contours) {
    if (contour.empty()) continue;
    ++contoursWithVertices;
    vertexCount += contour.size();
    only = &contour;
  }
  if (contoursWithVertices == 0) return;
  if (contoursWithVertices == 1 && vertexCount <= kFanCacheSize && !tess.hasEdgeFlagCallback() &&
      renderFan(tess, *only)) {
    return;
  }
  renderGeneral(tess, contours);
}

}  // namespace glass::gl::glu
