// glMap1, glMap2, glGetMap and glMapGrid (spec 5.1, 6.1.8).
#include <glm/vec4.hpp>

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "evaluators/map_targets.h"

namespace glass::gl {

namespace {

bool validOrder(int order) { return order >= 1 && order <= kMaxEvalOrder; }

}  // namespace

int mapValuesPerPoint(GLenum target) {
  MapKind kind;
  return map1Kind(target, kind) || map2Kind(target, kind) ? mapComponents(kind) : 0;
}

// Errors (spec 5.1): GL_INVALID_ENUM for a target that is not a map, GL_INVALID_VALUE for
// u1 == u2, a stride below k or an order outside 1..GL_MAX_EVAL_ORDER.
void map1Command(Context& ctx, GLenum target, double u1, double u2, int stride, int order,
                 const std::vector<double>& points) {
  if (rejectInsideBeginEnd(ctx)) return;
  MapKind kind;
  if (!map1Kind(target, kind)) return recordError(ctx, GL_INVALID_ENUM);
  const int k = mapComponents(kind);
  if (u1 == u2 || stride < k || !validOrder(order)) return recordError(ctx, GL_INVALID_VALUE);
  if (points.size() < static_cast<std::size_t>(order * k)) return;  // no data was read
  std::vector<glm::dvec4> control;
  control.reserve(static_cast<std::size_t>(order));
  for (int i = 0; i < order; ++i) control.push_back(mapControlPoint(kind, &points[static_cast<std::size_t>(i * k)]));
  Map1& map = ctx.evaluators.maps1[mapIndex(kind)];
  map.u1 = u1;
  map.u2 = u2;
  map.curve = geometry::BezierCurve::fromHomogeneous(std::move(control));
}

void map2Command(Context& ctx, GLenum target, double u1, double u2, int ustride, int uorder,
                 double v1, double v2, int vstride, int vorder, const std::vector<double>& points) {
  if (rejectInsideBeginEnd(ctx)) return;
  MapKind kind;
  if (!map2Kind(target, kind)) return recordError(ctx, GL_INVALID_ENUM);
  const int k = mapComponents(kind);
  if (u1 == u2 || v1 == v2 || ustride < k || vstride < k || !validOrder(uorder) || !validOrder(vorder))
    return recordError(ctx, GL_INVALID_VALUE);
  if (points.size() < static_cast<std::size_t>(uorder * vorder * k)) return;
  std::vector<glm::dvec4> control;
  control.reserve(static_cast<std::size_t>(uorder * vorder));
  for (int p = 0; p < uorder * vorder; ++p) control.push_back(mapControlPoint(kind, &points[static_cast<std::size_t>(p * k)]));
  Map2& map = ctx.evaluators.maps2[mapIndex(kind)];
  map.u1 = u1;
  map.u2 = u2;
  map.v1 = v1;
  map.v2 = v2;
  map.surface = geometry::BezierSurface::fromHomogeneous(uorder - 1, vorder - 1, std::move(control));
}

// GL_COEFF lists the control points as glMap stored them, u the outer index for two-dimensional
// maps (as Mesa returns them), k values each.
bool getMapCommand(Context& ctx, GLenum target, GLenum query, std::vector<double>& values) {
  if (rejectInsideBeginEnd(ctx)) return false;
  values.clear();
  MapKind kind;
  const bool one = map1Kind(target, kind);
  if (!one && !map2Kind(target, kind)) {
    recordError(ctx, GL_INVALID_ENUM);
    return false;
  }
  const int k = mapComponents(kind);
  const auto appendPoint = [&](const glm::dvec4& p) {
    for (int c = 0; c < k; ++c) values.push_back(p[c]);
  };
  const Map1& map1 = ctx.evaluators.maps1[mapIndex(kind)];
  const Map2& map2 = ctx.evaluators.maps2[mapIndex(kind)];
  switch (query) {
    case GL_COEFF:
      if (one) {
        for (const glm::dvec4& p : map1.curve.homogeneousControlPoints()) appendPoint(p);
      } else {
        for (const glm::dvec4& p : map2.surface.homogeneousControlPoints()) appendPoint(p);
      }
      return true;
    case GL_ORDER:
      if (one) {
        values = {static_cast<double>(map1.curve.controlPointCount())};
      } else {
        values = {static_cast<double>(map2.surface.degreeU() + 1), static_cast<double>(map2.surface.degreeV() + 1)};
      }
      return true;
    case GL_DOMAIN:
      values = one ? std::vector<double>{map1.u1, map1.u2} : std::vector<double>{map2.u1, map2.u2, map2.v1, map2.v2};
      return true;
    default:
      recordError(ctx, GL_INVALID_ENUM);
      return false;
  }
}

void mapGrid1Command(Context& ctx, int un, double u1, double u2) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (un <= 0) return recordError(ctx, GL_INVALID_VALUE);
  ctx.evaluators.attributes.grid1 = {un, u1, u2};
}

void mapGrid2Command(Context& ctx, int un, double u1, double u2, int vn, double v1, double v2) {
  if (rejectInsideBeginEnd(ctx)) return;
  if (un <= 0 || vn <= 0) return recordError(ctx, GL_INVALID_VALUE);
  ctx.evaluators.attributes.grid2 = {un, vn, u1, u2, v1, v2};
}

}  // namespace glass::gl
