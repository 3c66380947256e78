// `ifs3d`: the polyhedral rebuild of a 3D IFS (glass::geometry's polyhedralRebuild) as
// GL_TRIANGLES with one normal per triangle (flat: the face's own), each map's part in its colour.
// With `map K step T` the whole rebuild is drawn through map K's animation matrix at T
// (glass/geometry/polar_decomposition.h: scaling, then rotation by slerp, then translation).
#include "interpret/executor.h"

#include <glass/geometry/ifs3d.h>
#include <glass/geometry/polar_decomposition.h>
#include <glass/scene/ifs3_rebuild_draw.h>

namespace glass::scene {

void Interpreter::Executor::run(const Ifs3d &s) {
  std::string problem;
  const std::vector<geometry::RebuildTriangle> triangles =
      geometry::polyhedralRebuild(*s.system, s.depth, geometry::kMaxRebuildTriangles, problem);
  if (!problem.empty()) fail("ifs3d: " + problem);
  geometry::Affine3 motion;
  if (s.animatedMap >= 0) {
    const double t = value(s.step);
    if (!(t >= 0.0 && t <= 1.0)) fail("ifs3d: step " + std::to_string(t) + " is outside 0..1");
    motion = geometry::decomposeTrs(s.system->maps[static_cast<std::size_t>(s.animatedMap)].transform).at(t);
  }
  // The colours are the statement's own: the current colour and normal come back after it.
  saveCurrentValues();
  glPushAttrib(GL_CURRENT_BIT);
  glPushMatrix();
  const glm::dmat4 m = motion.toMatrix4();
  glMultMatrixd(&m[0][0]);
  drawIfs3Rebuild(*s.system, triangles, s.partColors);
  glPopMatrix();
  glPopAttrib();
  resendCurrentValues();
}

} // namespace glass::scene
