// Evaluator state (spec 5.1, table 6.24): the nine one-dimensional and nine two-dimensional maps
// of glMap1 and glMap2, their enables, GL_AUTO_NORMAL and the grids of glMapGrid.
#pragma once

#include <array>

#include "glass/geometry/bezier_curve.h"
#include "glass/geometry/bezier_surface.h"

namespace glass::gl {

// The maps in the order of their GL names: GL_MAP1_COLOR_4 + k and GL_MAP2_COLOR_4 + k.
enum class MapKind { Color4, Index, Normal, TextureCoord1, TextureCoord2, TextureCoord3, TextureCoord4, Vertex3, Vertex4 };
inline constexpr int kMapKindCount = 9;
// GL_MAX_EVAL_ORDER, as in Mesa (the specification asks for at least 8).
inline constexpr int kMaxEvalOrder = 30;

// A map's control points are kept as homogeneous 4-vectors of the library's Bezier forms: the k
// values of a point in x, y, z, w order, the unused ones 0. Only the vertex maps are ever
// projected (GL_MAP*_VERTEX_4 is the rational case); the other maps are evaluated as plain
// polynomials in all four components.
struct Map1 {
  double u1 = 0.0, u2 = 1.0;
  geometry::BezierCurve curve;  // order = control point count
};

struct Map2 {
  double u1 = 0.0, u2 = 1.0, v1 = 0.0, v2 = 1.0;
  geometry::BezierSurface surface;  // uorder = degreeU + 1, vorder = degreeV + 1
};

struct MapGrid1 {
  int segments = 1;
  double u1 = 0.0, u2 = 1.0;
};

struct MapGrid2 {
  int segmentsU = 1, segmentsV = 1;
  double u1 = 0.0, u2 = 1.0, v1 = 0.0, v2 = 1.0;
};

// What glPushAttrib(GL_EVAL_BIT) saves: the enables and the grids, not the maps.
struct EvaluatorAttributes {
  std::array<bool, kMapKindCount> map1Enabled{};
  std::array<bool, kMapKindCount> map2Enabled{};
  bool autoNormal = false;
  MapGrid1 grid1;
  MapGrid2 grid2;
};

struct EvaluatorState {
  EvaluatorState();  // every map of order 1 holding the attribute's initial value (table 6.24)

  EvaluatorAttributes attributes;
  std::array<Map1, kMapKindCount> maps1;
  std::array<Map2, kMapKindCount> maps2;
};

}  // namespace glass::gl
