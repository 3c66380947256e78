// glutSolidTeapot and glutWireTeapot for the Mesa build of the scene library only.
//
// freeglut refuses to draw without glutInit, which needs a window system, so the reference
// renderer takes its GLUT shapes from glass's pipeline/src/glut, written on plain GL calls. The
// teapot there drives glass's evaluators directly; this file draws the same teapot through the
// public evaluator API (glMap2d, glMapGrid2d, glEvalMesh2), so Mesa evaluates it: the geometry
// library's Utah teapot data, turned y-up and scaled as freeglut does, (x, y, z) ->
// (x, z - 1.575, -y) * size / 2, on a 7 x 7 grid (9 x 9 wire) with GL_AUTO_NORMAL and, for the
// solid teapot, texture coordinates (s, t) = (v, u) over each patch.
#include <GL/gl.h>
#include <GL/glut.h>

#include <glass/geometry/teapot.h>

#include <vector>

namespace {

void drawTeapot(double size, bool solid) {
  const double scale = size / 2.0;
  const int segments = solid ? 7 : 9;
  glPushAttrib(GL_EVAL_BIT | GL_ENABLE_BIT);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  if (solid) {
    // u = k, v = l at ctrl[2k + 4l]: (0,0) -> (0,0), (1,0) -> (0,1), (0,1) -> (1,0), (1,1) -> (1,1).
    static const GLdouble texture[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    glMap2d(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, 0.0, 1.0, 4, 2, texture);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
  }
  glMapGrid2d(segments, 0.0, 1.0, segments, 0.0, 1.0);
  const auto points = glass::geometry::teapotControlPoints();
  for (const auto &patch : glass::geometry::teapotPatchIndices()) {
    // Control point (i, j) of the data, i the first index, sits at u = j, v = i: ustride 3,
    // vstride 12 over the points in the data's order.
    std::vector<GLdouble> control;
    for (int index : patch) {
      const auto &p = points[static_cast<std::size_t>(index)];
      control.insert(control.end(), {p.x * scale, (p.z - 1.575) * scale, -p.y * scale});
    }
    glMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, control.data());
    glEvalMesh2(solid ? GL_FILL : GL_LINE, 0, segments, 0, segments);
  }
  glPopAttrib();
}

} // namespace

extern "C" {
void glutSolidTeapot(GLdouble size) { drawTeapot(size, true); }
void glutWireTeapot(GLdouble size) { drawTeapot(size, false); }
}
