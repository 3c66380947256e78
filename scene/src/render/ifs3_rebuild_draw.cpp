#include "glass/scene/ifs3_rebuild_draw.h"

#include "gl_api.h"

namespace glass::scene {

void drawIfs3Rebuild(const geometry::IteratedFunctionSystem3 &ifs,
                     const std::vector<geometry::RebuildTriangle> &triangles, bool partColors) {
  glBegin(GL_TRIANGLES);
  int lastPart = -2;
  for (const geometry::RebuildTriangle &t : triangles) {
    if (partColors && t.part != lastPart) {
      const geometry::IfsColor c = t.part < 0 ? geometry::IfsColor{0.8f, 0.8f, 0.8f}
                                              : geometry::partColor3(ifs, static_cast<std::size_t>(t.part));
      glColor3f(c.r, c.g, c.b);
      lastPart = t.part;
    }
    glNormal3d(t.normal.x, t.normal.y, t.normal.z);
    glVertex3d(t.corners.a.x, t.corners.a.y, t.corners.a.z);
    glVertex3d(t.corners.b.x, t.corners.b.y, t.corners.b.z);
    glVertex3d(t.corners.c.x, t.corners.c.y, t.corners.c.z);
  }
  glEnd();
}

} // namespace glass::scene
