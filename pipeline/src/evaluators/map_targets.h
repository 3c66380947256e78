// The evaluator map targets (spec 5.1, table 5.1): which GL name is which map, how many values a
// control point has, and the attribute's initial value that a map of order 1 holds at start.
#pragma once

#include <GL/gl.h>

#include "evaluators/evaluator_state.h"

namespace glass::gl {

// false when target is not one of GL_MAP1_COLOR_4 .. GL_MAP1_VERTEX_4.
bool map1Kind(GLenum target, MapKind& kind);
// false when target is not one of GL_MAP2_COLOR_4 .. GL_MAP2_VERTEX_4.
bool map2Kind(GLenum target, MapKind& kind);

// k: the values per control point (table 5.1).
int mapComponents(MapKind kind);

inline int mapIndex(MapKind kind) { return static_cast<int>(kind); }

// A control point's k values as the homogeneous 4-vector the map keeps: unused components 0,
// except that a GL_MAP*_VERTEX_3 point gets w = 1 (its vertex is (x, y, z, 1)).
glm::dvec4 mapControlPoint(MapKind kind, const double* values);

}  // namespace glass::gl
