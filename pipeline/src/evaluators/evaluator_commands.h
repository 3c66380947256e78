// The evaluator commands (spec 5.1) on a context, with their errors. The GL entry points
// (evaluator_api.cpp) convert arguments, copy control points, and record or run these.
#pragma once

#include <GL/gl.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace glass::gl {

struct Context;
struct StateValue;

// glMap1 and glMap2. points holds the control points read with the caller's strides and packed:
// order (map1) or uorder * vorder (map2, u the outer index) points of k values each. The
// arguments are checked here; the entry point reads no points for a call these checks reject
// (see mapValuesPerPoint) and passes an empty vector.
void map1Command(Context& ctx, GLenum target, double u1, double u2, int stride, int order,
                 const std::vector<double>& points);
void map2Command(Context& ctx, GLenum target, double u1, double u2, int ustride, int uorder,
                 double v1, double v2, int vstride, int vorder, const std::vector<double>& points);
// k, the values per control point of a GL_MAP1_* or GL_MAP2_* target, or 0 for another name.
int mapValuesPerPoint(GLenum target);

// glGetMap: the values of GL_COEFF, GL_ORDER or GL_DOMAIN; false (after recording the error)
// for a bad target or query, or inside glBegin/glEnd.
bool getMapCommand(Context& ctx, GLenum target, GLenum query, std::vector<double>& values);

void mapGrid1Command(Context& ctx, int un, double u1, double u2);
void mapGrid2Command(Context& ctx, int un, double u1, double u2, int vn, double v1, double v2);

// What one evaluation produces: the vertex (x, y, z, w) in object coordinates and, when their
// maps are enabled, the colour, normal and texture coordinates (completed to four as glTexCoord1-3
// complete them).
struct EvaluatedVertex {
  glm::dvec4 object{0.0, 0.0, 0.0, 1.0};
  bool hasColor = false, hasNormal = false, hasTexCoord = false;
  glm::dvec4 color{0.0};
  glm::dvec3 normal{0.0};
  glm::dvec4 texCoord{0.0};
};
// Evaluates the enabled maps of one or two dimensions at the domain point; false when no vertex
// map is enabled (glEvalCoord then does nothing).
bool evaluateMaps1(const Context& ctx, double u, EvaluatedVertex& out);
bool evaluateMaps2(const Context& ctx, double u, double v, EvaluatedVertex& out);

void evalCoord1Command(Context& ctx, double u);
void evalCoord2Command(Context& ctx, double u, double v);
void evalPoint1Command(Context& ctx, int i);
void evalPoint2Command(Context& ctx, int i, int j);
void evalMesh1Command(Context& ctx, GLenum mode, int i1, int i2);
void evalMesh2Command(Context& ctx, GLenum mode, int i1, int i2, int j1, int j2);

// glEnable/glDisable/glIsEnabled of GL_MAP1_*, GL_MAP2_* and GL_AUTO_NORMAL; false when cap is
// none of them.
bool setEvaluatorCapability(Context& ctx, GLenum cap, bool enabled);
bool getEvaluatorCapability(const Context& ctx, GLenum cap, bool& enabled);
// glGet of GL_MAX_EVAL_ORDER and the grids; false for any other pname.
bool queryEvaluatorState(const Context& ctx, GLenum pname, StateValue& value);

}  // namespace glass::gl
