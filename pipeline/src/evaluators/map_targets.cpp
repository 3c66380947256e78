#include "evaluators/map_targets.h"

#include <array>
#include <vector>

namespace glass::gl {

bool map1Kind(GLenum target, MapKind& kind) {
  if (target < GL_MAP1_COLOR_4 || target > GL_MAP1_VERTEX_4) return false;
  kind = static_cast<MapKind>(target - GL_MAP1_COLOR_4);
  return true;
}

bool map2Kind(GLenum target, MapKind& kind) {
  if (target < GL_MAP2_COLOR_4 || target > GL_MAP2_VERTEX_4) return false;
  kind = static_cast<MapKind>(target - GL_MAP2_COLOR_4);
  return true;
}

int mapComponents(MapKind kind) {
  static constexpr std::array<int, kMapKindCount> kComponents = {4, 1, 3, 1, 2, 3, 4, 3, 4};
  return kComponents[static_cast<std::size_t>(mapIndex(kind))];
}

glm::dvec4 mapControlPoint(MapKind kind, const double* values) {
  glm::dvec4 point(0.0);
  const int k = mapComponents(kind);
  for (int c = 0; c < k; ++c) point[c] = values[c];
  if (kind == MapKind::Vertex3) point.w = 1.0;
  return point;
}

namespace {

// Table 6.24: each map starts with order 1, domain [0, 1], and the attribute's initial value.
glm::dvec4 initialValue(MapKind kind) {
  switch (kind) {
    case MapKind::Color4: return {1.0, 1.0, 1.0, 1.0};
    case MapKind::Index: return {1.0, 0.0, 0.0, 0.0};
    case MapKind::Normal: return {0.0, 0.0, 1.0, 0.0};
    case MapKind::TextureCoord4: return {0.0, 0.0, 0.0, 1.0};
    case MapKind::Vertex3: return {0.0, 0.0, 0.0, 1.0};
    case MapKind::Vertex4: return {0.0, 0.0, 0.0, 1.0};
    default: return {0.0, 0.0, 0.0, 0.0};
  }
}

}  // namespace

EvaluatorState::EvaluatorState() {
  for (int k = 0; k < kMapKindCount; ++k) {
    const std::vector<glm::dvec4> point = {initialValue(static_cast<MapKind>(k))};
    maps1[k].curve = geometry::BezierCurve::fromHomogeneous(point);
    maps2[k].surface = geometry::BezierSurface::fromHomogeneous(0, 0, point);
  }
}

}  // namespace glass::gl
