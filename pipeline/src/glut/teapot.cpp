// glutSolidTeapot and glutWireTeapot: the Utah teapot (Newell's 32 bicubic patches, the
// geometry library's teapot data) drawn through the evaluators, glMap2 and glEvalMesh2, as the
// original GLUT drew it.
//
// Size, orientation and sampling follow freeglut 3, so that a program draws the same teapot with
// glass as with freeglut: the patch data (z up, standing on z = 0) is turned so that y is up,
// (x, y, z) -> (x, z - 1.575, -y) * size / 2, which freeglut folds into the control points rather
// than the modelview matrix (so normals keep unit length without GL_NORMALIZE); each patch is
// sampled on a grid of 8 x 8 points for the solid teapot and 10 x 10 for the wire one; the normal
// is the cross product of the derivative along a patch's second index and the one along its
// first (u runs along the second index, v along the first, so GL_AUTO_NORMAL's du x dv is that
// normal); the solid teapot has texture coordinates s = v, t = u over each patch. At the top of
// the lid and the middle of the bottom, where a row of control points collapses to one point,
// freeglut sets the normal to (0, +-1, 0); the evaluators' limit normal is that same vector.
//
// What differs from freeglut: freeglut 3 evaluates the patches itself in float and draws
// triangles split along the other diagonal of each grid quad; here the evaluators compute in
// double and glEvalMesh2 splits quads as Mesa's evaluators do.
//
// The teapot leaves no trace in the GL state: the evaluator state (maps, enables, grid) is put
// back as it was. It is one command for display lists.
#include <GL/glut.h>

#include <array>
#include <vector>

#include "core/context.h"
#include "evaluators/evaluator_commands.h"
#include "evaluators/map_targets.h"
#include "glass/geometry/teapot.h"
#include "lists/command_recording.h"

namespace glass::gl::glut {

namespace {

// freeglut's teapot centre height in Newell's units (it once was 1.5).
constexpr double kTeapotCentreHeight = 1.575;

// A teapot patch as a GL_MAP2_VERTEX_3 map: turned to y up and scaled, u along the data's second
// index.
geometry::BezierSurface teapotMap(const std::array<int, 16>& indices, double size) {
  const std::span<const glm::dvec3> points = geometry::teapotControlPoints();
  const double scale = size / 2.0;
  std::vector<glm::dvec4> net(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const glm::dvec3& p = points[static_cast<std::size_t>(indices[static_cast<std::size_t>(4 * i + j)])];
      net[static_cast<std::size_t>(4 * j + i)] =
          glm::dvec4(p.x * scale, (p.z - kTeapotCentreHeight) * scale, -p.y * scale, 1.0);
    }
  return geometry::BezierSurface::fromHomogeneous(3, 3, std::move(net));
}

// (s, t) = (v, u): bilinear, u the outer index of the map.
geometry::BezierSurface teapotTextureMap() {
  std::vector<glm::dvec4> net = {{0.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {1.0, 1.0, 0.0, 0.0}};
  return geometry::BezierSurface::fromHomogeneous(1, 1, std::move(net));
}

void drawTeapot(Context& ctx, double size, bool solid) {
  if (rejectInsideBeginEnd(ctx)) return;
  const EvaluatorState saved = ctx.evaluators;
  const int segments = solid ? 7 : 9;
  EvaluatorAttributes& attributes = ctx.evaluators.attributes;
  attributes = EvaluatorAttributes{};
  attributes.map2Enabled[mapIndex(MapKind::Vertex3)] = true;
  attributes.autoNormal = true;
  attributes.grid2 = MapGrid2{segments, segments, 0.0, 1.0, 0.0, 1.0};
  if (solid) {
    attributes.map2Enabled[mapIndex(MapKind::TextureCoord2)] = true;
    ctx.evaluators.maps2[mapIndex(MapKind::TextureCoord2)] = Map2{0.0, 1.0, 0.0, 1.0, teapotTextureMap()};
  }
  for (const std::array<int, 16>& indices : geometry::teapotPatchIndices()) {
    ctx.evaluators.maps2[mapIndex(MapKind::Vertex3)] = Map2{0.0, 1.0, 0.0, 1.0, teapotMap(indices, size)};
    evalMesh2Command(ctx, solid ? GL_FILL : GL_LINE, 0, segments, 0, segments);
  }
  ctx.evaluators = saved;
}

}  // namespace

}  // namespace glass::gl::glut

extern "C" {

void glutSolidTeapot(GLdouble size) {
  glass::gl::compileOrExecute([=](glass::gl::Context& ctx) { glass::gl::glut::drawTeapot(ctx, size, true); });
}

void glutWireTeapot(GLdouble size) {
  glass::gl::compileOrExecute([=](glass::gl::Context& ctx) { glass::gl::glut::drawTeapot(ctx, size, false); });
}

}  // extern "C"
